// cornell_cycles_specular.pov: cornell_cycles.pov with the tall box a mirror
// and the short one glass, for comparing lancer's path with Blender Cycles
// on specular paths and caustics (cornell_cycles.py --specular 1 builds it
// in Blender). Everything else, and every comment on why, is as in
// cornell_cycles.pov; keep the three files in sync.
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

// A perfect mirror (lancer: reflection 1 and no diffuse; Cycles: a sharp
// white Glossy BSDF, which has no Fresnel either).
box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.35>
      texture { pigment { rgb 1 } finish { ambient 0 diffuse 0 reflection 1 } } }
// Clear glass of ior 1.5 (lancer: a smooth dielectric with Fresnel; Cycles:
// a sharp white Glass BSDF). Lifted 1 mm off the floor: with its bottom
// face in the floor's plane the two renderers resolve the coincident
// surfaces differently (Cycles' image then has a dark band along the
// bottom of the glass and is 3 % darker overall).
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y * -18 translate <0.35, 0.001, -0.3>
      texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } } interior { ior 1.5 } }
