// POV-Ray 3.7's tilings 11 to 27 (the Penrose tilings 25 to 27 among
// them) and pavements of squares, triangles and hexagons with their
// exterior, interior and form, turned into the x-y plane, each on a flat
// tile that shows the pigment itself (ambient 1, diffuse 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <3.15, 2.1, -5> look_at <3.15, 2.1, 0> right x*6.3 up y*4.2 }
#macro Tile(Col, Row, Pig)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01>
    texture { pigment { Pig translate <Col*1.05, Row*1.05, 0> } finish { ambient 1 diffuse 0 } } }
#end
background { rgb <0.2, 0.3, 0.4> }
#declare Rainbow = color_map { [0 rgb <1, 0, 0>] [0.33 rgb <1, 1, 0>] [0.66 rgb <0, 0.6, 1>] [1 rgb <1, 0, 1>] }
#declare Edges = color_map { [0 rgb <0.9, 0.8, 0.5>] [0.8 rgb <0.6, 0.3, 0.1>] [0.85 rgb 0] [1 rgb 0] }
Tile(0, 3, pigment { tiling 11 rotate x*90 scale 0.15 color_map { Rainbow } })
Tile(1, 3, pigment { tiling 12 rotate x*90 scale 0.15 color_map { Rainbow } })
Tile(2, 3, pigment { tiling 13 rotate x*90 scale 0.15 color_map { Rainbow } })
Tile(3, 3, pigment { tiling 14 rotate x*90 scale 0.15 color_map { Rainbow } })
Tile(4, 3, pigment { tiling 15 rotate x*90 scale 0.12 color_map { Rainbow } })
Tile(5, 3, pigment { tiling 16 rotate x*90 scale 0.12 color_map { Rainbow } })
Tile(0, 2, pigment { tiling 17 rotate x*90 scale 0.12 color_map { Rainbow } })
Tile(1, 2, pigment { tiling 18 rotate x*90 scale 0.15 color_map { Rainbow } })
Tile(2, 2, pigment { tiling 19 rotate x*90 scale 0.12 color_map { Rainbow } })
Tile(3, 2, pigment { tiling 20 rotate x*90 scale 0.12 color_map { Rainbow } })
Tile(4, 2, pigment { tiling 21 rotate x*90 scale 0.15 color_map { Rainbow } })
Tile(5, 2, pigment { tiling 22 rotate x*90 scale 0.1 color_map { Rainbow } })
Tile(0, 1, pigment { tiling 23 rotate x*90 scale 0.1 color_map { Rainbow } })
Tile(1, 1, pigment { tiling 24 rotate x*90 scale 0.1 color_map { Rainbow } })
Tile(2, 1, pigment { tiling 25 rotate x*90 scale 0.15 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(3, 1, pigment { tiling 26 rotate x*90 scale 0.2 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(4, 1, pigment { tiling 27 rotate x*90 scale 0.15 translate <0.5, 0.5, 0> color_map { Rainbow } })
Tile(5, 1, pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 9 exterior 1 interior 1 form 1 rotate x*90 scale 0.12 color_map { Edges } })
Tile(0, 0, pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 30 exterior 2 interior 2 form 2 rotate x*90 scale 0.1 color_map { Edges } })
Tile(1, 0, pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 7 exterior 2 interior 2 form 2 rotate x*90 scale 0.15 color_map { Edges } })
Tile(2, 0, pigment { pavement number_of_sides 3 number_of_tiles 4 pattern 2 exterior 1 interior 1 form 1 rotate x*90 scale 0.15 color_map { Edges } })
Tile(3, 0, pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 17 interior 1 form 2 rotate x*90 scale 0.1 color_map { Edges } })
Tile(4, 0, pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 3 interior 2 form 1 rotate x*90 scale 0.1 color_map { Edges } })
Tile(5, 0, pigment { pavement number_of_sides 6 number_of_tiles 4 pattern 6 rotate x*90 scale 0.1 color_map { Edges } })
