// Two rainbows (the outer one with an arc and falloff, its colours
// partly transmitting) over a sky and a distant floor: the ring fades
// with the distance to what it is seen against.
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -10> look_at <0, 6, 20> angle 90 }
light_source { <0, 20, -30> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.5, 0.55, 0.6>] [1 rgb <0.1, 0.15, 0.4>] } } }
plane { y, 0 pigment { checker rgb 0.3 rgb 0.5 scale 4 } }
sphere { <6, 4, 30>, 5 pigment { rgb <0.7, 0.6, 0.5> } }
#declare Spectrum = color_map {
  [0.000 color rgbt <1, 0, 0, 0.2>]
  [0.200 color rgbt <1, 0.5, 0, 0.2>]
  [0.400 color rgbt <1, 1, 0, 0.2>]
  [0.600 color rgbt <0, 1, 0, 0.2>]
  [0.800 color rgbt <0, 0, 1, 0.2>]
  [1.000 color rgbt <0.5, 0, 1, 0.2>]
}
rainbow { angle 30 width 8 distance 60 direction <0, 0, 1> up y color_map { Spectrum } }
rainbow {
  angle 45 width 6 distance 1e5 direction <0.1, -0.05, 1> up <0.1, 1, 0>
  arc_angle 120 falloff_angle 60
  color_map { [0 rgbft <0.2, 0.2, 1, 0.3, 0.4>] [0.5 rgbt <1, 1, 1, 0.5>] [1 rgbt <1, 0.2, 0.2, 0.6>] }
}
