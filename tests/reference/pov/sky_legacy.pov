// A #version 3.6 sky: POV composites its layers as 3.6 did, and the
// background shows through where the top layers transmit; emission scales
// the sky but not the background.
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at <0, 2.5, 0> angle 80 }
background { rgb <0.1, 0.5, 0.2> }
#declare Sky = sky_sphere {
  pigment { gradient x color_map { [0 rgbt <0.9, 0.9, 0.2, 0.7>] [1 rgbf <0.2, 0.2, 0.9, 0.6>] } scale 0.5 }
  pigment { bozo scale 0.2 color_map { [0.3 rgbf <0.75, 0.75, 0.75, 0.1>] [0.6 rgbf <1, 1, 1, 1>] } }
  emission rgb <1.2, 1, 0.8>
}
sky_sphere { Sky rotate z*20 }
plane { y, 0 pigment { rgb 0.5 } finish { reflection 0.3 } }
