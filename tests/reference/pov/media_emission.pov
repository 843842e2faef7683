// An emitting medium (issue 20): a glowing ball whose density falls off
// from the centre (spherical density with a colour map), and a hollow
// box of constant emission, against a dark room; method 3 with POV's
// default samples, and a second ball sampled with more intervals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <3, 8, -5> color rgb 0.6 }
background { rgb 0 }
plane { y, 0 pigment { rgb 0.5 } }
sphere { 0, 1
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission <1.5, 0.8, 0.3> density { spherical color_map { [0 rgb 0] [1 rgb 1] } } } }
  hollow translate <-1.3, 1.1, 0>
}
sphere { 0, 0.8
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission <0.3, 0.6, 1.5> absorption 0.5 intervals 5 samples 4, 4
                     density { spherical } density { gradient y color_map { [0 rgb 1] [1 rgb 0.2] } scale 2 translate -y } } }
  hollow translate <1.3, 1.1, 0.5>
}
box { <-0.5, 0.01, -2>, <0.5, 0.4, -1.5>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission 0.8 absorption 0.4 } }
  hollow
}
