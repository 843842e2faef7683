// facing_mirrors.pov: two parallel mirrors with a sphere between them: an
// infinite corridor of reflections. Shows: deep recursion, max_trace_level,
// the adc_bailout weight cut-off. Suits: whitted (the point of it), path.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 40 }

render_settings { integrator "whitted" { } width 320 height 240 }

camera { location <0.6, 1.6, -2.5> look_at <-0.2, 1.2, 0> right x * 4 / 3 angle 60 }

light_source { <0, 3.5, -1> color rgb 0.9 }

plane { y, 0 texture { pigment { checker color rgb 0.9, color rgb 0.1 scale 0.5 } finish { ambient 0.05 } } }
plane { y, 4 texture { pigment { color rgb 0.9 } finish { ambient 0.2 } } }

// Slightly tinted mirrors so successive images fade and shift in colour.
#declare Mirror = texture { pigment { color rgb 0 } finish { ambient 0 diffuse 0 reflection { rgb <0.92, 0.95, 0.9> } } }
box { <-2.05, 0, -4>, <-2, 3, 4> texture { Mirror } }
box { <2, 0, -4>, <2.05, 3, 4> texture { Mirror } }

sphere { <0, 1, 0.5>, 0.5 texture { pigment { color rgb <0.9, 0.3, 0.1> } finish { phong 0.5 } } }
