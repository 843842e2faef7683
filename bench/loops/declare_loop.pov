// Loop bench (bench/README.md, 'Plain expressions without the grammar'): 200,000 passes
// of two #declares of rand/vlength/sin, one sphere in the end.
#version 3.7;
camera { location <50, 50, -100> look_at <50, 50, 0> }
light_source { <0, 100, -100> color rgb 1 }
#declare S = seed(3);
#declare Sum = 0;
#for (I, 0, 199999)
  #local P = <rand(S), rand(S), rand(S)> * 100;
  #declare Sum = Sum + vlength(P) * sin(I / 10);
#end
sphere { 0, 1 pigment { rgb 1 } }
