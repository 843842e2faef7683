// Interior media (issue 20): a hollow glass sphere holding an absorbing
// medium and a transparent box holding a denser chromatic one, over a
// plain floor and wall under a point light. POV-Ray 3.7 shows interior media
// only in hollow objects; jitter 0 makes its media sampling deterministic.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1.2 }
background { rgb <0.3, 0.4, 0.6> }
plane { y, 0 pigment { rgb <0.9, 0.85, 0.7> } finish { diffuse 0.8 ambient 0.1 } }
plane { -z, -4 pigment { rgb <0.3, 0.5, 0.8> } finish { diffuse 0.8 ambient 0.1 } }
sphere { <-1.2, 1, 0>, 1
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 phong 0.6 reflection 0.05 }
  interior { ior 1.3 media { absorption <0.2, 0.8, 1.2> } }
  hollow
}
box { <0.4, 0.01, -0.6>, <2.2, 1.6, 0.6>
  pigment { rgbt 1 }
  finish { ambient 0 diffuse 0 }
  interior { media { absorption <1.1, 0.4, 0.2> } media { absorption 0.3 } }
  hollow
}
