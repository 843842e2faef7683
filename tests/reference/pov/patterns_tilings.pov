// POV-Ray 3.7's tilings (tiling 1 to 10, turned into the x-y plane) and
// density_file (a small df3, trilinear and tricubic), each on a flat tile
// that shows the pigment itself (ambient 1, diffuse 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
#macro Tile(Col, Row, Pig)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01>
    texture { pigment { Pig translate <Col*1.05, Row*1.05, 0> } finish { ambient 1 diffuse 0 } } }
#end
background { rgb <0.2, 0.3, 0.4> }
#declare Rainbow = color_map { [0 rgb <1, 0, 0>] [0.33 rgb <1, 1, 0>] [0.66 rgb <0, 0.6, 1>] [1 rgb <1, 0, 1>] }
#declare Edges = color_map { [0 rgb <0.9, 0.8, 0.5>] [0.8 rgb <0.6, 0.3, 0.1>] [0.85 rgb 0] [1 rgb 0] }
Tile(0, 2, pigment { tiling 1 rotate x*90 scale 0.3 color_map { Edges } })
Tile(1, 2, pigment { tiling 2 rotate x*90 scale 0.2 color_map { Rainbow } })
Tile(2, 2, pigment { tiling 3 rotate x*90 scale 0.3 color_map { Rainbow } })
Tile(3, 2, pigment { tiling 4 rotate x*90 scale 0.25 color_map { Rainbow } })
Tile(0, 1, pigment { tiling 5 rotate x*90 scale 0.2 color_map { Rainbow } })
Tile(1, 1, pigment { tiling 6 rotate x*90 scale 0.2 color_map { Rainbow } })
Tile(2, 1, pigment { tiling 7 rotate x*90 scale 0.2 color_map { Rainbow } })
Tile(3, 1, pigment { tiling 8 rotate x*90 scale 0.2 color_map { Rainbow } })
Tile(0, 0, pigment { tiling 9 rotate x*90 scale 0.2 color_map { Rainbow } })
Tile(1, 0, pigment { tiling 10 rotate x*90 scale 0.25 rotate z*15 color_map { Edges } })
Tile(2, 0, pigment { density_file df3 "patterns/density8.df3" interpolate 1 color_map { Rainbow } })
Tile(3, 0, pigment { density_file df3 "patterns/density8.df3" interpolate 2 color_map { Rainbow } })
