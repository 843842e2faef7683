// +UA with an opaque background: every pixel is opaque.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.2, 0.4, 0.8> }
camera { location <0, 1.2, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <4, 6, -5> color rgb 1 }
sphere { <0, 0.6, 0>, 0.6 pigment { rgbt <0.3, 0.6, 0.9, 0.5> } }
