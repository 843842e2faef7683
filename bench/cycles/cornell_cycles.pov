// cornell_cycles.pov: a Cornell box for comparing lancer's path integrator
// with Blender Cycles (bench/cycles/cornell_cycles.py builds the same scene
// in Blender). Every element is chosen so that it means exactly the same in
// both renderers:
// - the room is five finite 2 x 2 quads, open towards the camera, so rays
//   leaving the box see the black background in both (infinite planes would
//   need Cycles geometry of a different shape);
// - walls are Lambertian (ambient 0, diffuse 1: albedo = pigment), which is
//   Cycles' Diffuse BSDF at roughness 0;
// - the lamp is an emissive quad of radiance emission x pigment, emitting on
//   both sides (the upper side into the void above the ceiling), as a Cycles
//   Emission shader on a mesh does (a Cycles lamp's
//   watts would need a conversion; a surface's radiance needs none);
// - camera angle is the horizontal field of view in both.
// Keep the numbers in sync with cornell_cycles.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

// max_depth 16 counts bounces from the camera hit (1 = direct light only),
// which is Cycles' max_bounces 15 (0 = direct light only).
render_settings { integrator "path" { max_depth 16 } width 256 height 256 samples 64 }

camera {
    location <0, 1, -3.4>
    look_at <0, 1, 0>
    right x
    angle 40
}

#declare White = texture { pigment { color rgb 0.73 } finish { ambient 0 diffuse 1 } }
#declare Red   = texture { pigment { color rgb <0.63, 0.065, 0.05> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.14, 0.45, 0.091> } finish { ambient 0 diffuse 1 } }
#declare Lamp  = texture { pigment { color rgb <1, 0.85, 0.6> } finish { ambient 0 diffuse 0 emission 40 } }

// A quad from its four corners, in order around its edge.
#macro Quad(A, B, C, D, T)
    mesh { triangle { A, B, C } triangle { A, C, D } texture { T } }
#end

Quad(<-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, White)       // floor
// The ceiling has a hole for the lamp, so the light the lamp sends upwards
// leaves the scene (a lamp under a closed ceiling would light a thin gap
// that diffuse bounces find only by chance: fireflies in both renderers).
Quad(<-1, 2, -1>, <1, 2, -1>, <1, 2, -0.25>, <-1, 2, -0.25>, White)
Quad(<-1, 2, 0.25>, <1, 2, 0.25>, <1, 2, 1>, <-1, 2, 1>, White)
Quad(<-1, 2, -0.25>, <-0.25, 2, -0.25>, <-0.25, 2, 0.25>, <-1, 2, 0.25>, White)
Quad(<0.25, 2, -0.25>, <1, 2, -0.25>, <1, 2, 0.25>, <0.25, 2, 0.25>, White)
Quad(<-1, 0, 1>, <1, 0, 1>, <1, 2, 1>, <-1, 2, 1>, White)         // back wall
Quad(<-1, 0, -1>, <-1, 0, 1>, <-1, 2, 1>, <-1, 2, -1>, Red)       // left wall
Quad(<1, 0, -1>, <1, 0, 1>, <1, 2, 1>, <1, 2, -1>, Green)         // right wall

// A 0.5 x 0.5 lamp filling the hole in the ceiling.
Quad(<-0.25, 2, -0.25>, <0.25, 2, -0.25>, <0.25, 2, 0.25>, <-0.25, 2, 0.25>, Lamp)

box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.35> texture { White } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y * -18 translate <0.35, 0, -0.3> texture { White } }
