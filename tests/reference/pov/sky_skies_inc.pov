// skies.inc's declared sky_spheres, one turned, over a background colour.
#version 3.7;
#include "colors.inc"
#include "skies.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 0.5, -4> look_at <0, 2, 0> angle 80 }
background { rgb <0.3, 0.1, 0.0> }
sky_sphere { S_Cloud2 rotate y*30 }
sphere { <0, 1, 0>, 1 pigment { rgb 1 } finish { reflection 1 ambient 0 diffuse 0 } }
plane { y, 0 pigment { rgb 0.5 } }
