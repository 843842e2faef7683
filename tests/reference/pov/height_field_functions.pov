// height_field { function W, H { … } }: a float function (smooth) and a
// pigment function's grey, as POV-Ray makes them into 16-bit images.
// Reference: povray +Iheight_field_functions.pov +Oheight_field_functions.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 1.2, -0.9> look_at <0.5, 0.1, 0.5> angle 55 }
light_source { <-2, 5, -3> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
height_field {
  function 64, 48 { 0.5 + 0.3 * sin(x * 9) * cos(y * 7) }
  smooth
  pigment { color rgb <0.9, 0.7, 0.4> }
  scale <0.5, 0.4, 1>
}
height_field {
  function 40, 40 { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.2>] } } }
  pigment { color rgb <0.4, 0.8, 0.5> }
  scale <0.5, 0.3, 1> translate x * 0.5
}
