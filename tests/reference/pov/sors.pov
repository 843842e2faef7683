// POV's sor: a closed vase and an open goblet, their squared radius a
// cubic in y between points (the first and last only steer the ends).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.6, 0> angle 40 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
sor { 7, <0, -0.5>, <0.6, 0>, <0.8, 0.4>, <0.4, 1>, <0.5, 1.6>, <0.7, 2>, <0.8, 2.2>
  pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } translate <-1.6, -1, 0.5> }
sor { 6, <0.1, -0.3>, <0.1, 0>, <0.15, 0.8>, <0.7, 1.2>, <0.9, 1.8>, <0.6, 2.2> open
  pigment { color rgb <0.3, 0.6, 0.9> } finish { phong 0.5 } rotate x*-20 translate <1.4, -1, 0.5> }
