// Surfaces whose filter and transmit add up to more than 1: POV-Ray does
// not clamp their opacity, 1 - filter - transmit, so their own light turns
// negative. A film around the camera with `transmit 20` stretches the
// contrast of everything behind it 20 times (POV's advanced/bwstripe.pov
// does this), and a pane with filter 0.7 and transmit 0.6 darkens what it
// lets through.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <3, 8, -6> color rgb 1 }
background { rgb 0.49 }
sphere { <0, 1.5, -6>, 0.001 hollow
  pigment { rgb 0.5 transmit 20 } finish { ambient 1 diffuse 0 } }
plane { y, 0 pigment { gradient x triangle_wave color_map { [0 rgb 0.46] [1 rgb 0.52] } }
  finish { ambient 1 diffuse 0.05 } }
box { <-1.5, 0.2, -1>, <0.2, 2, -0.9> pigment { rgb <0.9, 0.6, 0.3> filter 0.7 transmit 0.6 }
  finish { ambient 0.3 diffuse 0.1 } }
sphere { <1, 1, 1>, 1 pigment { rgb <0.47, 0.5, 0.49> } finish { ambient 0.95 diffuse 0.08 } }
