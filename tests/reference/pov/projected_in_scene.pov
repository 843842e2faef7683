// projected_through an object that is itself in the scene, as POV-Ray's
// lights/projected_through.pov does: the light reaches a point only along
// rays that meet the object, and only what lies between the point and the
// object can shadow it, so the object does not shadow its own projection.
// A ball between the ring and the wall shadows part of the projected
// diamond, and the ring's own surface is lit only where the light passes
// through it further on.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1, 3, -8> look_at <-0.5, 1.5, 0> angle 50 }
plane { y, 0 pigment { rgb 0.9 } }
plane { z, 1 pigment { rgb <0.3, 0.5, 0.7> } }
#declare Ring = union {
  torus { 1, 0.15 rotate 90*x }
  box { <-0.4, -0.4, -0.05>, <0.4, 0.4, 0.05> rotate 45*z }
  translate <-1, 2, -4> }
object { Ring pigment { rgb <0.7, 0.8, 0.2> } }
sphere { <-1.6, 1.6, -1.2>, 0.3 pigment { rgb <0.9, 0.3, 0.2> } }
light_source { <-1, 2.2, -9> color rgb 2 projected_through { Ring } }
light_source { <3, 6, -6> color rgb 0.5 }
