// The camera inside a hollow sphere of scattering and absorbing media, as
// in POV's abyss.pov: every camera ray starts in the sphere's medium, so
// the objects inside it are hazed by their distance (POV-Ray's containing
// interiors), not only the rays that reach the sphere's far side. A
// smaller hollow box with emitting media sits inside, and a glass ball
// whose refracted rays keep the medium.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 60 }
light_source { <-4, 9, -3> color rgb 1.2 }
background { rgb <0.1, 0.2, 0.4> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { <1.6, 1, 1>, 1 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.5 } }
sphere { <-0.6, 0.7, -1.5>, 0.7 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.3 } }
box { <-3, 0, 2>, <-1.5, 2.5, 4> pigment { rgbt 1 } hollow interior { media { emission <0.1, 0.25, 0.1> } } }
sphere { <0, 2, -3>, 30 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow
         interior { media { scattering { 1, 0.03 } absorption <0.06, 0.03, 0.01> } } }
