// A room lit by a POV area light (adaptive, no jitter) and a dim fill.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 1, 0> angle 55 }
light_source { <0, 3.8, 0> color rgb 1.2 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive 1 }
light_source { <-4, 3, -5> color rgb 0.2 }
box { <-3, 0, -7>, <3, 4, 3> pigment { color rgb <0.9, 0.85, 0.8> } finish { diffuse 0.7 ambient 0.05 } }
sphere { <-0.9, 0.7, 0.3>, 0.7 pigment { color rgb <0.8, 0.3, 0.2> } finish { phong 0.5 } }
box { <0.4, 0, -0.6>, <1.4, 1.2, 0.4> rotate y*25 pigment { color rgb <0.2, 0.4, 0.8> } }
sphere { <0.2, 0.35, -1.4>, 0.35 pigment { color rgb 0.9 } finish { reflection 0.6 ambient 0 diffuse 0.2 } }
