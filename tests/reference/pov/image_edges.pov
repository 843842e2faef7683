// Images at the edges of their pixels, and bump maps of a colour-mapped
// file: as POV-Ray's map_pos, a point exactly on a pixel's edge (the faces
// of a unit box, at x, y = 0 and 1) takes the pixel beyond POV's EPSILON
// nudge, not the next row; a bump_map reads the colour's grey by default
// and a palette file's indices with use_index.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3, -4> look_at <0.5, 0.6, 0> angle 55 }
light_source { <-3, 6, -5> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
plane { y, -0.001 pigment { rgb 0.5 } }
box { 0, 1 pigment { image_map { png "test.png" } } rotate y*20 translate <-1.7, 0, 0> }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> rotate y*30 translate <0.6, 0, 0> pigment { rgb 0.8 }
  normal { bump_map { png "test.png" map_type 0 } bump_size 2 } }
box { <-0.5, 0.13, -0.47>, <0.5, 1.13, 0.53> rotate y*-20 translate <2.5, 0, 0.4> pigment { rgb 0.8 }
  normal { bump_map { png "test.png" map_type 0 use_index } bump_size 0.5 } }
