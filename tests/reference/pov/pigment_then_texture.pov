// A pigment written on an object before a texture makes the object's
// texture (POV-Ray copies its default texture for it), and the texture
// written after lies on top of it as a layer: the glass block (from
// advanced/glasschess.pov) is clear glass over a filtering grey with the
// default finish's ambient and diffuse, carved with a piece. The right
// ball's finish comes first, its texture after.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
light_source { <500, 50, -5> rgb 1 }
camera { location <7, 1.6, -11> right x * 4/3 look_at <2, 0.8, -3.8> angle 40 }
sky_sphere { pigment { gradient y color_map { [0.0 color rgb <0.3, 0.05, 0.15>] [1.0 color rgb 1] } translate <0, -0.1, 0> } }
plane { y, -0.01 pigment { checker rgb 1 rgb <0, 0, 1> scale 1.5 } }
#declare Glass = texture {
  pigment { rgbf <0.98, 1.0, 0.98, 1> }
  finish { specular 1 roughness 0.001 ambient 0 diffuse 0 reflection { 0, 1 fresnel } }
}
difference {
  superellipsoid { <0.05, 0.05> translate <0, 1, 0> scale <0.5, 0.9, 0.5>
    pigment { rgbf 0.9 }
    texture { Glass }
    interior { ior 1.5 fade_distance 2 fade_power 2 }
  }
  sphere { <0, 1, 0>, 0.3 texture { pigment { rgbt <0.9, 0.9, 0.6, 0.6> } finish { reflection 0.3 } } }
  no_shadow
  rotate <0, 68, 0>
  translate <2.2 * 1.5, 0, -3.5 * 1.5>
}
sphere { <0.6, 0.7, -2.5>, 0.7
  finish { phong 1 phong_size 20 }
  texture { pigment { rgbt <1, 0.6, 0.4, 0.5> } }
}
