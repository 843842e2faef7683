// A pre-3.7 scene without assumed_gamma: POV-Ray writes the colours
// unchanged (no sRGB curve). `version` reads the #version in force.
#version 3.6;
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
plane { y, 0 pigment { color rgb 0.5 } }
#if (version < 3.7)
  sphere { <-1.1, 0.7, 0>, 0.7 pigment { color rgb <0.8, 0.4, 0.2> } finish { phong 0.5 } }
#end
#declare Saved = version;
#version 3.7;
#if (version = 3.7)
  sphere { <1.1, 0.7, 0>, 0.7 pigment { color rgb <0.2, 0.4, 0.8> } }
#end
#version Saved;
