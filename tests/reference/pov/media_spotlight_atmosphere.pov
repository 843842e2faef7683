// Scene-level media (issue 20): an atmosphere of scattering and absorbing
// media lit by a spotlight whose beam crosses it, a solid box (no media
// inside: not hollow) and a hollow sphere (the atmosphere fills it), with
// jitter, so POV-Ray's samples are random and the images agree in the mean.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1.5, 0> angle 55 }
light_source { <0, 6, -1> color rgb 1.5 spotlight point_at <0.5, 0, 0.5> radius 12 falloff 20 }
background { rgb <0.05, 0.05, 0.1> }
media { scattering { 2, 0.04 } absorption 0.01 intervals 3 samples 6 jitter 0.5 }
plane { y, 0 pigment { rgb 0.7 } }
plane { -z, -5 pigment { rgb 0.4 } }
box { <-3, 0, -1>, <-1.5, 1.5, 0.5> pigment { rgb <0.2, 0.5, 0.9> } }
sphere { <2, 1, -1>, 0.8 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow }
