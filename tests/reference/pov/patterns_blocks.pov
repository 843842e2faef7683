// POV-Ray's block patterns with their default colours, lists of colours
// and of pigments (nested in the block's pattern space), and the wave
// types, frequency and phase on a gradient.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
#macro Tile(Col, Row, Pig)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01>
    texture { pigment { Pig translate <Col*1.05, Row*1.05, 0> } finish { ambient 1 diffuse 0 } } }
#end
background { rgb <0.2, 0.3, 0.4> }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.6>] [1 rgb <1, 0.9, 0.3>] }
Tile(0, 2, pigment { checker scale 0.25 })
Tile(1, 2, pigment { hexagon rgb <1, 0.5, 0>, rgb <0, 0.5, 1>, rgb 1 scale 0.12 rotate x*90 })
Tile(2, 2, pigment { brick color rgb 0.9, color rgb <0.7, 0.2, 0.1> brick_size <0.3, 0.12, 0.2> mortar 0.03 })
Tile(3, 2, pigment { checker pigment { gradient y color_map { Ramp } } pigment { gradient x scale 0.5 } scale 0.25 })
Tile(0, 1, pigment { square scale 0.25 })
Tile(1, 1, pigment { triangular scale 0.25 })
Tile(2, 1, pigment { cubic scale 0.3 rotate <20, 30, 0> })
Tile(3, 1, pigment { gradient x frequency 3 phase 0.2 color_map { Ramp } })
Tile(0, 0, pigment { gradient x triangle_wave frequency 2 color_map { Ramp } })
Tile(1, 0, pigment { gradient x sine_wave frequency 2 color_map { Ramp } })
Tile(2, 0, pigment { gradient x scallop_wave frequency 2 color_map { Ramp } })
Tile(3, 0, pigment { gradient x poly_wave 3 color_map { [0 rgb 0] [0.5 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb 1] } })
