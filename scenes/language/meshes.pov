// Shows triangle geometry: triangle, smooth_triangle, mesh with a
// per-triangle texture, and mesh2 with normals and uv coordinates.
// Suits: raycast (a language scene: the picture only proves it evaluates).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> }
light_source { <5, 10, -5> color rgb 1 parallel point_at <0, 0, 0> }

triangle { <-3, 0, 0>, <-2, 0, 0>, <-2.5, 1, 0> pigment { rgb <1, 0.5, 0> } }
smooth_triangle { <-1.5, 0, 0>, <0, 0, -1>, <-0.5, 0, 0>, <0, 0, -1>, <-1, 1, 0>, <0, 0.5, -1> pigment { rgb 1 } }
mesh {
  triangle { <0, 0, 0>, <1, 0, 0>, <0.5, 1, 0> texture { pigment { rgb <0, 1, 0> } } }
  triangle { <0, 0, 0>, <0.5, 1, 0>, <0, 1, 0> }
  pigment { rgb 0.5 }
}
mesh2 {
  vertex_vectors { 4, <1.5, 0, 0>, <2.5, 0, 0>, <2.5, 1, 0>, <1.5, 1, 0> }
  normal_vectors { 1, <0, 0, -1> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  normal_indices { 2, <0, 0, 0>, <0, 0, 0> }
  uv_indices { 2, <0, 1, 2>, <0, 2, 3> }
  pigment { checker rgb 1, rgb 0 scale 0.25 }
}
