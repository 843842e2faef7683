// Two constant fogs (one filtering, one with a transmit floor) over a row
// of spheres receding into the distance, the sky behind them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 1, 10> angle 60 }
light_source { <5, 10, -10> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.1, 0.2, 0.7>] } } }
#declare I = 0;
#while (I < 6)
  sphere { <-3 + I * 1.2, 1, I * 4>, 1 pigment { rgb <1, 0.3 + I * 0.1, 0.2> } }
  #declare I = I + 1;
#end
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 scale 2 } }
fog { distance 30 color rgbft <0.6, 0.7, 0.8, 0.5, 0.3> }
fog { fog_type 1 distance 80 color rgbt <0.5, 0.45, 0.4, 0.6> }
