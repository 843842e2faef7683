// Parametric surfaces: a sphere in a sphere container with precompute and
// a uv-mapped checker (POV's u and v as given, not rescaled), a ribbon in a
// box container that cuts it, scaled and turned, without precompute, a
// torus from functions written apart and called with (u, v), and a
// surface whose functions give no bound (max_gradient too low), drawn with
// the holes POV-Ray leaves.
// Reference: povray +Iparametrics.pov +Oparametrics.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.2, 0> angle 48 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.25, 0.3, 0.4> }
plane { y, -1.1 pigment { color rgb 0.8 } }

parametric {
  function { sin(v) * cos(u) }, function { cos(v) }, function { sin(v) * sin(u) }
  <0, 0>, <2*pi, pi>
  contained_by { sphere { 0, 1.05 } }
  max_gradient 1.2
  accuracy 0.003
  precompute 14, x, y, z
  texture {
    uv_mapping pigment { checker color rgb <1, 0.5, 0.2> color rgb 1 scale <0.7, 0.6, 1> }
    finish { phong 0.5 }
  }
  translate <-2.2, 0, 0.5>
}

parametric {
  function { u * cos(v) } function { 0.3 * sin(3 * v) } function { u * sin(v) }
  <0.3, 0>, <1.3, 2*pi>
  contained_by { box { <-1.2, -1, -1.2>, <1.2, 1, 0.8> } }
  max_gradient 2
  accuracy 0.004
  pigment { color rgb <0.4, 0.9, 0.5> }
  finish { specular 0.4 }
  scale 0.9 rotate <-25, 30, 0> translate <0.1, 0, 0.6>
}

#declare R = 0.6;
#declare r = 0.25;
#declare TorusX = function(u, v) { (R + r * cos(v)) * cos(u) }
#declare TorusY = function(u, v) { r * sin(v) }
#declare TorusZ = function(u, v) { (R + r * cos(v)) * sin(u) }
parametric {
  function { TorusX(u, v) } function { TorusY(u, v) } function { TorusZ(u, v) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { -1, 1 } }
  max_gradient 1
  accuracy 0.003
  precompute 10 x z
  pigment { color rgb <0.5, 0.6, 1> }
  rotate -60*x translate <2.2, 0.1, 0.3>
}

parametric {
  function { u } function { 0.35 * sin(8 * u) * cos(8 * v) } function { v }
  <-0.5, -0.5>, <0.5, 0.5>
  max_gradient 0.5
  accuracy 0.01
  pigment { color rgb <1, 0.9, 0.3> }
  translate <0, 0.2, -2>
}
