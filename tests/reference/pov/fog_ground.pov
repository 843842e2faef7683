// Ground fog thinning upwards from fog_offset, over a tilted up vector,
// with a mirror that sees the fog along its reflected rays.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> angle 70 }
light_source { <-5, 10, -5> color rgb 1 }
background { rgb <0.2, 0.3, 0.6> }
box { <-1, 0, -1>, <1, 4, 1> pigment { rgb <0.2, 0.8, 0.3> } rotate y*30 translate <-3, 0, 4> }
sphere { <2, 1.5, 2>, 1.5 pigment { rgb 0.1 } finish { reflection 0.8 } }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.2 } }
fog {
  fog_type 2
  distance 4
  color rgb <0.8, 0.8, 0.9>
  fog_offset 0.5
  fog_alt 0.8
  up <0.1, 1, 0>
  rotate z*5
}
