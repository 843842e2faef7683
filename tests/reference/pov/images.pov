// image_map's POV defaults (planar projection, no interpolation), map_type 1
// and 2, image_pattern through a colour map, bump_map, and an image_map
// inside a pigment_map (once). The images are POV-Ray's own, from
// Debian's povray-includes.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 right x*4/3 angle 60 }
light_source { <-5, 8, -10> rgb 1 }
// default planar projection, no interpolation
sphere { <-2.2, 1.1, 0>, 1 pigment { image_map { png "test.png" } translate -0.5 scale 2 } finish { ambient 0.3 diffuse 0.7 } }
// spherical and cylindrical, bilinear
sphere { <0, 1.1, 0>, 1 pigment { image_map { png "povmap.png" map_type 1 interpolate 2 } } finish { ambient 0.3 diffuse 0.7 } }
cylinder { <2.2, 0.3, 0>, <2.2, 1.9, 0>, 0.8 pigment { image_map { png "plasma3.png" map_type 2 interpolate 2 } scale <1, 1.6, 1> translate y*0.3 } finish { ambient 0.3 diffuse 0.7 } }
// image_pattern through a colour map, once
box { <-3.2, -2, 0>, <-1.2, 0, 0.1> pigment { image_pattern { png "Mount1.png" interpolate 2 } color_map { [0 rgb <0,0,0.4>] [0.5 rgb <0.2,0.8,0.2>] [1 rgb 1] } translate -0.5 scale 2 translate <-2.2, -1, 0> } finish { ambient 1 diffuse 0 } }
// bump_map on a plane-like box, use_color
box { <-1, -2, 0>, <1, 0, 0.1> pigment { rgb 0.8 } normal { bump_map { png "Mount2.png" interpolate 2 bump_size 3 } translate -0.5 scale 2 translate <0, -1, 0> } finish { phong 0.6 } }
// an image_map inside a pigment_map, once
box { <1.2, -2, 0>, <3.2, 0, 0.1> pigment { gradient x pigment_map { [0 rgb <1, 0.5, 0>] [1 image_map { png "plasma2.png" once } translate -0.5 scale 2 translate <2.2, -1, 0>] } scale 2 translate x*1.2 } finish { ambient 0.5 diffuse 0.5 } }
