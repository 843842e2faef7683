// Fog in front of the backs of objects that have no inside (a polygon, a
// triangle, a disc seen from behind): POV-Ray keeps a ray's list of the
// objects it entered, so these rays ran in the open and are fogged. A ray
// through a transparent non-hollow polygon is "in" it from then on, and
// sees no fog beyond it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <-4, 6, -5> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
fog { distance 6 color rgb <0.6, 0.6, 0.7> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
// Faces turned away from the camera: the ray ends on their back.
polygon { 4, <-3, 0.2, 0>, <-1.2, 0.2, 0>, <-1.2, 2, 0>, <-3, 2, 0>
  pigment { rgb <1, 0.3, 0.2> } rotate y*180 translate <-4.2, 0, 2> }
disc { <0, 1, 3>, <0, 0, 1>, 0.9 pigment { rgb <0.2, 0.9, 0.3> } }
triangle { <1.2, 0.2, 1>, <3, 0.2, 1>, <2, 2.2, 1> pigment { rgb <0.3, 0.4, 1> } }
// A transparent screen, then a sphere behind it: POV hides the fog past a
// non-hollow patch the ray went through.
polygon { 4, <-0.8, 0, -1>, <0.8, 0, -1>, <0.8, 0.8, -1>, <-0.8, 0.8, -1>
  pigment { rgbt <1, 1, 1, 0.8> } }
sphere { <0, 0.4, 4>, 0.4 pigment { rgb <1, 0.8, 0.2> } }
