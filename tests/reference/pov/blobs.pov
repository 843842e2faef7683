// POV's blob: sphere components (one scaled into an ellipsoid, one
// negative) and cylinder components with hemispherical ends, at two
// thresholds; the old `component` syntax too.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> look_at <0, 0.4, 0> angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.4 } }
blob {
  threshold 0.6
  sphere { <-0.6, 0, 0>, 1, 1 }
  sphere { <0.6, 0, 0>, 1, strength 1 }
  sphere { <0, 0.7, 0>, 0.8, 1 scale <1.5, 1, 1> }
  sphere { <0, 0, -0.8>, 0.6, -1 }
  pigment { color rgb <0.9, 0.4, 0.3> } finish { phong 0.6 }
  translate <-2.5, 0, 1>
}
blob {
  threshold 0.5
  cylinder { <-1, -0.5, 0>, <1, 0.5, 0>, 0.6, 1 }
  cylinder { <0, -0.8, -0.6>, <0, 0.9, 0.6>, 0.5, 1.5 }
  sphere { <1, 0.5, 0>, 0.7, 1 }
  pigment { color rgb <0.3, 0.7, 0.9> } finish { phong 0.5 }
  rotate y*20 translate <1.6, 0, 1>
}
blob {
  threshold 0.4
  component 1, 0.9, <-0.4, 0, 0>
  component 1, 0.9, <0.4, 0.2, 0>
  pigment { color rgb <0.5, 0.9, 0.4> }
  translate <0, -0.3, -2.2>
}
