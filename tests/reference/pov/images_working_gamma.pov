// image_maps under assumed_gamma 2.2: POV-Ray decodes a file's colours
// and encodes them into the working space (v^(1/2.2)) before shading, so
// they look as under assumed_gamma 1; a palette image the same
// (POV's advanced/sunsethf.pov).
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 0.6, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 5, -6> color rgb 1 }
background { rgb 0.3 }
sphere { <-1.8, 0.6, 0>, 1 pigment { image_map { png "test.png" } translate -0.5 scale 2 } finish { ambient 0.3 diffuse 0.7 } }
box { <-0.6, -0.5, 0>, <1, 1.5, 0.1> pigment { image_map { png "fract003.png" interpolate 2 } scale <1.6, 2, 1> translate <-0.6, -0.5, 0> } finish { ambient 0.4 diffuse 0.6 } }
sphere { <2, 0.6, 0>, 1 pigment { image_map { png "plasma3.png" map_type 1 } } finish { ambient 0.3 diffuse 0.7 } }
