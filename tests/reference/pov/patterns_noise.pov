// POV-Ray's patterns built on its noise: bozo, spotted, granite, agate,
// marble and wood with turbulence, wrinkles, bumps, dents, crackle, cells,
// and the fractals mandel and julia.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
#macro Tile(Col, Row, Pig)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01>
    texture { pigment { Pig translate <Col*1.05, Row*1.05, 0> } finish { ambient 1 diffuse 0 } } }
#end
background { rgb <0.2, 0.3, 0.4> }
#declare Ramp = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.9, 0.2, 0.2>] [1 rgb <1, 0.9, 0.3>] }
Tile(0, 2, pigment { bozo scale 0.2 })
Tile(1, 2, pigment { spotted scale 0.15 color_map { Ramp } })
Tile(2, 2, pigment { granite scale 0.8 color_map { Ramp } })
Tile(3, 2, pigment { agate scale 0.5 })
Tile(0, 1, pigment { marble turbulence 0.5 scale 0.5 })
Tile(1, 1, pigment { wood turbulence 0.08 scale 0.1 rotate y*80 })
Tile(2, 1, pigment { wrinkles scale 0.3 color_map { Ramp } })
Tile(3, 1, pigment { bumps scale 0.2 color_map { Ramp } })
Tile(0, 0, pigment { dents scale 0.3 color_map { Ramp } })
Tile(1, 0, pigment { crackle scale 0.2 color_map { Ramp } })
Tile(2, 0, pigment { cells scale 0.15 color_map { Ramp } })
Tile(3, 0, pigment { mandel 30 scale 0.4 translate <0.7, 0.5, 0> color_map { Ramp } })
