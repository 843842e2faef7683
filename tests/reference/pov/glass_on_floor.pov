// Transparent boxes resting on a plane: their bottoms lie exactly in the
// plane, so a ray inside one meets its bottom face and the floor at the
// same distance. POV-Ray shows the floor there; lancer once found one or
// the other by the rounding of the distance, and showed the background
// below the floor through half the pixels. (A cylinder's end cap in the
// plane shows the same speckle in POV-Ray 3.7 itself, so none is here;
// lancer shows the floor under it too.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.9, 0.2, 0.6> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.25 scale 0.5 } }
box { <-2.2, 0, -0.5>, <-1.0, 1.2, 0.7> rotate y*-20 pigment { rgbt <1, 1, 1, 0.95> } }
box { <-0.5, 0, -0.6>, <0.6, 1.5, 0.4> rotate y*30 pigment { rgbf <0.8, 1, 0.9, 0.9> } interior { ior 1.5 } }
box { <1.0, 0, -0.4>, <2.2, 1.6, 0.8> rotate y*15 pigment { rgbt <0.7, 0.8, 1, 0.8> } }
