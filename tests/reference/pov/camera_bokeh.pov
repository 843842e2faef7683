// Focal blur through a shaped lens (POV's bokeh): a disc with its upper
// right quarter closed. Small bright balls out of focus, behind and in
// front of the focal plane, show the lens' shape (flipped in front of the
// focus); the ball at the focal point stays sharp.
// povray +Icamera_bokeh.pov +Ocamera_bokeh.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.02, 0.02, 0.05> }
light_source { <-10, 20, -20> color rgb 1 }
#declare Open_Disc = pigment { spherical color_map { [0.5 rgb 0] [0.5 rgb 1] } translate <0.5, 0.5, 0> }
camera { location <0, 0, -6> look_at 0 angle 50
         aperture 0.8 blur_samples 120 variance 0 focal_point <0, 0, 0>
         bokeh { pigment { gradient x
           pigment_map { [0.5 Open_Disc]
                         [0.5 gradient y pigment_map { [0.5 Open_Disc] [0.5 rgb 0] }] } } } }
sphere { 0, 0.5 pigment { checker color rgb <1, 0.3, 0.2> color rgb 0.9 scale 0.2 } }
#declare Glow = finish { ambient 1 diffuse 0 }
// Lights out of focus: a row far behind the focus, one nearer, and one
// in front of it (there the shape turns over).
#declare Row = 0;
#while (Row < 3)
  #declare Column = 0;
  #while (Column < 4)
    sphere { <(Column - 1.5) * (2.4 - Row * 0.7), 1.3 - Row * 1.1, 9 - Row * 5.5>, 0.12 + Row * 0.02
             pigment { color rgb <0.6 + Column * 0.3, 0.5 + Row * 0.4, 1.5 - Column * 0.3> * (2.2 - Row * 0.8) } finish { Glow } }
    #declare Column = Column + 1;
  #end
  #declare Row = Row + 1;
#end
