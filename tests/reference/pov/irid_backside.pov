// finish { irid { amount thickness t turbulence f } } (POV's thin-film tint of
// each light's reflection) and diffuse backside (a panel lit from behind).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0.5, 0> right x*4/3 angle 55 }
light_source { <-5, 8, -10> rgb 1 }
light_source { <4, 3, 8> rgb <0.6, 0.6, 0.8> }
plane { y, -1 pigment { checker rgb 0.8, rgb 0.4 } }
sphere { <-1.6, 0.3, 0>, 1 pigment { rgb <0.5, 0.5, 0.5> } finish { irid { 0.5 thickness 0.6 } phong 0.5 } }
sphere { <0.6, 0.3, 0>, 1 pigment { rgb <0.3, 0.2, 0.6> } finish { irid { 0.35 thickness 0.4 turbulence 0.6 } diffuse 0.7 } }
// diffuse backside: a thin panel lit from behind by the second light
box { <1.8, -1, -0.5>, <3.2, 1.6, -0.48> pigment { rgb <0.9, 0.8, 0.5> } finish { diffuse 0.5, 0.6 } }
