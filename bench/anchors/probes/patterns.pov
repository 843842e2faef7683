// Probe of bench/pov_anchors.sh (stop 56): solid noise patterns (granite,
// marble and wood with turbulence, agate, bumps) on a plane, a sphere, a
// CSG difference and a torus (lancer -i shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <5, 6, -3> color rgb 0.4 }
plane { y, 0 pigment { granite color_map { [0 rgb 0.2] [1 rgb 0.9] } scale 2 } normal { bumps 0.3 scale 0.2 } }
sphere { <-2, 1, 0>, 1 pigment { marble turbulence 0.8 color_map { [0 rgb <0.9,0.9,1>] [0.8 rgb <0.3,0.3,0.5>] [1 rgb 0] } } finish { phong 0.5 } }
difference { box { <-0.9, 0, -0.9>, <0.9, 1.8, 0.9> } sphere { <0, 0.9, 0>, 1.15 } pigment { wood turbulence 0.3 color_map { [0 rgb <0.8,0.5,0.2>] [1 rgb <0.4,0.2,0.1>] } scale 0.3 } }
torus { 0.8, 0.25 rotate x*90 translate <2.2, 1.05, 0> pigment { agate } finish { specular 0.6 } }
