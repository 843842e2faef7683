// Anchor scene of bench/pov_anchors.sh: spheres between two facing mirrors,
// five bounces (lancer -i whitted; POV-Ray without anti-aliasing).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
camera { location <0.5, 1.5, -3.5> look_at <0, 1, 0> angle 60 }
light_source { <2, 4, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 } }
#declare Mirror = finish { reflection 0.9 ambient 0 diffuse 0.1 }
box { <-3, 0, 2>, <3, 3, 2.1> pigment { rgb 1 } finish { Mirror } }
box { <-3, 0, -4.1>, <3, 3, -4> pigment { rgb 1 } finish { Mirror } }
sphere { <-0.7, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } finish { reflection 0.3 specular 0.6 } }
sphere { <0.7, 0.5, 0.5>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } finish { phong 0.8 } }
