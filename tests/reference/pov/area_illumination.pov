// area_illumination: every grid point of an area light lights with its own
// direction and attenuation (a long light close to a wall and a sphere).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <0, 2.2, -0.5> color rgb 1 area_light <4, 0, 0>, <0, 0, 0.5>, 9, 2 area_illumination on
               fade_distance 1.5 fade_power 2 }
light_source { <-3, 4, -5> color rgb 0.1 }
plane { y, 0 pigment { color rgb 0.85 } }
plane { z, 1.5 pigment { color rgb <0.8, 0.75, 0.7> } }
sphere { <0.8, 0.5, 0>, 0.5 pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.6 phong_size 20 } }
