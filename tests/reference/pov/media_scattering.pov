// A scattering medium lit by a point light (issue 20): a hollow box of
// isotropic and Henyey-Greenstein scattering with a sphere inside casting
// its shadow through the medium, seen against a dark wall; the light's
// own shadow rays cross the medium, which dims them.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 1.2, 0> angle 55 }
light_source { <1.5, 5, -1> color rgb 1 }
background { rgb 0 }
plane { y, 0 pigment { rgb 0.6 } }
plane { -z, -3 pigment { rgb 0.3 } }
box { <-2.5, 0.01, -1.5>, <2.5, 3, 1.5>
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior {
    media { scattering { 1, 0.15 } }
    media { scattering { 5, <0.05, 0.08, 0.12> eccentricity 0.5 } intervals 2 }
  }
  hollow
}
sphere { <0.3, 1.5, -0.2>, 0.5 pigment { rgb <1, 0.4, 0.2> } }
