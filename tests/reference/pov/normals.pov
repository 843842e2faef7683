// POV-Ray's normals on lit spheres: bumps, dents, ripples, waves,
// wrinkles, quilted and facets (their own normals), a gradient and
// granite (the slope of their value), a slope_map, a normal_map and a
// scaled bump pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <2.1, 1.575, -5> look_at <2.1, 1.575, 0> right x*4.2 up y*3.15 }
light_source { <-10, 12, -15> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
#macro Ball(Col, Row, Nor)
  sphere { <Col*1.05+0.5, Row*1.05+0.5, 0>, 0.5
    texture { pigment { rgb <0.9, 0.85, 0.7> } normal { Nor } finish { ambient 0.1 diffuse 0.8 phong 0.4 } } }
#end
Ball(0, 2, normal { bumps 0.6 scale 0.1 })
Ball(1, 2, normal { dents 0.8 scale 0.15 })
Ball(2, 2, normal { ripples 0.8 scale 0.1 })
Ball(3, 2, normal { waves 0.6 scale 0.1 })
Ball(0, 1, normal { wrinkles 0.7 scale 0.15 })
Ball(1, 1, normal { quilted 0.8 scale 0.15 })
Ball(2, 1, normal { facets size 0.1 })
Ball(3, 1, normal { gradient x 0.8 scale 0.2 })
Ball(0, 0, normal { granite 0.5 scale 0.5 })
Ball(1, 0, normal { gradient y 1 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.25 })
Ball(2, 0, normal { gradient x normal_map { [0.3 bumps 0.6 scale 0.05] [0.7 dents 0.8 scale 0.1] } })
Ball(3, 0, normal { onion 0.5 scale 0.1 })
