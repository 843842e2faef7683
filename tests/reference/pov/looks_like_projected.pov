// looks_like lamps, a negative light and a light projected through a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> angle 50 }
#declare Bulb = sphere { 0, 0.25 pigment { color rgb <1, 0.9, 0.6> } finish { ambient 1 diffuse 0 } }
light_source { <0, 0, 0> color rgb <1, 0.9, 0.6> looks_like { Bulb } translate <-1, 2.5, 0> }
light_source { <2, 1.2, -1> color rgb 0.5 looks_like { box { -0.1, 0.1 pigment { color rgb 1 } finish { ambient 1 } rotate 45*y } } }
light_source { <0, 0.8, -0.6> color rgb -0.6 fade_distance 1 fade_power 2 }
light_source { <-2, 3, -2> color rgb 0.4 projected_through { sphere { <-1, 2, -1>, 0.5 } } }
plane { y, 0 pigment { color rgb 0.8 } }
sphere { <0.2, 0.7, 0.8>, 0.7 pigment { color rgb <0.3, 0.6, 0.9> } finish { phong 0.5 } }
