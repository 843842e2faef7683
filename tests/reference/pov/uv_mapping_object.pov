// An object's own uv_mapping, written before its texture (POV-Ray's rule,
// as advanced/benchmark/benchmark.pov uses it): the pigment, normal and
// image that follow map by the surface's (u, v), and stay on the surface
// when the object moves.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, -1 pigment { checker rgb 1, rgb 0.5 } }
sphere { 0, 1 uv_mapping pigment { checker rgb <1, 0, 0>, rgb 1 scale <0.1, 0.2, 1> } translate <-1.2, 0.3, 0> }
#declare Block = box { <-0.85, -1, -0.8>, <0.85, 1, 0.8> }
object { Block uv_mapping texture { pigment { image_map { png "test.png" } } finish { ambient 0.3 } } rotate y * 20 translate <1.35, 0, 0> }
torus { 0.5, 0.2 uv_mapping pigment { checker rgb <0, 0.6, 0>, rgb 1 scale <0.0625, 0.25, 1> } normal { bumps 0.5 scale 0.05 }
  rotate x * -60 translate <1.4, 1.6, -0.5> }
