// A smooth glass height field of plateaus and slopes over a checker floor.
// Its interpolated normals shade and bend the rays, but a ray leaving a
// hit starts off the facet the hit lies on, across the facet's own normal:
// started across the smooth one it found the same slope again at once and
// the glass went black in spots (advanced/glasschess.pov's floor).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
light_source { <500, 50, -5> rgb 1 }
camera { location <1.5, 1.5, -2.0> right x * 4/3 look_at <0, 0, 0> angle 60 }
background { rgb <0.5, 0.2, 0.3> }
height_field {
   function 64, 64 { pigment { checker color rgb 1 color rgb 0 scale 1/16 } }
   smooth translate <-0.5, 0.0,-0.5>
   scale < 12,0.5, 12>
   pigment { rgbf <0.98, 1.0, 0.98, 1> } finish { ambient 0 diffuse 0 }
   interior {ior 1.2}
}
plane { y, -2 pigment { checker rgb 1 rgb <0, 0, 1> scale 1.5 } }
