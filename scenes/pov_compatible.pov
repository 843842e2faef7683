// pov_compatible.pov: a scene valid in POV-Ray 3.7 unchanged, written in
// the common subset so both programs render the same picture. The lights use
// fade_distance/fade_power 2, which lancer and POV-Ray attenuate alike; the
// finishes avoid phong/specular (lancer normalises those lobes) and area
// lights (physical rectangles in lancer), the documented differences.
// Render in POV-Ray with: povray +W320 +H240 -A pov_compatible.pov
// Suits: raycast, shadow, whitted.
#version 3.7;
#include "colors.inc"

global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera {
    location <0, 2, -6>
    look_at <0, 0.8, 0>
    right x * image_width / image_height
    angle 55
}

light_source { <-4, 6, -5> color White fade_distance 8 fade_power 2 }
light_source { <5, 3, -2> color rgb <0.3, 0.3, 0.4> fade_distance 6 fade_power 2 }

background { color rgb <0.1, 0.1, 0.15> }

plane {
    y, 0
    texture {
        pigment { checker color rgb 0.8, color rgb 0.3 }
        finish { ambient 0.05 diffuse 0.7 reflection 0.1 }
    }
}

#declare Shiny = finish { ambient 0.05 diffuse 0.6 reflection 0.3 }

union {
    sphere { <-1.3, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.1> } }
    sphere { <1.3, 0.7, -0.3>, 0.7 pigment { color rgb <0.1, 0.4, 0.8> } }
    finish { Shiny }
}

box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> rotate y * 35 translate <0.1, 0, 1.5> pigment { color Yellow } }

mesh2 {
    vertex_vectors { 4, <-3, 0, 2>, <-2, 0, 3>, <-2.5, 1.8, 2.5>, <-1.6, 0, 1.6> }
    face_indices { 2, <0, 1, 2>, <1, 3, 2> }
    pigment { color Green }
}
