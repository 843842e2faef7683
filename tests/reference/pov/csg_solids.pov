// POV's CSG: difference (with a texture per child and a nested union to
// remove), intersection, merge, inverse and clipped_by, with transforms
// at every level; opaque, lit by a point light with shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.2, 0> angle 48 }
light_source { <-4, 9, -7> color rgb 1 }
light_source { <5, 3, -5> color rgb 0.3 }
plane { y, -1 pigment { color rgb <0.7, 0.75, 0.8> } }
difference {
  box { -1, 1 pigment { color rgb <0.9, 0.5, 0.2> } }
  sphere { <0, 0, 0>, 1.3 pigment { color rgb <0.2, 0.4, 0.9> } }
  union {
    cylinder { <0, -2, 0>, <0, 2, 0>, 0.35 }
    cylinder { <-2, 0, 0>, <2, 0, 0>, 0.35 }
    pigment { color rgb <0.9, 0.9, 0.2> }
  }
  rotate y*30 translate <-2.8, 0, 0.5>
}
intersection {
  sphere { 0, 1 }
  cylinder { <0, -2, 0>, <0, 2, 0>, 0.7 }
  box { <-2, -0.75, -2>, <2, 0.75, 2> }
  pigment { color rgb <0.3, 0.8, 0.4> }
  finish { phong 0.7 }
  rotate <20, 0, -25> translate <0, 0, 1.2>
}
merge {
  sphere { <-0.5, 0, 0>, 0.7 }
  sphere { <0.5, 0, 0>, 0.7 }
  torus { 0.9, 0.2 rotate x*90 }
  pigment { color rgb <0.8, 0.3, 0.6> }
  translate <2.8, 0, 0.8>
}
intersection {
  box { -0.8, 0.8 }
  sphere { 0, 0.6 inverse }
  pigment { color rgb <0.9, 0.9, 0.9> }
  clipped_by { plane { z, 0 } }
  rotate y*-35 translate <-1.4, -0.2, -2.3>
}
sphere { 0, 0.8 clipped_by { plane { y, 0.2 } } pigment { color rgb <0.9, 0.25, 0.25> } rotate x*-60 translate <1.5, -0.2, -2.4> }
