// double_illuminate: thin surfaces lit from behind as from the front (a
// disc, a triangle mesh, a polygon in a union that sets it for everything
// inside, a plane seen from below), a sphere whose own body still shadows
// its far side, and the same disc without it beside them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 60 }
light_source { <1, 4, 6> color rgb 1 }
light_source { <-3, 2, -4> color rgb 0.25 }
#declare Paper = texture { pigment { color rgb <0.9, 0.85, 0.7> } finish { ambient 0.05 diffuse 0.8 phong 0.5 } }
disc { <-2.2, 1.6, 0>, <0.2, 0, -1>, 0.6 texture { Paper } double_illuminate }
disc { <-0.8, 1.6, 0>, <0.2, 0, -1>, 0.6 texture { Paper } }
mesh { triangle { <0.2, 1, 0>, <1.2, 1, 0.3>, <0.7, 2.2, 0.1> } texture { Paper } double_illuminate }
union {
  polygon { 5, <1.5, 0.9, 0>, <2.6, 0.9, 0.2>, <2.6, 2.0, 0.2>, <1.5, 2.0, 0>, <1.5, 0.9, 0> }
  sphere { <2.05, 0.45, -0.5>, 0.35 double_illuminate off }
  texture { Paper }
  double_illuminate
}
sphere { <-1.5, 0.45, -0.8>, 0.4 texture { Paper } double_illuminate }
plane { -y, -3 texture { pigment { checker color rgb 0.8 color rgb 0.4 } finish { ambient 0.1 diffuse 0.7 } } double_illuminate }
plane { y, 0 texture { pigment { color rgb 0.6 } finish { ambient 0.1 } } }
