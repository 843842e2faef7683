// uv_mapping on a sphere, a box (POV's unfolded cube) and a torus, at the
// start of a pigment and in a texture, and pigment_pattern (a pigment's
// grey as the value of a colour map, turbulence on top).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 1, rgb 0.5 } }
sphere { <-1.2, 0.3, 0>, 1 pigment { uv_mapping checker rgb <1, 0, 0>, rgb 1 scale <0.1, 0.2, 1> } }
box { <0.5, -1, -0.8>, <2.2, 1, 0.8> texture { uv_mapping pigment { gradient x color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } frequency 4 } } }
torus { 0.5, 0.2 rotate x*-60 translate <1.4, 1.6, -0.5> pigment { uv_mapping checker rgb <0, 0.6, 0>, rgb 1 scale <0.0625, 0.25, 1> } }
sphere { <-0.2, 1.8, 0>, 0.5 pigment { pigment_pattern { checker rgb 1, rgb 0 scale 0.2 } turbulence 0.3 color_map { [0 rgb <0, 0.5, 0>] [1 rgb <1, 1, 0>] } } }
