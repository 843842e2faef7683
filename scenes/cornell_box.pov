// cornell_box.pov: the Cornell box, lit by a rectangular area light in the
// ceiling. Shows: boxes and planes as walls, a physical area light, colour
// bleeding (path, gather), soft shadows (path; shadow with area_samples).
// Suits: path (reference), gather, shadow, whitted, raycast.
#version 3.7;
global_settings { assumed_gamma 1.0 }

render_settings { integrator "path" { max_depth 8 } width 256 height 256 samples 64 }

camera {
    location <0, 1, -3.4>
    look_at <0, 1, 0>
    right x
    angle 40
}

#declare White = texture { pigment { color rgb 0.73 } finish { ambient 0 diffuse 1 } }
#declare Red   = texture { pigment { color rgb <0.63, 0.065, 0.05> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.14, 0.45, 0.091> } finish { ambient 0 diffuse 1 } }

// The room: a 2 x 2 x 2 box open towards the camera.
plane { y, 0 texture { White } }                    // floor
plane { y, 2 texture { White } }                    // ceiling
plane { z, 1 texture { White } }                    // back wall
plane { x, -1 texture { Red } }                     // left wall
plane { x, 1 texture { Green } }                    // right wall

// A 0.5 x 0.5 panel just under the ceiling.
light_source {
    <0, 1.98, 0>
    color rgb <1, 0.85, 0.6> * 4
    area_rectangle <0.5, 0, 0>, <0, 0, 0.5>
}

box { <-0.3, 0, -0.3>, <0.3, 1.2, 0.3> rotate y * 20 translate <-0.35, 0, 0.35> texture { White } }
box { <-0.3, 0, -0.3>, <0.3, 0.6, 0.3> rotate y * -18 translate <0.35, 0, -0.3> texture { White } }
