// POV cylinder lights and a faded parallel light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0, 0> angle 50 }
light_source { <0, 8, 0> color rgb <1, 0.9, 0.7> cylinder point_at <0, 0, 0> radius 1.2 falloff 2.5 tightness 3 }
light_source { <-6, 3, -2> color rgb <0.3, 0.5, 1> cylinder point_at <0, 0.5, 0.5> radius 0.5 falloff 0.9 }
light_source { <5, 6, -5> color rgb 0.15 }
light_source { <4, 5, 4> color rgb 0.3 parallel point_at 0 fade_distance 3 fade_power 2 }
plane { y, 0 pigment { color rgb 0.8 } }
sphere { <0.6, 0.7, 0.3>, 0.7 pigment { color rgb <0.9, 0.3, 0.3> } finish { phong 0.6 phong_size 30 } }
box { <-1.8, 0, -0.5>, <-0.8, 1.5, 0.5> pigment { color rgb <0.3, 0.9, 0.4> } }
