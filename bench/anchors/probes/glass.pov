// Probe of bench/pov_anchors.sh (stop 56): a glass sphere and a
// transmitting cylinder over a turned checker floor and a moved wall, two
// lights: refraction and filtered shadows (lancer -i whitted).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-3, 6, -4> color rgb 1 }
light_source { <4, 5, -2> color rgb 0.5 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 scale 0.5 } rotate y*30 translate <0, 0, 0> }
plane { z, 0 pigment { rgb <0.6, 0.7, 0.9> } translate z*5 }
sphere { <-1.2, 1, 0>, 1 pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { reflection 0.1 phong 0.8 } interior { ior 1.5 } }
cylinder { <1.2, 0, 0>, <1.2, 1.8, 0>, 0.7 pigment { rgbt <1, 0.8, 0.8, 0.7> } interior { ior 1.33 } }
box { <-0.4, 0, 1.5>, <0.4, 0.8, 2.3> pigment { rgb <1, 0.3, 0.2> } rotate y*30 }
