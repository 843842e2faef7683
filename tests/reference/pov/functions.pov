// The function pattern: user functions with parameters, functions.inc's
// f_noise3d, f_sphere, f_torus and f_agate, pattern and pigment functions,
// select, min/max and comparisons.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { orthographic location <0, 0, -10> look_at 0 right x*8 up y*6 }
#declare Ring = function(a, b) { abs(sqrt(a*a + b*b) - 0.8) }
#declare Tile = function { pattern { checker scale 0.5 } }
#declare Hue = function { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } scale 2 } }
#macro Square(X, Y) box { <X - 1.25, Y - 1.25, 0>, <X + 1.25, Y + 1.25, 0.1> } #end
object { Square(-2.7, 1.4) pigment { function { Ring(x + 2.7, y - 1.4) } color_map { [0 rgb 1] [0.3 rgb <0.2, 0.3, 0.8>] [1 rgb 0] } } finish { ambient 1 diffuse 0 } }
object { Square(0, 1.4) pigment { function { f_noise3d(x * 3, y * 3, z * 3) } color_map { [0 rgb <0, 0.3, 0>] [1 rgb <1, 1, 0.5>] } } finish { ambient 1 diffuse 0 } }
object { Square(2.7, 1.4) pigment { function { select(sin(x * 4) * cos(y * 4), 0.2, 0.5, 0.9) } } finish { ambient 1 diffuse 0 } }
object { Square(-2.7, -1.4) pigment { function { Tile(x, y, z) * 0.5 + f_agate(x, y, z) * 0.5 } color_map { [0 rgb <0.5, 0.1, 0>] [1 rgb <1, 0.9, 0.6>] } } finish { ambient 1 diffuse 0 } }
object { Square(0, -1.4) pigment { function { Hue(x, y, z).red * 0.8 + f_sphere(x, y + 1.4, z, 0) * 0.2 } } finish { ambient 1 diffuse 0 } }
object { Square(2.7, -1.4) pigment { function { select((max(abs(x - 2.7), abs(y + 1.4)) < 0.8 & f_torus(x - 2.7, z, y + 1.4, 0.6, 0.3) < 0) - 0.5, 0.3, 1) } } finish { ambient 1 diffuse 0 } }
