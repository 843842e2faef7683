// mesh_camera distribution type 1: the meshes' faces in a row, pixel i
// taking face i of them all; two meshes looking two ways. POV adds
// ray_number times the number of faces to the face index, so of the 3
// rays per pixel only the first finds a face, and the pixel is its colour
// (not a third of it). The one face of a declared mesh2 between them moves
// the second mesh's faces on by one pixel. (POV-Ray 3.7 reads a mesh2
// written out inside a mesh_camera as a mesh; a declared one is fine.)
// Reference: povray +Icamera_mesh_summed.pov +Ocamera_mesh_summed.png +FN +W160 +H120 -A -D -V +WT2 -GA
#include "camera_world.inc"
#include "camera_mesh_grid.inc"
#declare Upper = Pixel_Mesh(160, 120, 0, 60, false)
#declare Lower = Pixel_Mesh(160, 120, 60, 120, false)
#declare One_Face = mesh2 { vertex_vectors { 3, <-1, 0, 0>, <0, 1, 0>, <1, 0, 0> } face_indices { 1, <0, 1, 2> } }
camera {
  mesh_camera { 3 1
    mesh { Upper rotate x * 12 translate <0, 2, -5> }
    mesh2 { One_Face translate <0, 1, -5> }
    mesh { Lower rotate <12, 90, 0> translate <-5, 1.5, 0> }
  }
}
