// An interior written on a union reaches every part that has a texture of
// its own but no interior (POV-Ray's Post_Process gives each child without
// an interior its parent's), through nested unions too; a part with an
// interior of its own keeps it. The parts do not touch.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -5> look_at <0, 0.5, 0> angle 55 }
light_source { <3, 5, -4> color rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.2 scale 0.5 } }
plane { z, 3 pigment { gradient x color_map { [0 rgb <1, 0.3, 0.2>] [1 rgb <0.2, 1, 0.3>] } scale 0.5 } }
union {
  sphere { <-1.6, 0.5, 0>, 0.6 pigment { rgbf <1, 0.9, 0.9, 0.95> } }
  union {
    sphere { <0, 0.5, 0>, 0.6 pigment { rgbf <0.9, 0.9, 1, 0.95> } }
    box { <-0.4, -0.9, -0.4>, <0.4, -0.3, 0.4> pigment { rgbf <0.9, 1, 1, 0.9> } }
  }
  sphere { <1.6, 0.5, 0>, 0.6 pigment { rgbf <0.9, 1, 0.9, 0.95> } interior { ior 1.1 } }
  interior { ior 1.6 }
}
