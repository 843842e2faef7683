// An orthographic camera with neither angle, up nor right: POV scales the
// default right and up by the distance to look_at.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 3, -10> look_at <0, 0.5, 0> }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.2 } rotate y*30 }
sphere { <0, 0.5, 0>, 0.5 pigment { color rgb <0.9, 0.6, 0.2> } finish { phong 0.5 } }
sphere { <2, 1, 1>, 1 pigment { color rgb <0.2, 0.6, 0.9> } }
