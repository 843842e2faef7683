// Many POV point lights over 400 spheres on a floor (bench/pov_lights.sh):
// the classic integrators light every hit by every light, each behind its
// own shadow ray, as POV-Ray does. `Lights` is set on the command line
// (lancer: --declare; POV-Ray: Declare=Lights=N); 16 without.
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (Lights) #declare Lights = 16; #end
camera { location <0, 12, -22> look_at <0, 0, 0> angle 50 }
plane { y, 0 pigment { rgb 0.8 } }
#declare R = seed(3);
#for (I, 0, 399)
  sphere { <rand(R) * 30 - 15, 0.5, rand(R) * 30 - 15>, 0.5
    pigment { rgb <rand(R), rand(R), rand(R)> } finish { phong 0.5 } }
#end
#for (I, 0, Lights - 1)
  light_source { <rand(R) * 30 - 15, 3 + rand(R) * 5, rand(R) * 30 - 15> rgb 2 / Lights }
#end
