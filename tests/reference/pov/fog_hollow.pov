// Fog applies only outside solid objects: rays through a solid glass
// sphere see no fog inside it, through a hollow one they do; a light with
// media_attenuation is dimmed by the fog on its way.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 60 }
light_source { <0, 8, -2> color rgb 1.5 media_attenuation on }
background { rgb 0 }
sphere { <-1.3, 1, 0>, 1 pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 } }
sphere { <1.3, 1, 0>, 1 pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 } hollow }
box { <-4, 0, 3>, <4, 3, 3.2> pigment { checker rgb <1, 0.2, 0.2> rgb <0.2, 0.2, 1> scale 0.5 } }
plane { y, 0 pigment { rgb 0.8 } }
fog { distance 9 color rgb <0.3, 0.6, 0.3> }
