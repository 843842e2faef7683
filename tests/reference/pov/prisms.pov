// POV's prism with every spline (linear with a hole, quadratic, cubic,
// Bezier) and both sweeps (linear, conic), capped and open.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -10> look_at <0, 0.2, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
prism { linear_sweep linear_spline -1, 0.5, 10,
  <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <-0.4, -0.4>, <0.4, -0.4>, <0.4, 0.4>, <-0.4, 0.4>, <-0.4, -0.4>
  pigment { color rgb <0.9, 0.4, 0.3> } rotate y*20 translate <-3, 0, 1> }
prism { quadratic_spline -1, 0.2, 6, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>, <0, 1>
  pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.5 } translate <0, 0, 1.3> }
prism { cubic_spline 0, 1.2, 7, <0.5, -1>, <1, 0>, <0, 1.2>, <-1, 0>, <0, -0.6>, <1, 0>, <0, 1.2>
  pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } translate <3, -1, 1> }
prism { bezier_spline -1, -0.2, 8, <0, 0>, <1.5, 0>, <1.5, 1>, <0, 1>, <0, 1>, <-0.8, 1>, <-0.8, 0>, <0, 0>
  pigment { color rgb <0.9, 0.8, 0.3> } translate <-2.2, 0, -2.2> }
prism { conic_sweep linear_spline 0, 1, 5, <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1>
  rotate x*180 translate y*0.6 scale <0.8, 1.6, 0.8> pigment { color rgb <0.8, 0.4, 0.9> } translate <0.3, -0.05, -2> }
prism { linear_sweep linear_spline 0, 1, 4, <0, 0>, <1, 0>, <0.5, 1>, <0, 0> open
  pigment { color rgb 0.9 } rotate y*-30 translate <2.2, -1, -2.2> }
