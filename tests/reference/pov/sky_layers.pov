// sky_sphere with two pigments (the upper one partly filtering and
// transmitting), moved as a whole, seen directly and in a mirror sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 1.5, 0> angle 70 }
light_source { <3, 5, -4> color rgb 1 }
background { rgb <0.9, 0.2, 0.1> }
sky_sphere {
  pigment { gradient y color_map { [0 color rgb <1, 1, 1>] [0.4 color rgb <0.2, 0.3, 0.9>] [1 color rgb <0, 0, 0.3>] } }
  pigment {
    bozo turbulence 0.6 scale <0.3, 0.1, 0.3>
    color_map { [0.4 color rgbt 1] [0.7 color rgbt <1, 1, 1, 0.2>] [1 color rgbf <0.6, 0.6, 0.6, 0.5>] }
  }
  rotate x*10 translate y*0.1
}
sphere { <0, 1, 0>, 1 pigment { rgb 0.9 } finish { reflection 0.6 ambient 0 diffuse 0.4 } }
plane { y, 0 pigment { checker rgb 0.2 rgb 0.8 } }
