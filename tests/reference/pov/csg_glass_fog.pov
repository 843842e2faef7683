// Glass CSG objects in fog: a ray that enters through one part and leaves
// through another has left the object (POV-Ray's parts share their
// parent's interior), so the fog beyond it shows.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.2, -6> look_at <0, 1, 0> angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.15, 0.2, 0.35> }
fog { distance 12 color rgb <0.75, 0.75, 0.8> }
plane { y, 0 pigment { checker rgb 0.85 rgb 0.25 scale 0.75 } }
// A lens: two spheres' common part.
intersection {
  sphere { <0.9, 0, 0>, 1.2 } sphere { <-0.9, 0, 0>, 1.2 }
  rotate y*70 translate <-1.2, 1.2, 0.5>
  pigment { rgbf <0.95, 0.95, 1, 0.9> } finish { reflection 0.05 }
  interior { ior 1.5 }
}
// A thick ring: a box less a cylinder.
difference {
  box { <-0.8, -0.8, -0.25>, <0.8, 0.8, 0.25> }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.45 }
  rotate <10, -25, 0> translate <1.4, 1.1, 0.8>
  pigment { rgbf <0.9, 1, 0.9, 0.85> }
  interior { ior 1.3 }
}
sphere { <0.2, 0.5, 5>, 0.5 pigment { rgb <1, 0.5, 0.2> } }
