// POV's old tiles { … tile2 … } texture pattern, on a plane and a sphere.
// povray +Itiles.pov +Otiles.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at 0 angle 50 }
light_source { <3, 5, -4> rgb 1 }
plane { y, 0 texture { tiles { texture { pigment { rgb <0.8, 0.2, 0.1> } finish { phong 0.5 } }
                        tile2 texture { pigment { rgb <0.1, 0.3, 0.9> } } } } }
sphere { <0, 1, 0>, 1 texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb <1, 1, 0> } } } scale 0.5 } }
