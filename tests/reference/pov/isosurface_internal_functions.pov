// Isosurfaces of functions.inc's internal functions beyond the basic
// shapes: a double helix (f_helix1, as abyss.pov uses it), an algebraic
// surface clamped by its field strength (f_torus2), a rounded-square helix
// (f_helix2, section 0.5 turned), a surface of revolution of a 2-D curve
// (f_witch_of_agnesi_2d, SOR switch on) and ridged multifractal noise
// (f_ridged_mf) displacing a sheet.
// Reference: povray +Iisosurface_internal_functions.pov +Oisosurface_internal_functions.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 3.2, -7.5> look_at <0, 0.2, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.35 shadowless }
background { color rgb <0.25, 0.3, 0.4> }
#declare Paint = finish { phong 0.4 diffuse 0.7 ambient 0.1 }

isosurface {
  function { f_helix1(x, y, z, 2, 4, 0.15, 0.5, 1, 1, 0) }
  contained_by { box { <-0.8, -1.2, -0.8>, <0.8, 1.2, 0.8> } }
  max_gradient 3
  pigment { color rgb <1, 0.55, 0.2> } finish { Paint }
  translate <-2.6, 0.1, 0.8>
}
isosurface {
  function { -f_torus2(x, y, z, 1, 0.7, 0.25) }
  contained_by { box { <-1.1, -0.4, -1.1>, <1.1, 0.4, 1.1> } }
  max_gradient 8
  pigment { color rgb <0.3, 0.7, 1> } finish { Paint }
  rotate <-50, 20, 0> translate <0, 0.2, 0.8>
}
isosurface {
  function { f_helix2(x, y, z, 0, 3, 0.25, 0.45, 0, 0.5, 0) }
  contained_by { box { <-0.8, -1.1, -0.8>, <0.8, 1.1, 0.8> } }
  max_gradient 2.5
  pigment { color rgb <0.4, 0.9, 0.4> } finish { Paint }
  translate <2.6, 0, 0.8>
}
isosurface {
  function { -f_witch_of_agnesi_2d(x, y, z, 1, 0.4, 0.3, 1, 0, 0) }
  contained_by { box { <-1, -0.05, -1>, <1, 1, 1> } }
  max_gradient 6
  pigment { color rgb <0.85, 0.4, 0.9> } finish { Paint }
  translate <-1.9, -0.9, -1.8>
}
isosurface {
  function { y - 0.3 * f_ridged_mf(x * 0.8, 0, z * 0.8, 0.5, 2, 3, 1, 2, 2) }
  contained_by { box { <-1.3, -0.1, -0.8>, <1.3, 0.9, 0.8> } }
  max_gradient 12
  pigment { color rgb <1, 0.3, 0.35> } finish { Paint }
  translate <1.7, -1.1, -1.7>
}
