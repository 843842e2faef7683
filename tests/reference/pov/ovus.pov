// POV's ovus: an egg (top radius half the bottom), equal radii, a top
// radius above the bottom one, a tiny top radius, one scaled and rotated
// about a tilted axis, and one cut open by a box in a difference.
// povray +Iovus.pov +Oovus.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -11> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
ovus { 1, 0.5 pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } translate <-3.6, 0, 2> }
ovus { 0.8, 0.8 pigment { color rgb <0.3, 0.8, 0.4> } finish { specular 0.4 } translate <-1.2, -0.2, 2> }
ovus { 0.55, 1 pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } translate <1.2, -0.45, 2> }
ovus { 0.9, 0.04 pigment { color rgb <0.9, 0.8, 0.3> } finish { phong 0.3 } translate <3.6, -0.1, 2> }
ovus { 1, 0.6 pigment { color rgb <0.8, 0.5, 0.9> } finish { phong 0.6 reflection 0.1 }
  scale <0.6, 1, 0.8> rotate <-20, 0, 70> translate <-2, 0, -1.5> }
difference {
  ovus { 1, 0.7 }
  box { <-2, 0.4, -2>, <0.2, 2, 0.1> }
  pigment { color rgb <0.95, 0.6, 0.2> } finish { phong 0.4 }
  rotate y*-30 translate <2, 0, -1.5>
}
