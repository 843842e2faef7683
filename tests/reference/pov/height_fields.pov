// POV's height_field from images: a 16 x 16 8-bit grey PNG flat-shaded
// (its triangulation diagonals show as facets) and smooth, and a 33 x 17
// 16-bit grey PNG, smooth, cut by water_level 0.4. The images hold
// 127 + 120 sin(0.7 x) cos(0.45 y) and 32767 + 30000 sin(0.35 x + 0.2 y)
// cos(0.3 y) at pixel (x, y), y down from the top row.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -7> look_at <0, 0, 0.4> angle 40 }
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -0.01 pigment { checker color rgb 0.85 color rgb 0.4 } }
height_field { png "height_field_16.png" gamma 1.0
  pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 }
  translate <-0.5, 0, -0.5> scale <2.4, 0.8, 2.4> rotate y*20 translate <-1.5, 0, 1.2> }
height_field { png "height_field_16.png" gamma 1.0 smooth
  pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.5 }
  translate <-0.5, 0, -0.5> scale <2.4, 0.8, 2.4> rotate y*-20 translate <1.5, 0, 1.2> }
height_field { png "height_field_33x17.png" gamma 1.0 smooth water_level 0.4
  pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.5 }
  translate <-0.5, 0, -0.5> scale <3.6, 1, 1.6> translate <0, 0, -1.4> }
