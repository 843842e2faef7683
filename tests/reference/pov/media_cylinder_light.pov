// Scene-level media lit by two cylinder lights (issue 20): as in POV-Ray
// 3.7, a medium's samples are placed in the stretch of each ray a beam
// lights (POV's ComputeCylinderLightInterval), so a narrow beam in a long
// ray is found. A point light that lights no media (media_interaction off)
// lights the surfaces only; a hollow sphere with media of its own sits in
// the second beam.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -9> look_at <0, 1.5, 0> angle 50 }
light_source { <-3, 8, -2> color rgb 1.2 cylinder point_at <0, 0, 1> radius 0.6 falloff 0.9 tightness 2 }
light_source { <6, 3, 3> color rgb <1, 0.8, 0.5> cylinder point_at <-4, 2, 0> radius 0.3 falloff 0.5 }
light_source { <4, 6, -6> color rgb 0.3 media_interaction off }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.3 } }
sphere { <1.5, 1, 1>, 1 pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.6 } }
box { <-2.5, 0, 2>, <-1, 3, 3> pigment { rgb <0.2, 0.5, 0.8> } }
sphere { <0, 2.3, 1.2>, 0.6 pigment { rgbt 1 } hollow
         interior { media { scattering { 2, 0.6 } } } }
media { scattering { 1, 0.08 } intervals 12 samples 3 }
