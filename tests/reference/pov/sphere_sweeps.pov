// POV's sphere_sweep with every spline: a linear zigzag whose radii vary
// (tangent cones between the spheres, one sphere swallowing the next), a
// b_spline wave and a glossy cubic_spline (Catmull-Rom) loop in 3D, whose
// phong highlight shows any faceting of the normals; one sets tolerance.
// povray +Isphere_sweeps.pov +Osphere_sweeps.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -10> look_at <0, 0.6, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
sphere_sweep { linear_spline 5, <-4.2, -0.6, 0>, 0.4, <-3.2, 1.2, 0.3>, 0.15, <-2.4, -0.2, -0.2>, 0.3,
  <-1.8, 0.3, 0>, 0.9, <-1.5, 1.6, 0.5>, 0.2
  pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.4 } }
sphere_sweep { b_spline 7, <-1, -0.5, -1>, 0.2, <0, 1.5, -1>, 0.5, <1, -0.6, -1.5>, 0.3, <2, 1.4, -1>, 0.1,
  <3, -0.4, -1.5>, 0.45, <4, 1.2, -1>, 0.25, <5, 0, -1>, 0.3
  tolerance 1e-4
  pigment { color rgb <0.3, 0.8, 0.4> } translate <-0.9, 0, -0.4> }
sphere_sweep { cubic_spline 8, <2, 2.5, 3>, 0.3, <0, 0.2, 2>, 0.4, <1.5, 2, 1>, 0.2, <3, 0.3, 0.5>, 0.45,
  <2, -0.5, -0.5>, 0.3, <0.5, 1.5, 0>, 0.35, <0, 3, 2>, 0.15, <-1, 0, 3>, 0.2
  pigment { color rgb <0.3, 0.5, 0.9> } finish { phong 0.9 phong_size 60 specular 0.3 } translate <-0.5, 0, 1> }
