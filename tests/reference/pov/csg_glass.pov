// Glass CSG: refraction through every face a difference keeps, a merge
// (no inner surfaces) and an intersection lens, in front of a checker.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker color rgb 0.9 color rgb 0.2 scale 0.7 } }
plane { z, 3 pigment { checker color rgb <0.8, 0.3, 0.2> color rgb <0.9, 0.9, 0.6> scale 0.7 } }
#declare Glass = material { texture { pigment { color rgbf <0.95, 0.98, 1, 0.92> } finish { diffuse 0.05 reflection { 0.05 } } } interior { ior 1.5 } };
difference {
  box { <-0.9, -0.9, -0.3>, <0.9, 0.9, 0.3> }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.5 }
  material { Glass }
  rotate y*20 translate <-2.2, 0, 0>
}
merge {
  sphere { <-0.35, 0, 0>, 0.6 }
  sphere { <0.35, 0, 0>, 0.6 }
  material { Glass }
  translate <0, -0.1, -0.5>
}
intersection {
  sphere { <0, 0, -1.2>, 1.5 }
  sphere { <0, 0, 1.2>, 1.5 }
  material { Glass }
  rotate y*-20 translate <2.2, 0, 0>
}
