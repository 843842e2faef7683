// Warps and maps: classic turbulence with octaves, omega and lambda, the
// turbulence, repeat (with flip), black_hole, cylindrical, spherical and
// planar warps, a transform after a warp, colour maps with filter and
// transmit over the background, a pigment_map and average.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
#macro Tile(Col, Row, Pig)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01>
    texture { pigment { Pig translate <Col*1.05, Row*1.05, 0> } finish { ambient 1 diffuse 0 } } }
#end
background { rgb <0.2, 0.3, 0.4> }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.9, 0.2, 0.2>] [1 rgb <1, 0.9, 0.3>] }
Tile(0, 2, pigment { gradient x turbulence 0.3 octaves 3 omega 0.7 lambda 2.5 color_map { Ramp } })
Tile(1, 2, pigment { gradient x warp { turbulence <0.2, 0.4, 0> octaves 2 } color_map { Ramp } })
Tile(2, 2, pigment { checker scale 0.25 warp { repeat x * 0.5 flip y } })
Tile(3, 2, pigment { checker scale 0.1 warp { black_hole <0.5, 0.5, 0>, 0.45 falloff 2 strength 1.5 } })
Tile(0, 1, pigment { gradient y color_map { Ramp } warp { cylindrical orientation z } scale 0.4 translate <0.5, 0.5, 0> })
Tile(1, 1, pigment { checker scale <0.1, 0.25, 1> warp { spherical orientation z } translate <0.5, 0.5, 0> })
Tile(2, 1, pigment { gradient x warp { turbulence 0.3 } scale 0.5 color_map { Ramp } })
Tile(3, 1, pigment { gradient x scale 0.5 warp { turbulence 0.3 } color_map { Ramp } })
Tile(0, 0, pigment { gradient x color_map { [0 rgbf <1, 0, 0, 1>] [1 rgbt <0, 1, 0, 0.7>] } })
Tile(1, 0, pigment { gradient y pigment_map { [0 checker rgb 1, rgb 0 scale 0.1] [0.5 gradient x color_map { Ramp }] [1 rgb <0, 0.5, 0>] } })
Tile(2, 0, pigment { average pigment_map { [1 gradient x] [2 gradient y color_map { Ramp }] [1 rgb <1, 0, 0>] } })
Tile(3, 0, pigment { onion scale 0.2 color_map { [0 rgb 1] [0.5 rgb 0] } translate <0.5, 0.5, 0> })
