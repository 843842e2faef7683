// mesh_camera distribution type 2: a stereo pair, one mesh per half of the
// image, left to right. The meshes face inwards and a negative direction z
// turns every ray around; POV numbers each strip's faces with the image's
// column, so the right half reads its mesh a strip further on (kept).
// Reference: povray +Icamera_mesh_side_by_side.pov +Ocamera_mesh_side_by_side.png +FN +W160 +H120 -A -D -V +WT2 -GA
#include "camera_world.inc"
#include "camera_mesh_grid.inc"
#declare Eye = Pixel_Mesh(80, 120, 0, 120, true)
camera {
  mesh_camera { 1 2
    mesh { Eye rotate <10, 8, 0> translate <-0.4, 2, -5> }
    mesh { Eye rotate <10, 8, 0> translate <0.4, 2, -5> }
  }
  direction <0, 0, -1>
}
