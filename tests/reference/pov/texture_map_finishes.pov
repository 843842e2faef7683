// Each entry of a texture_map, a block pattern's list of textures and a
// material_map is lit with its own finish and normal, and between two map
// entries the lit colours are blended (POV-Ray's ComputeTextureColour):
// a checker of a mirror and a matte phong tile, a gradient from a dull
// bumpy texture to a shiny mirror one, nested maps with transforms, POV's
// old tiles with layered textures on each side, and an average of three
// textures (one bumpy, one a mirror) turned with the texture.
// Reference: povray +Itexture_map_finishes.pov +Otexture_map_finishes.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 5, -3> color rgb 0.4 }
sky_sphere { pigment { gradient y color_map { [0 color rgb <0.9, 0.8, 0.6>] [1 color rgb <0.2, 0.4, 0.9>] } } }
#declare Matte = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { diffuse 0.9 ambient 0.1 phong 0.8 phong_size 20 } }
#declare Mirror = texture { pigment { color rgb 0.2 } finish { diffuse 0.2 ambient 0 reflection 0.7 } }
plane { y, 0 texture { checker texture { Matte } texture { Mirror } scale 1.5 } }
#declare Dull = texture { pigment { color rgb <0.3, 0.8, 0.3> } normal { bumps 0.6 scale 0.15 } finish { diffuse 0.8 } }
#declare Shiny = texture { pigment { color rgb <0.2, 0.3, 0.9> } finish { diffuse 0.5 specular 0.9 roughness 0.01 reflection 0.4 } }
sphere { <-1.6, 1, 0>, 1 texture { gradient x texture_map { [0.2 Dull] [0.8 Shiny] } scale 2 translate -1 } translate <-1.6, 0, 0> }
sphere { <1.6, 1, 0>, 1
  texture {
    onion
    texture_map {
      [0.3 gradient y texture_map { [0.4 Shiny] [0.6 Matte] } scale 0.5]
      [0.7 Dull]
    }
    scale 0.7 rotate 30*z
  }
  translate <1.6, 0, 0>
}
box { <-0.6, 0, 1.5>, <0.6, 1.4, 2.5>
  texture { hexagon texture { Matte } texture { Shiny } texture { Dull } scale 0.3 }
}
#declare Stripes = texture { pigment { gradient y color_map { [0.5 rgbt <1, 1, 1, 0>] [0.5 rgbt <0, 0, 0, 1>] } scale 0.2 } finish { phong 0.9 } }
cylinder { <2.6, 0, 2.2>, <2.6, 1.6, 2.2>, 0.5
  texture { tiles { texture { Shiny } texture { Stripes } tile2 texture { Dull } texture { pigment { rgbf <1, 0.8, 0.2, 0.6> } } } scale 0.4 }
}
sphere { <-2.9, 0.5, -1.6>, 0.5
  texture { average texture_map { [1 Dull] [1 Mirror] [2 pigment { radial frequency 6 color_map { [0 rgb <1, 0.8, 0>] [1 rgb <0.2, 0, 0.5>] } } finish { phong 1 }] } rotate 90*x }
}
