// interior_texture: what a surface shows where a ray meets it from inside
// (against its normal): a bowl (a sphere clipped open) showing its inside,
// a mesh sheet curled so both sides show, smooth triangles whose normals
// face away from the triangles' own, discs from both sides, and a
// union whose interior_texture reaches its children (the one with a
// texture of its own too), a patterned one
// moving with the object's later transforms.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 55 }
light_source { <-3, 6, -5> color rgb 1 }
light_source { <3, 4, 2> color rgb 0.4 }
#declare Outside = texture { pigment { color rgb <0.2, 0.4, 0.8> } finish { phong 0.4 } }
#declare Inside = texture { pigment { checker color rgb <0.9, 0.6, 0.2> color rgb <0.5, 0.1, 0.1> scale 0.2 } }
sphere { 0, 0.8 clipped_by { plane { y, 0.3 } } texture { Outside } interior_texture { Inside }
         rotate x * -25 translate <-1.6, 0.8, 0> }
mesh {
  triangle { <-0.6, 0, 0>, <0.6, 0, 0>, <0, 1.2, 0.3> }
  triangle { <-0.6, 0, 0>, <0, 1.2, 0.3>, <-0.9, 1.1, -0.4> }
  texture { Outside } interior_texture { Inside }
  translate <0.1, 0.2, 0.2>
}
mesh {
  smooth_triangle { <-0.5, 0, 0>, <0.3, 0.1, 1>, <0.5, 0, 0>, <-0.3, 0.1, 1>, <0, 0.8, 0>, <0, 0.3, 1> }
  smooth_triangle { <0.5, 0, 0>, <-0.3, 0.1, 1>, <0, 0.8, 0>, <0, 0.3, 1>, <0.6, 0.9, 0.4>, <0.2, 0.3, 1> }
  texture { Outside } interior_texture { Inside }
  translate <1.9, 0, -1.6>
}
disc { <1.6, 0.9, 0>, <0.3, 0.2, -1>, 0.5 texture { Outside } interior_texture { pigment { color rgb <0.2, 0.8, 0.3> } } }
disc { <1.6, 0.9, 1.5>, <0.3, 0.2, 1>, 0.5 texture { Outside } interior_texture { pigment { color rgb <0.2, 0.8, 0.3> } } }
union {
  disc { <0, 0, 0>, <0, 0, 1>, 0.4 }
  disc { <0.9, 0, 0>, <0, 0, 1>, 0.4 texture { pigment { color rgb 0.9 } } }
  texture { Outside }
  interior_texture { pigment { gradient x color_map { [0 color rgb <1, 0.2, 0.2>] [1 color rgb <1, 1, 0.2>] } } }
  scale 1.2 rotate y * 10 translate <-0.9, 2.2, 1.5>
}
plane { y, 0 texture { pigment { color rgb 0.7 } } interior_texture { pigment { color rgb <0.5, 0, 0.5> } } }
