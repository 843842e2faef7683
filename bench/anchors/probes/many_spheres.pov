// Probe of bench/pov_anchors.sh (stop 56): 400 spheres made by a #while
// loop, two lights, a floor: the BVH and the parser's loop (lancer -i shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 12, -18> look_at <0, 0, 0> angle 50 }
light_source { <-10, 20, -10> color rgb 1 }
light_source { <10, 15, -5> color rgb 0.5 }
plane { y, -0.5 pigment { rgb 0.8 } }
#declare I = 0;
#while (I < 400)
  sphere { <mod(I, 20) - 9.5, 0, div(I, 20) - 9.5>, 0.45 pigment { rgb <mod(I,3)/2, mod(I,5)/4, mod(I,7)/6> } finish { phong 0.4 } }
  #declare I = I + 1;
#end
