// mesh_camera distribution type 0: pixel i's ray leaves face i's centroid
// along its normal, moved 0.5 along it (location z), the mesh's transforms
// (a non-uniform scale among them) applied to the ray as to the mesh. The
// mesh has no faces for the bottom rows: those pixels are black.
// Reference: povray +Icamera_mesh_per_pixel.pov +Ocamera_mesh_per_pixel.png +FN +W160 +H120 -A -D -V +WT2 -GA
#include "camera_world.inc"
#include "camera_mesh_grid.inc"
#declare Grid = Pixel_Mesh(160, 120, 0, 108, false)
camera {
  mesh_camera { 1 0 mesh { Grid scale <1, 1.4, 1> rotate <15, -20, 0> translate <0.5, 2, -4> } }
  location <0, 0, 0.5>
}
