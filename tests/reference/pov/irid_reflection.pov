// irid tints what a surface reflects as well as its highlights: POV-Ray's
// ComputeReflection multiplies the reflected ray's colour by the film's
// interference colour, for the directions of the incoming and the
// reflected ray, before the reflection exponent, which raises the colour
// to 1 / exponent (POV's Reflect_Exp). Left: a mirror ball with a
// turbulent film; right: a thin film, `exponent 0.6` and a bumped normal;
// behind, a flat mirror with a thick film.
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength rgb <0.25, 0.18, 0.14> }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 6, -5> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb 0.2] [1 rgb <0.4, 0.6, 1>] } } }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.5> } }
sphere { <-1.1, 0.9, 0>, 0.9
  pigment { rgb 0.1 }
  finish { reflection 0.8 specular 0.6 roughness 0.01 irid { 0.5 thickness 0.6 turbulence 0.4 } }
}
sphere { <1.1, 0.9, 0>, 0.9
  pigment { rgb <0.3, 0.2, 0.1> }
  normal { bumps 0.3 scale 0.2 }
  finish { reflection { 0.7 exponent 0.6 } irid { 0.35 thickness 0.15 } }
}
box { <-3, 0, 2>, <3, 3, 2.1>
  pigment { rgb 0.05 }
  finish { reflection 0.6 irid { 0.7 thickness 2.5 } }
}
