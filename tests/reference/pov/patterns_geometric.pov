// POV-Ray's deterministic patterns, each on a flat tile that shows the
// pigment itself (ambient 1, diffuse 0): gradient, onion, spherical,
// cylindrical, boxed, planar, radial, spiral1, spiral2, leopard, quilted,
// through the default colour maps and colour maps of their own.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
#macro Tile(Col, Row, Pig)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01>
    texture { pigment { Pig translate <Col*1.05, Row*1.05, 0> } finish { ambient 1 diffuse 0 } } }
#end
background { rgb <0.2, 0.3, 0.4> }
#declare Rainbow = color_map { [0 rgb <1, 0, 0>] [0.33 rgb <1, 1, 0>] [0.66 rgb <0, 0.6, 1>] [1 rgb <1, 0, 1>] }
Tile(0, 2, pigment { gradient x })
Tile(1, 2, pigment { gradient <1, 1, 0> color_map { Rainbow } })
Tile(2, 2, pigment { onion scale 0.3 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(3, 2, pigment { spherical translate <0.5, 0.5, 0> color_map { [0 rgb 0] [0.5 rgb <0, 1, 0>] [1 rgb 1] } })
Tile(0, 1, pigment { cylindrical scale 0.6 translate <0.4, 0.6, 0> color_map { Rainbow } })
Tile(1, 1, pigment { boxed scale 0.45 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(2, 1, pigment { planar rotate z*60 scale 0.3 translate <0.5, 0.5, 0> })
Tile(3, 1, pigment { radial frequency 4 rotate x*90 translate <0.5, 0.5, 0> })
Tile(0, 0, pigment { spiral1 3 rotate x*90 scale 0.3 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(1, 0, pigment { spiral2 2 rotate x*90 scale 0.3 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(2, 0, pigment { leopard scale 0.08 color_map { Rainbow } })
Tile(3, 0, pigment { quilted control0 0.3 control1 0.8 scale 0.25 color_map { Rainbow } })
