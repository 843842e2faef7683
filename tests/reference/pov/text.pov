// POV's text: TrueType glyphs from POV-Ray's own fonts (Debian's
// fonts-povray), extruded, with kerning, an offset between characters,
// letters with holes (even-odd), seen at an angle so the sides show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.6, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.4 } }
text { ttf "timrom.ttf" "AVo gB&" 0.4, 0 pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 }
  rotate y*-15 translate <-2.6, 1.1, 0> }
text { ttf "cyrvetic.ttf" "Text 8%" 0.25, <0.05, 0.02, 0> pigment { color rgb <0.3, 0.6, 0.9> }
  rotate <20, 10, 0> translate <-2.2, 0.1, -1> }
