// mesh_camera distribution type 0 with 2 rays per pixel: a pixel's r-th
// ray leaves the r-th mesh; POV averages the rays it traces, so where the
// second mesh has no face (the lower half) the pixel is the first mesh's
// ray alone.
// Reference: povray +Icamera_mesh_averaged.pov +Ocamera_mesh_averaged.png +FN +W160 +H120 -A -D -V +WT2 -GA
#include "camera_world.inc"
#include "camera_mesh_grid.inc"
#declare Full = Pixel_Mesh(160, 120, 0, 120, false)
#declare Half = Pixel_Mesh(160, 120, 0, 60, false)
camera {
  mesh_camera { 2 0
    mesh { Full rotate x * 12 translate <0, 2, -5> }
    mesh { Half rotate <12, 25, 0> translate <0, 2, -5> }
  }
}
