// uv_mapping on shapes for which POV-Ray 3.7 defines no (u, v) (a plane,
// a cylinder, a cone): POV-Ray's uv_mapping reads the hit's world x and
// y there (ObjectBase::UVCoord), beside a sphere and a torus, which map
// their own (u, v). lancer once gave the cylinder and cone a map around
// their axis and the plane its x and z.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.7, 0> angle 55 }
light_source { <-3, 6, -5> color rgb 1 }
plane { y, 0 pigment { uv_mapping gradient x color_map { [0 rgb 1] [1 rgb 0.4] } scale 0.5 } }
sphere { <-1.4, 0.8, 0>, 0.8 pigment { uv_mapping checker rgb <1, 0, 0> rgb 1 scale <0.125, 0.25, 1> } }
torus { 0.6, 0.25 rotate x*-60 translate <0.2, 0.8, 0.2> pigment { uv_mapping gradient x color_map { [0 rgb <0, 0.5, 1>] [1 rgb <1, 1, 0>] } } }
cylinder { <1.6, 0, 0>, <1.6, 1.4, 0>, 0.5 pigment { uv_mapping checker rgb <0, 0.6, 0> rgb 1 scale <0.1, 0.25, 1> } }
cone { <0, 0, -1.5>, 0.4, <0, 0.8, -1.5>, 0 pigment { uv_mapping checker rgb <0.6, 0, 0.6> rgb 1 scale <0.125, 0.25, 1> } }
