// Two hollow boxes of scattering media that overlap: where a ray runs in
// both, POV-Ray samples their media as one (MediaFunction::ComputeMedia),
// the coefficients summed at each sample and the samples placed by the
// settings of the first medium with the most intervals, the one entered
// first here (samples 4 against 2). And a shadowless light (POV's fill
// light) lights no medium, only surfaces.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -10> look_at <0, 1, 0> angle 60 }
light_source { <10, 20, -5> color rgb 2 }
light_source { <-6, 3, -6> color rgb <0.4, 0.3, 0.2> shadowless }
background { rgb 0.1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
box { <-4, 0, -2>, <1, 3, 4> pigment { rgbf 1 } hollow
  interior { media { method 3 samples 4 intervals 1 aa_threshold 0.1 aa_level 3
    scattering { 2, rgb 0.1 extinction 0 } } } }
box { <-1, 0.5, -1>, <4, 2.5, 3> pigment { rgbf 1 } hollow
  interior { media { method 3 samples 2 intervals 1
    scattering { 4, rgb <0.05, 0.1, 0.2> extinction 0 }
    density { gradient x color_map { [0 rgb 0.2] [1 rgb 1] } scale 5 translate -x } } } }
