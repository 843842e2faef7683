// Shadowless lights are POV-Ray's fill lights: they light what faces them
// through anything and make no highlights (phong, specular). POV-Ray keeps
// one light type, so shadowless, spotlight and cylinder replace one
// another and the last written wins: a spotlight made shadowless lights
// every way, a shadowless light made a spotlight casts shadows.
// Reference: povray +Ifill_lights.pov +Ofill_lights.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -7> look_at <0, 0.5, 0> angle 55 }
plane { y, 0 pigment { color rgb 0.8 } }
sphere { <-1.6, 1, 0>, 1 pigment { color rgb <1, 0.6, 0.3> } finish { phong 0.9 phong_size 30 } }
sphere { <1.6, 1, 0>, 1 pigment { color rgb <0.4, 0.7, 1> } finish { specular 0.8 roughness 0.02 } }
light_source { <-4, 6, -5> color rgb 0.7 spotlight point_at <0, 0, 0> radius 8 falloff 12 shadowless }
light_source { <4, 7, -4> color rgb 0.6 shadowless spotlight point_at <1.6, 0, 0> radius 15 falloff 25 }
light_source { <0, 8, -2> color rgb 0.4 cylinder point_at <0, 0, 0> radius 1 falloff 2 shadowless }
light_source { <3, 3, -8> color rgb 0.3 shadowless }
