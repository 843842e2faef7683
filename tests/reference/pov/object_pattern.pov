// The object pattern: inside (second item) or outside (first) an object's
// solid, with colours, pigments, POV's default colours, and as a list of
// textures; the object named or written inline, moved with the pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 right x*4/3 angle 60 }
light_source { <-5, 8, -10> rgb 1 }
#declare Blob = difference { sphere { 0, 1 } box { <-0.3, -2, -2>, <0.3, 2, 2> } rotate z*30 }
#declare Ring = torus { 0.7, 0.25 rotate x*90 }
// colours: outside, inside
plane { z, 0 clipped_by { box { <-3.3, 0.1, -1>, <-0.1, 2.3, 1> } } pigment { object { Blob rgb <0.1, 0.2, 0.8>, rgb <1, 0.8, 0.2> } translate <-1.7, 1.2, 0> } finish { ambient 1 diffuse 0 } }
// pigments, and the object given inline, scaled with the pigment
plane { z, 0 clipped_by { box { <0.1, 0.1, -1>, <3.3, 2.3, 1> } } pigment { object { Ring pigment { checker rgb 1, rgb 0.3 scale 0.2 } pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,1,0>] } } } scale 1.3 translate <1.7, 1.2, 0> } finish { ambient 1 diffuse 0 } }
// default colours
plane { z, 0 clipped_by { box { <-3.3, -2.3, -1>, <-0.1, -0.1, 1> } } pigment { object { sphere { 0, 0.8 scale <1.5, 1, 1> } } translate <-1.7, -1.2, 0> } finish { ambient 1 diffuse 0 } }
// textures, and a normal list
box { <0.1, -2.3, 0>, <3.3, -0.1, 0.1> texture { object { object { Ring translate <1.7, -1.2, 0> } texture { pigment { rgb 0.8 } finish { phong 0.5 } } texture { pigment { rgb <0.9, 0.3, 0.3> } normal { bumps 0.8 scale 0.1 } } } } }
