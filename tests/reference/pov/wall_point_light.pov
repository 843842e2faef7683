// A matte wall under POV point lights: cosine law, no falloff (POV's
// point light without fade), a faded light and a shadowless one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 60 }
light_source { <-3, 2, -1> color rgb <0.7, 0.6, 0.5> }
light_source { <4, -1, -3> color rgb <0.2, 0.3, 0.5> fade_distance 2 fade_power 2 }
light_source { <0, 4, -0.5> color rgb 0.25 shadowless }
plane { z, 0 pigment { color rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
sphere { <1, 0.2, -0.8>, 0.6 pigment { color rgb <0.9, 0.4, 0.2> } }
