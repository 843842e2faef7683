// hard_shadows.pov: a point light and a directional (parallel) light over
// spheres, a box and a triangle. Shows: hard shadows from both, and that a
// POV point light, like the parallel one, does not fall off with distance.
// Suits: shadow (the point of it), whitted, path; raycast shows no shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }

render_settings { integrator "shadow" { } width 320 height 240 }

camera { location <0, 4, -9> look_at <0, 0.8, 0> right x * 4 / 3 angle 50 }

plane { y, 0 texture { pigment { color rgb 0.75 } finish { ambient 0.05 diffuse 0.9 } } }

// A warm point light to the left, falling off with distance.
light_source { <-3, 5, -2> color rgb <1, 0.8, 0.6> * 0.8 }
// A cool sun from the upper right.
light_source { <10, 10, -5> color rgb <0.25, 0.3, 0.4> parallel point_at <0, 0, 0> }

sphere { <-1.2, 1, 0>, 1 texture { pigment { color rgb <0.8, 0.2, 0.2> } finish { phong 0.4 phong_size 80 } } }
sphere { <1.5, 0.6, -0.8>, 0.6 texture { pigment { color rgb <0.2, 0.5, 0.8> } finish { specular 0.3 roughness 0.02 } } }
box { <0.8, 0, 1>, <2.2, 1.6, 2> texture { pigment { color rgb <0.9, 0.8, 0.3> } } }
triangle { <-3, 0, 2>, <-1, 0, 3>, <-2, 2.5, 2.5> texture { pigment { color rgb <0.3, 0.8, 0.3> } } }
