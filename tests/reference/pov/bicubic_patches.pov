// POV's bicubic_patch: one hump at type 1 with u_steps/v_steps 1 (its
// facets show) and 4, at type 0 with flatness stopping early, a flat
// patch on its defaults (steps 0: two triangles) and a patch with a
// collapsed edge (POV's +x normal at the collapsed corners); checkers in
// object space show where the pieces lie.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -10> look_at <0, 0.2, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
#declare Hump = bicubic_patch { type 1 u_steps 1 v_steps 1
  <-1, 0, -1>, <-0.33, 0, -1>, <0.33, 0, -1>, <1, 0, -1>,
  <-1, 0, -0.33>, <-0.33, 2, -0.33>, <0.33, 2, -0.33>, <1, 0.5, -0.33>,
  <-1, 0, 0.33>, <-0.33, 2, 0.33>, <0.33, 2, 0.33>, <1, 0.5, 0.33>,
  <-1, 0, 1>, <-0.33, 0, 1>, <0.33, 0, 1>, <1, 0, 1> }
object { Hump pigment { checker color rgb <0.9, 0.4, 0.3> color rgb <0.9, 0.8, 0.3> scale 0.25 }
  finish { phong 0.5 } rotate y*20 translate <-3, -1, 1.2> }
bicubic_patch { type 1 u_steps 4 v_steps 4
  <-1, 0, -1> <-0.33, 0, -1> <0.33, 0, -1> <1, 0, -1>
  <-1, 0, -0.33> <-0.33, 2, -0.33> <0.33, 2, -0.33> <1, 0.5, -0.33>
  <-1, 0, 0.33> <-0.33, 2, 0.33> <0.33, 2, 0.33> <1, 0.5, 0.33>
  <-1, 0, 1> <-0.33, 0, 1> <0.33, 0, 1> <1, 0, 1>
  pigment { checker color rgb <0.3, 0.8, 0.4> color rgb <0.2, 0.4, 0.9> scale 0.25 }
  finish { phong 0.5 } rotate y*-20 translate <0, -1, 1.5> }
bicubic_patch { type 0 flatness 0.2 u_steps 3 v_steps 3
  <-1, 0, -1>, <-0.33, 1, -1>, <0.33, 1, -1>, <1, 0, -1>,
  <-1, 0.6, -0.33>, <-0.33, -0.8, -0.33>, <0.33, 1.5, -0.33>, <1, 0.6, -0.33>,
  <-1, 0.6, 0.33>, <-0.33, 1.5, 0.33>, <0.33, -0.8, 0.33>, <1, 0.6, 0.33>,
  <-1, 0, 1>, <-0.33, 1, 1>, <0.33, 1, 1>, <1, 0, 1>
  pigment { checker color rgb 0.9 color rgb <0.8, 0.4, 0.9> scale 0.3 }
  finish { specular 0.4 } scale 1.1 translate <3, -0.6, 1.2> }
bicubic_patch { type 1 uv_vectors <0, 0>, <2, 0>, <2, 2>, <0, 2>
  <-1, 0, -1>, <-0.33, 0, -1>, <0.33, 0, -1>, <1, 0, -1>,
  <-1, 0, -0.33>, <-0.33, 0, -0.33>, <0.33, 0, -0.33>, <1, 0, -0.33>,
  <-1, 0, 0.33>, <-0.33, 0, 0.33>, <0.33, 0, 0.33>, <1, 0, 0.33>,
  <-1, 0, 1>, <-0.33, 0, 1>, <0.33, 0, 1>, <1, 0, 1>
  pigment { checker color rgb <0.3, 0.7, 0.8> color rgb 0.95 scale 0.4 }
  finish { ambient 0.2 diffuse 0.7 reflection 0.2 } rotate x*-35 rotate y*15 translate <-1.7, -0.2, -2.4> }
bicubic_patch { type 1 u_steps 2 v_steps 2
  <0, 1.2, 0>, <0, 1.2, 0>, <0, 1.2, 0>, <0, 1.2, 0>,
  <-0.6, 0.8, -0.5>, <-0.3, 0.9, 0.2>, <0.3, 0.9, 0.2>, <0.6, 0.8, -0.5>,
  <-1, 0.3, -0.7>, <-0.5, 0.4, 0.5>, <0.5, 0.4, 0.5>, <1, 0.3, -0.7>,
  <-1.2, 0, -0.8>, <-0.6, 0, 0.6>, <0.6, 0, 0.6>, <1.2, 0, -0.8>
  pigment { color rgb <0.95, 0.6, 0.2> } finish { phong 0.6 } rotate y*10 translate <1.6, -1, -2.3> }
