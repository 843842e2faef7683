// Probe of bench/pov_anchors.sh (stop 56): a room of mirrors, an inverted
// reflecting box around a fresnel sphere, a metallic one and a cylinder,
// max_trace_level 10 (lancer -i whitted).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.6, -3.5> look_at <0, 1, 0> angle 65 }
light_source { <0, 2.8, -1> color rgb 1 }
box { <-3, 0, -4>, <3, 3, 4> inverse pigment { rgb <0.8, 0.8, 0.7> } finish { reflection 0.6 } }
sphere { <-0.8, 0.7, 0.5>, 0.7 pigment { rgb 0.9 } finish { reflection { 0.2, 1 fresnel on } conserve_energy } interior { ior 1.5 } }
sphere { <0.9, 0.5, -0.3>, 0.5 pigment { rgb <0.9, 0.7, 0.2> } finish { reflection 0.8 metallic } }
cylinder { <0, 0, 1.8>, <0, 1.6, 1.8>, 0.4 pigment { rgb <0.3, 0.4, 0.9> } finish { reflection 0.3 phong 0.8 } }
