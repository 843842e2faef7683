// A glass cone whose base lies in the plane z = 0 and whose apex touches
// the floor. A hit on the base has z exactly 0, which float rounding cannot
// blur: a shadow ray leaving the cone through it must start off the base,
// or it finds the base again at t = 1e-17 and the light is lost (the
// speckled shadow under advanced/diffract.pov's cones).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <4, -5.2, -0.6> look_at <4, -2.1, -2> angle 50 }
light_source { <0.2, 90, 65> color rgb 20 fade_distance 20 fade_power 2 }
cone { 0, 1, -2 * z, 0
  pigment { rgbf 1 } finish { diffuse 0 ambient 0 reflection 0.05 }
  interior { ior 1.45 fade_distance 2 fade_power 3 caustics 1 }
  translate <4, 0.3, 0>
}
plane { z, -2 hollow on pigment { rgb 0.6 } }
