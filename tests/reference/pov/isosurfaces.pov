// Isosurfaces: a box container cutting a solid (its walls close it), a
// sphere container, open, threshold, functions.inc's f_torus and
// f_rounded_box, noise (f_noise3d), transforms, all_intersections in a
// difference, and evaluate.
// Reference: povray +Iisosurfaces.pov +Oisosurfaces.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 3.2, -7.5> look_at <0, 0.2, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.35 shadowless }
background { color rgb <0.25, 0.3, 0.4> }
plane { y, -1.2 pigment { checker color rgb 0.9 color rgb 0.45 } }
#declare Paint = finish { phong 0.4 diffuse 0.7 ambient 0.1 }

// Wavy sphere cut by its box: the flat walls are the container's.
isosurface {
  function { x*x + y*y + z*z - 1.1 + 0.12 * sin(9*x) * sin(9*z) }
  contained_by { box { <-0.9, -1, -0.9>, <0.9, 0.7, 0.9> } }
  max_gradient 4
  pigment { color rgb <1, 0.55, 0.2> } finish { Paint }
  translate <-2.6, 0, 0.8>
}
// A torus from functions.inc in a sphere container, tilted.
isosurface {
  function { f_torus(x, y, z, 0.8, 0.28) }
  contained_by { sphere { 0, 1.2 } }
  max_gradient 1.2
  pigment { color rgb <0.3, 0.7, 1> } finish { Paint }
  rotate <-50, 20, 0> translate <0, 0.1, 0.6>
}
// A rounded box scaled unevenly, with noise on its faces.
isosurface {
  function { f_rounded_box(x, y, z, 0.2, 0.7, 0.7, 0.7) - 0.15 * f_noise3d(x*4, y*4, z*4) }
  contained_by { box { -1, 1 } }
  max_gradient 2.5
  pigment { color rgb <0.4, 0.9, 0.4> } finish { Paint }
  scale <1.1, 0.8, 1> rotate y*30 translate <2.6, -0.3, 0.8>
}
// An open sheet: a wave, with no container walls.
isosurface {
  function { y + 0.25 * cos(5 * x) * cos(4 * z) }
  contained_by { box { <-1.2, -0.5, -0.6>, <1.2, 0.5, 0.6> } }
  open max_gradient 2
  pigment { color rgb <0.9, 0.85, 0.3> } finish { Paint }
  translate <-2.2, -0.6, -1.9>
}
// threshold moves the surface; evaluate picks max_gradient.
isosurface {
  function { sqrt(x*x + y*y + z*z) + 0.1 * sin(12 * y) }
  threshold 0.55
  contained_by { box { -1, 1 } }
  evaluate 1, 1.3, 0.9
  pigment { color rgb <0.85, 0.4, 0.9> } finish { Paint }
  translate <0.2, -0.55, -2.1>
}
// all_intersections lets CSG see both sides.
difference {
  isosurface {
    function { x*x + y*y + z*z - 0.36 }
    contained_by { box { -0.7, 0.7 } }
    all_intersections max_gradient 1.5
  }
  box { <0, 0, -1>, <1, 1, 1> }
  pigment { color rgb <1, 0.3, 0.35> } finish { Paint }
  rotate y*-35 translate <2.2, -0.6, -1.9>
}
