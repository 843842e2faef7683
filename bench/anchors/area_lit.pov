// Anchor scene of bench/pov_anchors.sh: soft shadows of an 8 x 8 area light
// with POV-Ray's adaptive sampling (lancer -i shadow; POV-Ray without
// anti-aliasing).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.5, 0> angle 50 }
light_source {
  <2, 6, -3> color rgb 1
  area_light <2, 0, 0>, <0, 0, 2>, 8, 8 adaptive 1 circular orient
}
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-1, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } }
box { <0.4, 0, -0.5>, <1.6, 1.2, 0.7> rotate y * 30 pigment { rgb <0.3, 0.7, 0.3> } }
