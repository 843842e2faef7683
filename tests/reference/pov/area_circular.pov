// A circular, oriented area light and an area spotlight with a line grid.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <2, 5, -2> color rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 9, 9 adaptive 2 circular orient }
light_source { <-3, 4, 1> color rgb <0.4, 0.5, 0.6> spotlight point_at <0, 0, 0> radius 20 falloff 30
               area_light <1, 0, 0>, <0, 1, 0>, 4, 3 }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.5 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.3, 0.8, 0.3> } finish { specular 0.4 roughness 0.02 } }
box { <1.2, 0, 0.7>, <1.8, 2, 1.3> pigment { color rgb 1 } }
