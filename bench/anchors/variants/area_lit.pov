// Variant anchor of bench/pov_anchors.sh: a circular, oriented 8 x 8 adaptive
// area light over a checker plane, a sphere, a box and a cylinder
// (lancer -i shadow; POV-Ray without anti-aliasing).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <0, 6, -2> color rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 8, 8 adaptive 1 circular orient }
plane { y, 0 pigment { checker rgb 0.8, rgb 0.5 } }
sphere { <-1, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.5 } }
box { <0.3, 0, -0.5>, <1.6, 1.2, 0.8> pigment { rgb <0.3, 0.6, 0.9> } }
cylinder { <-0.2, 0, 1.5>, <-0.2, 2, 1.5>, 0.3 pigment { rgb 0.8 } }
