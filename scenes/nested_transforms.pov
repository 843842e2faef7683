// nested_transforms.pov: unions inside unions, each with its own
// transform, and textures inherited from the enclosing union unless an
// object sets its own. Shows: union, object { Name }, translate/rotate/
// scale/matrix composition, texture inheritance.
// Suits: raycast, shadow, whitted, path.
#version 3.7;
global_settings { assumed_gamma 1.0 }

render_settings { integrator "shadow" { } width 320 height 240 }

camera { location <0, 5, -9> look_at <0, 1, 0> right x * 4 / 3 angle 50 }
light_source { <4, 9, -5> color rgb 0.8 }
light_source { <-6, 4, -4> color rgb 0.22 }

plane { y, 0 texture { pigment { color rgb 0.6 } } }

// One arm: a box with a sphere at its end.
#declare Arm = union {
    box { <0, -0.1, -0.1>, <1.2, 0.1, 0.1> }
    sphere { <1.3, 0, 0>, 0.2 texture { pigment { color rgb <0.9, 0.2, 0.2> } finish { phong 0.5 } } }
}

// A star of arms, itself rotated and lifted; the arms inherit its blue.
#declare Star = union {
    object { Arm rotate y * 0 }
    object { Arm rotate y * 72 }
    object { Arm rotate y * 144 }
    object { Arm rotate y * 216 }
    object { Arm rotate y * 288 }
    texture { pigment { color rgb <0.2, 0.4, 0.9> } }
}

object { Star rotate z * 15 translate <-2, 1.5, 0> }
object { Star scale 0.7 rotate <10, 30, 0> translate <2, 1, 0> }
// A shear through a raw matrix.
object {
    Star
    matrix < 1, 0, 0,
             0.5, 1, 0,
             0, 0, 1,
             0, 2.8, 1.5 >
    scale 0.6
}
