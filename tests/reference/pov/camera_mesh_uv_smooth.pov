// mesh_camera distribution type 3 with smooth: each pixel's point, read as
// (u,v), finds the face whose uv triangle holds it; the ray leaves that
// point of the face along the vertex normals interpolated there. The uv
// square's right eighth has no face: black. Only the first mesh counts.
// Reference: povray +Icamera_mesh_uv_smooth.pov +Ocamera_mesh_uv_smooth.png +FN +W160 +H120 -A -D -V +WT2 -GA
#include "camera_world.inc"
#include "camera_mesh_grid.inc"
#declare Lens = Uv_Sphere_Mesh(8, 6, 7, 2.4, 1.8)
camera {
  mesh_camera { 1 3
    mesh { Lens rotate <20, 30, 0> translate <-2, 3, -5> }
    smooth
  }
  location <0, 0, -0.01>
}
