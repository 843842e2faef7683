// Loop bench (bench/README.md): 100,000 spheres, each with its own pigment, from a #while.
#version 3.7;
camera { location <50, 50, -100> look_at <50, 50, 0> }
light_source { <0, 100, -100> color rgb 1 }
#declare I = 0;
#while (I < 100000)
  sphere { <mod(I, 300), div(I, 300), 0>, 0.3 pigment { rgb <0.5, 0.2, 0.1> } }
  #declare I = I + 1;
#end
