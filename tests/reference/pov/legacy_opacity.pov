// A pre-3.7 scene (#version 3.6, assumed_gamma 1 so the bytes compare with
// 3.7's): a filtering surface's own diffuse and ambient light is scaled by
// 1 - (filter * max(pigment) + transmit), POV-Ray's LegacyOpacity, not by
// 1 - filter - transmit. Strongly coloured filters show the difference.
#version 3.6;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> }
light_source { <-3, 6, -4> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, 0 pigment { checker color rgb 0.7 color rgb 0.3 } }
sphere { <-1.3, 0.7, 0>, 0.7 pigment { rgbf <0.9, 0.2, 0.1, 0.6> } finish { ambient 0.2 diffuse 0.8 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgbft <0.1, 0.3, 0.9, 0.5, 0.2> } finish { ambient 0.2 diffuse 0.8 } }
box { <0.8, 0, -0.5>, <2, 1.2, 0.5> pigment { rgbf <0.5, 0.9, 0.2, 0.8> } finish { ambient 0.3 diffuse 0.7 } }
