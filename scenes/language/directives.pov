// Shows the directive layer: #declare/#local, #while, #for, #if, #switch and
// a #macro that emits objects, all building a small grid of spheres.
// Suits: raycast (a language scene: the picture only proves it evaluates).
#version 3.7;
#include "colors.inc"
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -10> look_at <0, 0.5, 0> angle 50 }
light_source { <10, 12, -8> color White }

#macro Ball(Position, Tint)
  sphere { Position, 0.4 pigment { color Tint } finish { phong 0.3 } }
#end

union {
  #for (Row, -2, 2)
    #declare Column = -2;
    #while (Column <= 2)
      #switch (mod(Row + Column + 4, 3))
        #case (0) Ball(<Column, 0.4, Row>, Red) #break
        #case (1) Ball(<Column, 0.4, Row>, Green) #break
        #else Ball(<Column, 0.4, Row>, Blue)
      #end
      #declare Column = Column + 1;
    #end
  #end
  rotate y * 15
}

plane { y, 0 pigment { checker color White, color Gray50 } }
