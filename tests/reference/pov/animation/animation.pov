// An animation: clock moves and turns the objects, clock_delta and
// frame_number change colours, clock_on and final_frame are read.
// Reference frames: povray +Ianimation.pov +Oanimation.png +FN +W160 +H120 -A -D -V +WT2 -GA +KFI1 +KFF4
// (writes animation1.png .. animation4.png)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
background { color rgb <0.3, 0.35, 0.45> }
plane { y, 0 pigment { checker color rgb 0.85 color rgb 0.4 } }
#declare Turn = 360 * clock;
sphere { <-1.5 + 3 * clock, 0.6 + 0.4 * sin(pi * clock), 0>, 0.6
  pigment { color rgb <1, frame_number / final_frame, 0.2> }
  finish { phong 0.5 }
}
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  pigment { color rgb <0.2, 0.4 + clock_delta, 1> }
  rotate y * Turn translate <0, 0, 1.5>
}
#if (clock_on)
  cylinder { <1.8, 0, -1>, <1.8, 0.2 + clock, -1>, 0.2 pigment { color rgb <0.3, 0.9, 0.3> } }
#end
