// material_map: an image's pixels pick textures. Left, POV's own 4-bit
// palette image povmap.png picks by palette index among 3 textures (indices
// past the list: POV-Ray 3.7 takes a number above the count modulo it,
// and the count itself as the last texture), `once`, so the panel's edge
// beyond the image takes the first texture. Right, an RGB image picks by
// its red byte: 0 1 2 3 / 4 5 6 130 among 5 textures. Each texture's own
// pattern and scale apply inside its region.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at 0 right x * 4 up y * 3 }
#declare Flat = finish { ambient 1 diffuse 0 }
#declare T0 = texture { pigment { rgb <0.9, 0.2, 0.1> } finish { Flat } }
#declare T1 = texture { pigment { checker rgb <0.1, 0.7, 0.2> rgb <0.9, 0.9, 0.5> scale 0.1 } finish { Flat } }
#declare T2 = texture { pigment { gradient x color_map { [0 rgb <0.1, 0.1, 0.8>] [1 rgb <0.8, 0.8, 1>] } scale 0.3 } finish { Flat } }
#declare T3 = texture { pigment { rgb <0.9, 0.8, 0.1> } finish { Flat } }
#declare T4 = texture { pigment { rgb <0.2, 0.8, 0.9> } finish { Flat } }
plane { z, 0
  texture { material_map { png "povmap.png" once texture { T0 } texture { T1 } texture { T2 } }
            scale <2.1, 1.6, 1> translate <-2.05, -0.7, 0> }
  clipped_by { box { <-2, -1.5, -1>, <0, 1.5, 1> } }
}
plane { z, 0
  texture { material_map { png "material_map_indices.png" texture { T0 } texture { T1 } texture { T2 } texture { T3 } texture { T4 } }
            scale <1.9, 2.8, 1> translate <0.05, -1.4, 0> }
  clipped_by { box { <0, -1.5, -1>, <2, 1.5, 1> } }
}
