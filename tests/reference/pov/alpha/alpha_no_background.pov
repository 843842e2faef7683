// +UA with no background statement: the background is transparent; an
// opaque sphere, a sphere of transmit 0.5 (two surfaces: alpha 0.75) and
// one of filter 0.6 over nothing.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <4, 6, -5> color rgb 1 }
sphere { <-1.4, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgbt <0.3, 0.6, 0.9, 0.5> } }
sphere { <1.4, 0.6, 0>, 0.6 pigment { rgbf <0.8, 0.8, 0.2, 0.6> } }
box { <-2.5, -0.2, 1>, <2.5, 0, 3> pigment { rgb 0.7 } }
