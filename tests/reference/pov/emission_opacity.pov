// POV-Ray scales a finish's emission (and ambient) by the surface's
// opacity: a filtering or transmitting sphere shows that much less of its
// own light, and the rest is what it lets through. (Nothing else is in
// view: lancer's classic integrators also light the scene from an emitting
// object's proxy, which POV-Ray does not.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.7, -5> look_at <0, 0.7, 0> }
light_source { <-3, 6, -4> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
sphere { <-1.1, 0.7, 0>, 0.7 pigment { rgbf <0.9, 0.2, 0.1, 0.6> } finish { emission 0.8 diffuse 0.2 ambient 0 } }
sphere { <1.1, 0.7, 0>, 0.7 pigment { rgbt <0.1, 0.3, 0.9, 0.5> } finish { emission 0.5 ambient 0.3 } }
sphere { <0, 0.7, 2>, 0.5 pigment { rgbft <0.2, 0.9, 0.3, 0.3, 0.3> } finish { emission 1 phong 0.6 } }
