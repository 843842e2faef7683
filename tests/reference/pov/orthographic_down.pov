// An orthographic plan view straight down its sky: POV keeps the right
// vector, turns up to face the view, and sizes the view as the perspective
// camera of the same angle sees the look_at point.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0> angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.2 } }
sphere { <1, 0.5, 0.5>, 0.5 pigment { color rgb <0.9, 0.3, 0.2> } }
box { <-2, 0, -1>, <-1, 1, 0> pigment { color rgb <0.2, 0.5, 0.9> } }
