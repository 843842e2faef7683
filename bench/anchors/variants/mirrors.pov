// Variant anchor of bench/pov_anchors.sh: two facing mirror planes, a
// reflecting checker floor, reflecting spheres and a box, max_trace_level 8
// (lancer -i whitted; POV-Ray without anti-aliasing).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.5, -4> look_at <0, 1, 2> angle 60 }
light_source { <2, 4, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 1, rgb 0.2 } finish { reflection 0.2 } }
plane { z, 4 pigment { rgb 0.1 } finish { reflection 0.9 } }
plane { z, -5 pigment { rgb 0.1 } finish { reflection 0.9 } }
sphere { <-1, 1, 1>, 0.8 pigment { rgb <1, 0.5, 0.2> } finish { reflection 0.3 phong 0.7 } }
sphere { <1.2, 0.6, 0>, 0.6 pigment { rgb <0.3, 0.5, 1> } finish { reflection 0.5 } }
box { <-0.4, 0, 2>, <0.4, 1.5, 2.8> pigment { rgb 0.7 } rotate y*20 }
