// Probe of bench/pov_anchors.sh (stop 57): the common hand-written scene
// with one glass sphere among opaque spheres and a box over a checker
// floor, two lights: most shadow rays are blocked by opaque shapes, a few
// by the glass (lancer -i whitted).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 7, -5> color rgb 1 }
light_source { <5, 6, -2> color rgb 0.6 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.4 } }
sphere { <-2, 1, 0>, 1 pigment { rgb <1, 0.4, 0.3> } finish { phong 0.6 } }
sphere { <0.3, 0.7, 1.2>, 0.7 pigment { rgb <0.3, 0.8, 0.4> } }
box { <1.2, 0, -0.5>, <2.4, 1.4, 0.7> pigment { rgb <0.4, 0.5, 1> } rotate y*15 }
sphere { <0.5, 0.6, -1.4>, 0.6 pigment { rgbf <0.95, 1, 0.95, 0.9> } finish { reflection 0.1 } interior { ior 1.5 } }
