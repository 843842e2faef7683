// Probe of bench/pov_anchors.sh (stop 56): a circular, oriented 6 x 6
// adaptive area light and a point light over a box, a sphere and a torus
// (lancer -i shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <2, 5, -3> color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 6, 6 adaptive 1 jitter orient circular }
light_source { <-4, 3, -4> color rgb 0.3 }
plane { y, 0 pigment { rgb 0.8 } }
box { <-2.2, 0, -0.5>, <-1.2, 1, 0.5> rotate y*25 pigment { rgb <0.8, 0.3, 0.3> } }
sphere { <0, 0.8, 0.3>, 0.8 pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.5 } }
torus { 0.6, 0.2 translate <1.8, 0.2, -0.2> pigment { rgb <0.3, 0.3, 0.9> } }
