// POV's julia_fractal: quaternion sqr (default slice) and cube, hypercomplex
// sqr and cube (POV's hypercomplex cube iterates z^2, marched with other
// steps), a hypercomplex and a quaternion set cut by tilted slices.
//   povray +Ijulia_fractals.pov +Ojulia_fractals.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.4, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8
  pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } scale 1.3 translate <-3, 0.3, 1.5> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion cube max_iteration 8
  pigment { color rgb <0.3, 0.8, 0.4> } scale 1.4 rotate <0, 30, 0> translate <0, 0.4, 2> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex sqr max_iteration 9 precision 40
  pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } scale 0.9 translate <3, 0, 1.5> }
julia_fractal { <-0.5, 0.5, 0, 0.1> hypercomplex cube max_iteration 8 slice <0, 0.3, 0, 1>, 0.1
  pigment { color rgb <0.9, 0.8, 0.3> } scale 0.9 rotate <-20, 0, 0> translate <-1.8, -0.2, -2.2> }
julia_fractal { <-0.2, 0.6, 0.2, 0> quaternion sqr max_iteration 10 slice <0.5, 0, 0.3, 1>, 0.2
  pigment { color rgb <0.8, 0.5, 0.9> } finish { phong 0.5 } translate <1.7, 0, -2> }
