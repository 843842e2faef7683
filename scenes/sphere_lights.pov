// sphere_lights.pov: three sphere lights (lancer's area_sphere extension) of
// equal colour but different sizes and distances over a matte floor.
// Shows: bigger and closer lamps light more; soft shadows grow with the
// lamp's size. Suits: path (reference), gather, shadow (area_samples).
#version 3.7;
global_settings { assumed_gamma 1.0 }

render_settings { integrator "path" { } width 320 height 240 samples 32 }

camera { location <0, 3, -8> look_at <0, 0.5, 0> right x * 4 / 3 angle 55 }

plane { y, 0 texture { pigment { color rgb 0.7 } finish { ambient 0 diffuse 1 } } }

// Small and close, medium and mid-height, large and high: the same colour.
light_source { <-3, 1.2, 0> color rgb 1.5 area_sphere 0.1 }
light_source { <0, 2.0, 0> color rgb 1.5 area_sphere 0.3 }
light_source { <3, 3.0, 0> color rgb 1.5 area_sphere 0.8 }

// A small box beneath each light casts a shadow whose softness shows the
// lamp's size.
#declare Block = box { <-0.2, 0, -0.2>, <0.2, 0.5, 0.2> texture { pigment { color rgb 0.8 } finish { ambient 0 } } }
object { Block translate <-3, 0, 0.6> }
object { Block translate <0, 0, 0.6> }
object { Block translate <3, 0, 0.6> }
