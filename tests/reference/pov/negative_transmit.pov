// Negative filter and transmit, as POV-Ray reads them: what passes a
// surface is filter * pigment + transmit, unclamped, so a negative transmit
// subtracts what lies behind (POV's advanced/transmitfx.pov) and a shadow
// ray through it carries negative light, brightening nothing and darkening
// the floor below the light's own level. A surface with neither filter nor
// transmit is the only opaque one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-2, 8, -3> color rgb 1.2 }
plane { y, 0 pigment { checker rgb <0.2, 0.5, 0.9> rgb 0.85 scale 0.6 } finish { ambient 0.3 } }
sphere { <0, 0.6, 2>, 0.6 pigment { rgb <1, 0.4, 0.1> } finish { phong 1 } }
// a pane that subtracts the view behind it, and casts a negative shadow
box { <-2.5, 0.2, -0.5>, <-0.6, 1.8, -0.45> pigment { rgb 0.5 transmit -1 } finish { ambient 1 diffuse 0 } }
// a pane with a filter below zero
box { <0.6, 0.2, -0.5>, <2.5, 1.8, -0.45> pigment { rgb <0.3, 0.6, 0.9> filter -0.4 transmit 0.9 }
  finish { ambient 0.5 diffuse 0.3 } }
// and one that lets through more than arrives
sphere { <-1, 0.4, 1>, 0.4 pigment { rgb 1 transmit 1.6 } finish { ambient 0 diffuse 0.2 } }
