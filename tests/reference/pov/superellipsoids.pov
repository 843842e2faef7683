// POV's superellipsoid across its exponents: rounded boxes and cylinders,
// an ellipsoid, an octahedron-like diamond and a pinched star (e, n > 2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.3, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
superellipsoid { <0.2, 0.2> pigment { color rgb <0.9, 0.35, 0.2> } finish { phong 0.5 } rotate <0, 30, 0> translate <-3.3, 0, 1> }
superellipsoid { <1, 0.2> pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.5 } rotate <-90, 0, 0> translate <-1.1, 0, 1> }
superellipsoid { <1, 1> pigment { color rgb <0.3, 0.5, 0.9> } scale <0.8, 1, 0.8> translate <1.1, 0, 1> }
superellipsoid { <2, 2> pigment { color rgb <0.9, 0.8, 0.3> } rotate <20, 30, 0> translate <3.3, 0, 1> }
superellipsoid { <2.5, 3> pigment { color rgb <0.8, 0.4, 0.9> } finish { phong 0.4 } rotate <-80, 20, 0> translate <-1.6, 0, -2> }
difference {
  superellipsoid { <0.3, 0.5> }
  superellipsoid { <1, 1> scale 0.5 translate <0, 0, -1> }
  pigment { color rgb 0.9 }
  rotate y*-30 translate <1.8, 0, -2>
}
