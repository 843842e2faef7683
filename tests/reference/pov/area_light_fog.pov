// An oriented circular area light dimmed by fog on its way (media_attenuation)
// over a floor, a sphere, a box and a rotated torus, with a second, square
// area light: grid points seen past every object, partly shadowed and fully
// clear, where lancer traces no shadow ray at all.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <2, 5, -2> color rgb 1.2 area_light <2, 0, 0>, <0, 0, 2>, 7, 7 adaptive 1 circular orient
               media_attenuation on }
light_source { <-4, 3, -1> color rgb <0.4, 0.45, 0.5> area_light <0, 1.5, 0>, <0, 0, 1.5>, 5, 4 adaptive 0 }
fog { distance 30 color rgb <0.6, 0.65, 0.7> }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.45 } }
sphere { <-1.2, 0.8, 0.3>, 0.8 pigment { color rgb <0.8, 0.3, 0.2> } finish { specular 0.3 } }
box { <0.6, 0, -0.4>, <1.6, 1.4, 0.6> rotate y * 25 pigment { color rgb <0.3, 0.6, 0.8> } }
torus { 0.6, 0.15 rotate x * 60 translate <0.2, 1.9, 1.5> pigment { color rgb <0.9, 0.8, 0.3> } }
