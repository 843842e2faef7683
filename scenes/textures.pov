// textures.pov: image_map through surface (u,v) on a sphere, a plane, a
// box and an OBJ mesh, and a procedural checker. The test grid marks the
// (u,v) = (0,0) corner in white, so a flipped or rotated mapping shows.
// Shows: image_map (png), checker, obj_mesh with texcoords, pigment scale.
// Suits: raycast, shadow, whitted, path.
#version 3.7;
global_settings { assumed_gamma 1.0 }

render_settings { integrator "shadow" { } width 320 height 240 }

camera { location <0, 3.2, -7> look_at <0, 0.8, 0> right x * 4 / 3 angle 55 }
light_source { <-3, 8, -6> color rgb 1 }

#declare Grid = pigment { uv_mapping image_map { png "assets/uv_grid.png" interpolate 2 } }

// The floor: the same image laid flat (a planar image_map turned onto the
// x-z plane), one grid tile per 4 units. (POV-Ray defines no (u, v) for a
// plane: uv_mapping would read the hit's x and y, a single row here.)
plane { y, 0 texture { pigment { image_map { png "assets/uv_grid.png" interpolate 2 } rotate x * 90 scale 4 }
                       finish { ambient 0.05 } } }
sphere { <-2.2, 1, 0.5>, 1 texture { pigment { Grid } finish { ambient 0.05 } } }
// The box maps POV's unfolded cube: each face shows its own part of the grid.
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate y * 25 translate <0, 0, 1.2> texture { pigment { Grid } } }
obj_mesh {
    "assets/knot.obj"
    texture { pigment { Grid } }
    scale 0.9
    translate <2.2, 0.9, 0.4>
}
// Procedural checker on a small box in front.
box {
    <-0.4, 0, -0.4>, <0.4, 0.5, 0.4>
    translate <0.2, 0, -1.4>
    texture { pigment { checker color rgb <0.9, 0.9, 0.2>, color rgb <0.1, 0.1, 0.5> scale 0.2 } }
}
