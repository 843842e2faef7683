// POV's lathe with every spline: a linear vase, a quadratic and a cubic
// bowl, a Bezier bulb; seen from above and the side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.4, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
lathe { linear_spline 6, <0, 0>, <0.8, 0>, <0.5, 0.6>, <0.7, 1.5>, <0.6, 1.5>, <0, 0.2>
  pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } translate <-3, -1, 1> }
lathe { quadratic_spline 5, <0, -0.5>, <0, 0>, <1, 0.3>, <0.9, 1>, <0.5, 1.4>
  pigment { color rgb <0.3, 0.8, 0.4> } translate <-0.6, -1, 1.2> }
lathe { cubic_spline 6, <0, -1>, <0, 0>, <0.9, 0.2>, <0.6, 0.9>, <0.9, 1.3>, <1, 2>
  pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } translate <1.8, -1, 1> }
lathe { bezier_spline 8, <0, 0>, <1.2, 0>, <0.9, 1>, <0.3, 1.1>, <0.3, 1.1>, <0.2, 1.2>, <0.4, 1.4>, <0, 1.5>
  pigment { color rgb <0.9, 0.8, 0.3> } rotate x*-30 translate <0, -0.6, -2.2> }
