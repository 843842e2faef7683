// POV-Ray's no_image and no_reflection: an object hidden from camera rays
// (and what they refract into) still casts its shadow and shows in the
// mirror; one hidden from mirror rays shows to the camera but not in the
// mirror. On a union or CSG they reach every part.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 2.2, -7> look_at <0, 1, 0> angle 55 }
light_source { <-4, 8, -6> color rgb 1 }
background { rgb <0.2, 0.25, 0.35> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.4 } }
// The mirror behind everything.
box { <-4, 0, 2>, <4, 3, 2.2> pigment { rgb 0.05 } finish { reflection 0.9 } }
// Seen only in the mirror and by its shadow.
sphere { <-2, 0.8, 0>, 0.8 pigment { rgb <1, 0.3, 0.2> } no_image }
// Seen directly, missing from the mirror.
union {
  sphere { <0, 0.6, -0.5>, 0.6 } cylinder { <0, 0, -0.5>, <0, 1.8, -0.5>, 0.15 }
  pigment { rgb <0.2, 0.8, 0.3> } no_reflection
}
// A CSG object hidden from the camera, in front of a glass sphere that the
// camera sees it through refraction: hidden there too.
difference {
  box { <1.4, 0, -0.4>, <2.6, 1.2, 0.8> } sphere { <2, 1.2, 0.2>, 0.5 }
  pigment { rgb <0.3, 0.4, 1> } no_image
}
sphere { <1.2, 0.7, -2>, 0.6 pigment { rgbf <1, 1, 1, 0.95> } interior { ior 1.4 } }
// no_image off: seen.
sphere { <-0.9, 0.3, -2.3>, 0.3 pigment { rgb <1, 1, 0.2> } no_image off }
