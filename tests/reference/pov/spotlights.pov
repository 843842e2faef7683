// Three POV spotlights of different cones and tightness over a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -7> look_at <0, 0, 0> angle 55 }
light_source { <-3, 6, -1> color rgb <1, 0.3, 0.3> spotlight point_at <-2, 0, 0> radius 12 falloff 20 }
light_source { <0, 6, 0> color rgb <0.3, 1, 0.3> spotlight point_at <0, 0, 1> radius 5 falloff 25 tightness 10 }
light_source { <3, 6, -1> color rgb <0.3, 0.3, 1> spotlight point_at <2, 0, -1> }
light_source { <0, 8, -8> color rgb 0.1 }
plane { y, 0 pigment { color rgb 0.9 } }
sphere { <0, 0.8, 0.5>, 0.8 pigment { color rgb 0.8 } finish { phong 0.4 } }
