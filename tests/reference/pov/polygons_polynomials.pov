// POV's polygon (two loops: a frame with a hole, even-odd; 2-D points)
// and its polynomials: a quartic torus, a cubic surface and a poly of
// order 2 (a sphere), clipped and intersected to bound them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 0.5, 0> angle 48 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 5, -4> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
polygon { 10, <0, 0>, <2, 0>, <2, 2>, <0, 2>, <0, 0>, <0.5, 0.5>, <1.5, 0.5>, <1.5, 1.5>, <0.5, 1.5>, <0.5, 0.5>
  pigment { color rgb <0.9, 0.4, 0.2> } rotate y*-20 translate <-3.6, -0.6, 0.5> }
// (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) with R = 0.8, r = 0.3.
quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -1.46, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.1, 0, 0, 0, 0, 1, 0, -1.46, 0, 0.3025 >
  sturm
  pigment { color rgb <0.3, 0.5, 0.95> } finish { phong 0.6 }
  rotate x*-60 translate <0, 0.2, 0.8>
}
intersection {
  cubic { <0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0> }
  box { <-1, -1, -1>, <1, 1, 1> }
  pigment { color rgb <0.3, 0.85, 0.4> }
  translate <2.8, 0, 1>
}
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -0.36> pigment { color rgb <0.9, 0.85, 0.3> } finish { phong 0.5 } translate <-1.5, -0.3, -1.8> }
