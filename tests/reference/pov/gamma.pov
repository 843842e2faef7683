// assumed_gamma 2.2: colours are in a gamma-2.2 working space; srgb
// colours are decoded into it.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 5, -4> color rgb 1 }
plane { y, 0 pigment { color rgb 0.5 } }
sphere { <-1.1, 0.7, 0>, 0.7 pigment { color rgb <0.8, 0.4, 0.2> } }
sphere { <1.1, 0.7, 0>, 0.7 pigment { color srgb <0.8, 0.4, 0.2> } finish { phong 0.5 } }
