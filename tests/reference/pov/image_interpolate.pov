// image_map interpolation, close enough that a texel spans several pixels:
// `interpolate 2` blends the four nearest texels bilinearly, `interpolate 4`
// by the inverse of their squared distances (POV-Ray's norm_dist), which
// keeps each texel's colour near its centre and blends sharply between;
// without it, the texel the point lies in.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0.52, 0.48, -5> look_at <0.52, 0.48, 0> right x * 4/3 * 0.075 up y * 0.075 }
#macro Panel(X, Interpolation)
  plane { -z, 0
    pigment { image_map { png "test.png" #if (Interpolation > 0) interpolate Interpolation #end } }
    finish { ambient 1 diffuse 0 }
    clipped_by { box { <X + 0.52 - 0.016, -1, -1>, <X + 0.52 + 0.016, 2, 1> } }
  }
#end
Panel(-0.0335, 0)
Panel(0, 2)
Panel(0.0335, 4)
