// Anchor scene of bench/pov_anchors.sh: three spheres on a plane, one point
// light, hard shadows (lancer -i shadow; POV-Ray without anti-aliasing).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1.5, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <0, 0.8, 0.5>, 0.8 pigment { rgb <0.2, 0.8, 0.3> } }
sphere { <1.5, 0.6, 0>, 0.6 pigment { rgb <0.2, 0.3, 0.9> } }
