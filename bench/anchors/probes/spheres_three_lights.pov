// Probe of bench/pov_anchors.sh (written at stop 56, after the anchors were
// tuned): three spheres, one scaled, phong, specular and a gradient, three
// lights, a turned checker floor (lancer -i shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> angle 55 }
light_source { <-4, 6, -5> color rgb 0.8 }
light_source { <5, 4, -2> color rgb 0.4 }
light_source { <0, 8, 4> color rgb 0.3 }
plane { y, 0 pigment { checker rgb 1, rgb <0.2, 0.3, 0.4> } rotate y*15 }
sphere { 0, 1 scale <1, 0.7, 1> translate <-1.7, 0.7, 0> pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.6 specular 0.3 } }
sphere { <0, 1, 1>, 1 pigment { rgb <0.2, 0.9, 0.3> } finish { diffuse 0.8 specular 0.5 roughness 0.02 } }
sphere { 0, 0.6 translate <1.6, 0.6, -0.8> pigment { gradient y color_map { [0 rgb <0.2,0.3,1>] [1 rgb 1] } } }
