// POV-Ray's fake caustics (interior { caustics }): shadows of transparent
// objects brighten where the shadow ray meets the surface head on, more
// sharply for smaller values; one bumped, one filtering.
// Reference: povray +Ifake_caustics.pov +Ofake_caustics.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <1, 9, -2> color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <-2, 1, 0>, 0.9
  pigment { color rgbt <1, 1, 1, 0.8> }
  finish { ambient 0 diffuse 0.1 }
  interior { ior 1.3 caustics 1 }
}
sphere { <0, 1, 0>, 0.9
  pigment { color rgbf <0.6, 0.9, 1, 0.7> }
  finish { ambient 0 diffuse 0.1 }
  interior { ior 1.3 caustics 0.25 }
}
box { <-0.7, 0.3, -0.7>, <0.7, 1.5, 0.7>
  pigment { color rgbt <1, 0.9, 0.8, 0.6> }
  normal { bumps 0.6 scale 0.2 }
  finish { ambient 0 diffuse 0.1 }
  interior { caustics 0.6 }
  rotate 30*y translate <2, 0, 0.2>
}
