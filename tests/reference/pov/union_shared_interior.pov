// The parts of a union or CSG object that take its interior share it: to
// a ray's list of interiors they are one object (POV-Ray's Post_Process
// gives each part without an interior its parent's Interior, by pointer).
// Entering a second overlapping part of such a union "leaves" the object,
// so the ray bends as if into air (left). A nested union's parts that take
// its texture take the outer interior too (the middle's base). A part with
// an interior written for it is an object of its own, in a merge too
// (right).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 1, -5> look_at <0, 0.5, 0> angle 55 }
light_source { <3, 5, -4> color rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0.2 scale 0.5 } }
plane { z, 3 pigment { gradient x color_map { [0 rgb <1, 0.3, 0.2>] [1 rgb <0.2, 1, 0.3>] } scale 0.5 } }
union {
  sphere { <-1.9, 0.5, 0>, 0.55 }
  sphere { <-1.3, 0.5, 0.1>, 0.55 }
  cylinder { <-2.2, -0.4, 0>, <-1.0, -0.4, 0>, 0.25 }
  pigment { rgbf <1, 0.95, 0.9, 0.95> }
  interior { ior 1.5 }
}
union {
  sphere { <-0.25, 0.5, 0>, 0.5 pigment { rgbf <0.9, 0.9, 1, 0.95> } }
  sphere { <0.25, 0.5, 0>, 0.5 pigment { rgbf <0.9, 1, 0.9, 0.95> } }
  union {
    box { <-0.5, -0.9, -0.3>, <0.5, -0.3, 0.3> }
    sphere { <0, -0.3, 0>, 0.35 }
    pigment { rgbf <1, 1, 0.9, 0.9> }
  }
  interior { ior 1.33 }
}
merge {
  sphere { <1.4, 0.5, 0>, 0.55 pigment { rgbf <0.9, 1, 1, 0.95> } interior { ior 1.5 } }
  sphere { <1.9, 0.5, 0>, 0.45 pigment { rgbf <1, 0.9, 1, 0.95> } interior { ior 1.2 } }
  cylinder { <1.4, -0.9, 0>, <1.4, 0.1, 0>, 0.3 pigment { rgbf <1, 1, 0.9, 0.9> } }
  interior { ior 1.4 }
}
