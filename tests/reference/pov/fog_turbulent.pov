// Turbulent constant and ground fog (POV's Turbulence(), noise_generator 2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 65 }
light_source { <5, 10, -10> color rgb 1 }
background { rgb <0.6, 0.7, 0.9> }
cylinder { <0, 0, 0>, <0, 3, 0>, 0.6 pigment { rgb <0.9, 0.4, 0.1> } translate <-2, 0, 3> }
sphere { <1.5, 1, 1>, 1 pigment { rgb <0.2, 0.4, 0.9> } }
plane { y, 0 pigment { rgb 0.7 } }
fog { distance 12 color rgb 0.9 turbulence <0.5, 0.3, 0.5> turb_depth 0.8 octaves 4 omega 0.6 lambda 2.2 }
fog { fog_type 2 distance 3 color rgb <0.5, 0.5, 0.45> fog_offset 0.2 fog_alt 0.5 turbulence 0.8 }
