// normal { } bent surfaces that reflect and refract, as POV-Ray traces
// them: a bent normal that faces away from the ray is turned towards it
// before refracting, and a mirror ray the bent normal sends behind the
// surface is reflected about the surface's own normal instead.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 3, -9> look_at <0, 2.2, 0> angle 60 }
light_source { <0, 40, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 scale 2 } finish { ambient 0.1 diffuse 0.7 } }
// Water seen from below: hollow, refracting, totally reflecting at grazing
// angles.
plane { y, 5 hollow on
  pigment { rgbf <0.7, 0.7, 1, 0.9> } finish { reflection 0.6 }
  interior { ior 1.2 }
  normal { bumps 0.6 scale 0.5 } }
// A bumpy mirror ball.
sphere { <1.6, 1.2, 0>, 1.2 pigment { rgb 0.1 } finish { reflection 0.9 }
  normal { dents 1.2 scale 0.15 } }
sphere { <-1.8, 1, 1>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
