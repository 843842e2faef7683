// Shadow rays through overlapping media, as POV-Ray traces them: a light
// ray starts with the objects its ray was in (the camera ray's list, at a
// surface or a media sample), and each stretch up to the next surface is
// dimmed by the media of every object on that list, sampled as one; the
// list then gains or loses the object whose surface it crossed. A ball in
// the overlap of two boxes of absorbing, scattering media, lit through
// both.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -10> look_at <0, 1, 0> angle 60 }
light_source { <10, 20, -5> color rgb 2 }
background { rgb 0.1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
box { <-4, 0, -2>, <1, 3, 4> pigment { rgbf 1 } hollow
  interior { media { method 3 samples 4 intervals 1 aa_threshold 0.1 aa_level 3
    scattering { 2, rgb 0.1 extinction 1 } absorption rgb <0.05, 0.1, 0.2> } } }
box { <-1, 0.5, -1>, <4, 2.5, 3> pigment { rgbf 1 } hollow
  interior { media { method 3 samples 2 intervals 1 scattering { 4, rgb <0.05, 0.1, 0.2> extinction 1 } } } }
sphere { <0, 1.2, 0.5>, 0.5 pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 } }
