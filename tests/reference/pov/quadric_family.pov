// POV's cylinder (closed and open), cone (frustum and apex), torus, disc
// (with a hole) and quadric (an ellipsoid, and an infinite cylinder cut by
// an intersection), lit by two point lights with shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -9> look_at <0, 0.4, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 4, -3> color rgb 0.35 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.35 } finish { diffuse 0.7 } }
cylinder { <-3.2, -1, 1>, <-3.2, 0.8, 1>, 0.6 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
cylinder { <-1.6, -1, 1.2>, <-1.2, 0.6, 0.8>, 0.5 open pigment { color rgb <0.9, 0.8, 0.3> } }
cone { <0, -1, 1>, 0.8, <0, 0.9, 1>, 0.25 pigment { color rgb <0.3, 0.8, 0.35> } finish { specular 0.5 } }
cone { <1.7, -1, 1>, 0.6, <1.7, 1.2, 1>, 0 pigment { color rgb <0.3, 0.5, 0.9> } }
torus { 0.7, 0.25 rotate <-70, 20, 0> translate <3.3, 0, 1> pigment { color rgb <0.8, 0.4, 0.9> } finish { phong 0.8 } }
disc { <-2.5, -0.2, -1.6>, <0.3, 1, -0.6>, 0.75, 0.3 pigment { color rgb <1, 0.6, 0.2> } }
quadric { <1, 4, 2.5>, <0.5, 0, 0>, <0, 0, 0>, -0.6 translate <0, -0.4, -1.8> pigment { color rgb <0.2, 0.8, 0.8> } finish { phong 0.5 } }
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.25 }
  plane { y, 0.5 }
  plane { -y, 1 }
  rotate z*25 translate <2.4, 0, -1.8>
  pigment { color rgb <0.9, 0.9, 0.9> }
}
