// POV's light_group: a group's lights light only its objects (and cast
// their shadows on them); the scene's lights reach a group's objects only
// with global_lights on. A red light in one group, a blue one in another
// with global_lights; the floor and the middle ball are outside the groups.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> }
light_source { <-4, 6, -5> color rgb 0.8 }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <0, 0.6, 0>, 0.6 pigment { color rgb 1 } }
light_group {
  light_source { <3, 4, -3> color rgb <1, 0.2, 0.2> }
  sphere { <-1.6, 0.6, 0>, 0.6 pigment { color rgb 1 } }
  box { <-2.4, 0, 1>, <-0.8, 1.6, 1.3> pigment { color rgb 0.9 } }
}
#declare Blue = light_group {
  light_source { <-3, 3, -4> color rgb <0.2, 0.3, 1> }
  sphere { <0, 0.5, 0>, 0.5 pigment { color rgb 1 } }
  global_lights on
  translate <1.7, 0, 0>
}
object { Blue }
