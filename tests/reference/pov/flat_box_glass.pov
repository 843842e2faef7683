// Boxes flat along one axis, made of glass: POV-Ray enters such a box
// through the face that faces the ray, so the ray refracts into the glass
// and stays inside it (the way out is at the same point, too close to
// count) until it meets the next surface. Panes flat in x, y and z, seen
// from either side, over a checker that shows how each bends the view.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <1.5, 4, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <-4, 9, -6> color rgb 1 }
background { rgb <0.55, 0.65, 1> }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 scale 0.5 } finish { diffuse 0.8 ambient 0.2 } }
#declare Glass = material {
  texture { pigment { rgbt <0.9, 1, 0.9, 0.9> } finish { ambient 0 diffuse 0.1 reflection 0.1 } }
  interior { ior 1.4 } }
// flat in y, above the floor: seen from above
box { <-3, 0.5, -2>, <-0.5, 0.5, 1> material { Glass } }
// flat in x and in z, standing: the camera sees one from its +x side, one from -z
box { <1.5, 0, -1.5>, <1.5, 2, 1.5> material { Glass } }
box { <-0.2, 0, 1.2>, <2.5, 2.2, 1.2> material { Glass } }
// flat in y, above the camera's eye line: seen from below
box { <-2, 3.2, -4>, <3, 3.2, -1> material { Glass } }
sphere { <0.5, 0.6, 2.5>, 0.6 pigment { rgb <1, 0.3, 0.2> } }
sphere { <-1.8, 1.2, 1.6>, 0.5 pigment { rgb <0.2, 0.4, 1> } }
