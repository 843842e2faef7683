// image_map palette entries' filter and transmit: POV-Ray's `filter N, v`
// and `transmit N, v` (and `filter all`, `transmit all` on a palette file)
// set in the order written, over a checker. Magnified 2.5 to 4 pixels a
// texel, so that the comparison is about the entries, not about which
// texel a pixel's centre falls in.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 4 up y * 3 }
plane { z, 1 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.3, 0.8> scale 0.25 } finish { ambient 1 diffuse 0 } }
#macro Panel(Column, Row, Pigment)
  box { <0, 0, 0>, <1.9, 1.4, 0.01> pigment { Pigment } finish { ambient 1 diffuse 0 }
    translate <-1.95 + 2 * Column, -1.45 + 1.5 * Row, 0> }
#end
// test.png: 16 entries, 6 used, colours repeated in its palette.
Panel(0, 1, pigment { image_map { png "test.png" once transmit 0, 0.8 transmit 1, 0.8 filter 2, 0.9 transmit 4, 0.4 filter 5 0.5 }
                      scale <20.37, 12.71, 1> translate <-9.03, -5.27, 0> })
// Interpolated: the entries' transparency blends as their colours do. The
// file's transparent entry 0 gets filter 0.3 as well: it passes 1.3 times
// the light behind it, as POV-Ray computes it.
Panel(1, 1, pigment { image_map { png "povmap.png" once interpolate 2 filter all 0.3 transmit 3, 0.7 filter 1, 0 }
                      scale <16.3, 10.17, 1> translate <-2.23, -0.81, 0> })
// 256 entries, many alike; a later setting overrides an earlier one.
Panel(0, 0, pigment { image_map { png "fract003.png" once transmit 1, 1 transmit all 0.2 transmit 100, 0.8 transmit 130, 0.6 filter 165, 0.7 }
                      scale <32.3, 20.3, 1> translate <-15.13, -9.61, 0> })
// Repeated, nearest.
Panel(1, 0, pigment { image_map { png "plasma3.png" filter all 0.6 transmit 40, 0.4 transmit 60 0.4 }
                      scale <6.07, 6.13, 1> translate <-2.03, -3.11, 0> })
