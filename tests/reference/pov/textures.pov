// Patterned, layered and default textures, and interior fade: layers
// composited by their filter and transmit, a texture_map and a block
// pattern of textures whose entries share a finish, #default's finish on
// pigment-only objects, and glass slabs whose interior fades light with
// distance (fade_power 2 and POV's exponential 1001).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
light_source { <-10, 12, -15> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#default { finish { ambient 0.3 diffuse 0.7 } }
#declare Flat = finish { ambient 1 diffuse 0 }
#macro Tile(Col, Row)
  box { <Col*1.05, Row*1.05, 0>, <Col*1.05+1, Row*1.05+1, 0.01> }
#end
// Layers: red under a 75 % blue veil, then a bozo overlay with clear holes.
object { Tile(0, 2) texture { pigment { rgb <1, 0, 0> } finish { Flat } }
                    texture { pigment { rgbt <0, 0, 1, 0.25> } finish { Flat } } }
object { Tile(1, 2) texture { pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.5, 0>] } } finish { Flat } }
                    texture { pigment { bozo scale 0.15 color_map { [0.5 rgbt <1, 1, 1, 1>] [0.5 rgbf <0.2, 0.2, 1, 0.3>] } } finish { Flat } } }
// A texture_map and a checker of textures (one finish throughout).
object { Tile(2, 2) texture { gradient y texture_map {
           [0.2 pigment { rgb <1, 0, 0> } finish { Flat }]
           [0.8 pigment { checker rgb 1, rgb 0 scale 0.1 } finish { Flat }] } translate <2.1, 2.1, 0> } }
object { Tile(3, 2) texture { checker texture { pigment { rgb <0, 0.6, 1> } finish { Flat } }
                                      texture { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } finish { Flat } } scale 0.25 } }
// #default's finish on objects with only a pigment, lit.
object { Tile(0, 1) pigment { rgb <0.9, 0.6, 0.3> } }
sphere { <1.55, 1.55, 0>, 0.5 pigment { granite scale 0.5 } }
sphere { <2.6, 1.55, 0>, 0.5 pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.8 } }
object { Tile(3, 1) texture { pigment { rgb 0.8 } normal { bumps 0.8 scale 0.1 } } }
// Glass slabs of increasing thickness in front of a white card.
box { <-0.2, -0.2, 1>, <4.4, 1.1, 1.1> pigment { checker rgb 1, rgb 0.3 scale 0.25 } finish { Flat } }
#macro Slab(X, Depth, Fade)
  box { <X, 0.05, -Depth>, <X + 0.45, 0.95, 0>
    pigment { rgbt <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }
    interior { ior 1.0 fade_distance 0.5 fade_power Fade fade_color <0.2, 0.6, 1> } }
#end
Slab(0.0, 0.25, 2) Slab(0.5, 0.5, 2) Slab(1.0, 1.0, 2) Slab(1.5, 2.0, 2)
Slab(2.2, 0.25, 1001) Slab(2.7, 0.5, 1001) Slab(3.2, 1.0, 1001) Slab(3.7, 2.0, 1001)
