// text { internal N … }: POV-Ray's built-in fonts (1 timrom, 2 cyrvetic,
// 3 crystal, other numbers povlogo), which it also ships as files; and a
// character the font lacks drawn as the font's missing-character glyph
// (povlogo's is the POV-Ray logo, which it shows for "A" and "P").
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.2, 0.6, -5> look_at <1.2, 0.6, 0> }
light_source { <-3, 5, -6>, 1 }
#declare Face = finish { ambient 0.3 diffuse 0.7 }
text { internal 1 "Times" 0.25, 0 translate <-1.1, 1.5, 0> pigment { rgb <1, 0.6, 0.2> } finish { Face } }
text { internal 2 "Cyr" 0.25, <0.05, 0, 0> translate <-1.1, 0.5, 0> pigment { rgb <0.4, 0.9, 0.4> } finish { Face } }
text { internal 3 "Crys" 0.25, 0 translate <1.2, 0.5, 0> pigment { rgb <0.9, 0.4, 0.9> } finish { Face } }
text { internal 0 "AP" 0.25, 0 translate <-0.6, -0.6, 0> pigment { rgb <0.3, 0.6, 1> } finish { Face } }
