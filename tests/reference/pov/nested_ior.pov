// Refraction between objects inside one another: POV-Ray bends a ray by
// the ratio of the index it is in to the index it enters, read from the
// objects the ray has entered (not from the face it meets). Water in a
// glass, an air bubble in glass, two overlapping glass spheres (where the
// later entered wins), and Fresnel reflection inside them.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 12 }
camera { location <0, 2.2, -6> look_at <0, 0.9, 0> angle 50 }
light_source { <-3, 8, -5> color rgb 1 }
background { rgb <0.5, 0.6, 0.8> }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 scale 0.4 } finish { diffuse 0.8 ambient 0.2 } }
plane { z, 3 pigment { gradient x color_map { [0 rgb <1, 0.3, 0.2>] [0.5 rgb <0.2, 1, 0.3>] [1 rgb <1, 0.3, 0.2>] } scale 0.7 } }
#declare Clear = pigment { rgbf <1, 1, 1, 0.95> }
// a glass of water, the water a little inside the glass (not touching it)
difference {
  cylinder { <-1.6, 0.02, 0>, <-1.6, 1.8, 0>, 0.7 }
  cylinder { <-1.6, 0.2, 0>, <-1.6, 2, 0>, 0.6 }
  pigment { Clear } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 1.5 } }
cylinder { <-1.6, 0.25, 0>, <-1.6, 1.3, 0>, 0.55
  pigment { rgbf <0.8, 0.9, 1, 0.95> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel on } }
  interior { ior 1.33 } }
// an air bubble in a glass ball
sphere { <0.2, 1, 0.4>, 0.9 pigment { Clear } finish { ambient 0 diffuse 0 } interior { ior 1.6 } }
sphere { <0.35, 1.1, 0.2>, 0.4 pigment { Clear } finish { ambient 0 diffuse 0 } interior { ior 1.0 } }
// two overlapping balls of different glass
sphere { <1.8, 0.8, -0.5>, 0.7 pigment { Clear } finish { ambient 0 diffuse 0 } interior { ior 1.3 } }
sphere { <2.3, 0.9, -0.2>, 0.6 pigment { Clear } finish { ambient 0 diffuse 0 reflection 0.1 } interior { ior 1.7 } }
