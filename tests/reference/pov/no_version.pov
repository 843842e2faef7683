// A scene with no #version anywhere and no assumed_gamma: POV-Ray 3.7 reads
// it as 3.62 (legacy gamma: colours written unchanged, no sRGB curve)
// while `version` itself reads 3.7, which places the second sphere.
camera { location <0, 1.5, -5> look_at <0, 0.5, 0> }
light_source { <-3, 5, -4> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
box { -0.6, 0.6 rotate y * 30 translate <-1.2, 0.6, 0> pigment { color rgb <0.2, 0.6, 0.3> } }
sphere { <version - 2.5, 0.7, 0>, 0.7 pigment { color rgb <0.8, 0.4, 0.2> } finish { phong 0.5 } }
