// Shows materials and lights: declared textures, finishes with phong,
// specular and reflection, an interior with ior, an emitting object, a
// rectangular area light, the sphere-light extension and render_settings.
// Suits: raycast, path (reference: emitters and area lights).
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 max_trace_level 6 }
background { color rgb <0.05, 0.05, 0.1> }

render_settings { integrator "path" { max_depth 8 } width 320 height 240 samples 16 seed 1 }

camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 right x*image_width/image_height }
light_source { <0, 5, 0> color rgb 1 area_rectangle <2, 0, 0>, <0, 0, 2> }
light_source { <-3, 3, -3> color rgb <1, 0.9, 0.8> area_sphere 0.2 }

#declare Mirror = texture { pigment { color Black } finish { reflection { 0.9 } ambient 0 diffuse 0 } }
#declare Plastic = finish { phong 0.5 phong_size 60 specular 0.2 roughness 0.02 }

sphere { <-1.5, 1, 0>, 1 texture { Mirror } }
sphere { <0, 1, 0>, 1 pigment { color rgbf <0.9, 1, 0.9, 0.8> } interior { ior 1.5 } }
sphere { <1.5, 1, 0>, 1 pigment { color SkyBlue } finish { Plastic } }
box { <-0.3, 2.6, -0.3>, <0.3, 2.7, 0.3> pigment { color White } finish { emission 2 } }
plane { y, 0 pigment { checker color White, color Gray30 } }
