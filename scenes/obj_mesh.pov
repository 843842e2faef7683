// obj_mesh.pov: a Wavefront OBJ with its MTL materials (copper and teal
// segments of a torus knot), loaded once and instanced three times.
// Shows: obj_mesh, MTL to lancer materials, mesh instancing, smooth normals.
// Suits: raycast, shadow, whitted, gather, path.
#version 3.7;
global_settings { assumed_gamma 1.0 }

render_settings { integrator "shadow" { } width 320 height 240 }

camera { location <0, 3, -6> look_at <0, 0.6, 0> right x * 4 / 3 angle 55 }
light_source { <3, 7, -5> color rgb 1 }
light_source { <-5, 3, -3> color rgb 0.28 }
plane { y, 0 texture { pigment { color rgb 0.7 } finish { ambient 0.05 } } }

#declare Knot = obj_mesh { "assets/knot.obj" }
object { Knot translate <-2, 0.7, 0.5> }
object { Knot rotate x * 90 translate <0, 1.2, 1.5> }
object { Knot scale 0.6 translate <2, 0.5, 0> }
