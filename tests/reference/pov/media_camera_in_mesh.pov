// The camera inside a closed mesh: with inside_vector the mesh has an
// inside (POV's Mesh::Inside), so a hollow one's media fill the view; the
// mesh around it without inside_vector has none, so fog lies everywhere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -1> look_at <0, 1, 3> angle 70 }
light_source { <2, 5, -3> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
fog { distance 8 color rgb <0.7, 0.7, 0.6> }
#macro BoxMesh(A, B)
  triangle { <A.x, A.y, A.z>, <B.x, A.y, A.z>, <B.x, B.y, A.z> } triangle { <A.x, A.y, A.z>, <B.x, B.y, A.z>, <A.x, B.y, A.z> }
  triangle { <A.x, A.y, B.z>, <B.x, A.y, B.z>, <B.x, B.y, B.z> } triangle { <A.x, A.y, B.z>, <B.x, B.y, B.z>, <A.x, B.y, B.z> }
  triangle { <A.x, A.y, A.z>, <A.x, B.y, A.z>, <A.x, B.y, B.z> } triangle { <A.x, A.y, A.z>, <A.x, B.y, B.z>, <A.x, A.y, B.z> }
  triangle { <B.x, A.y, A.z>, <B.x, B.y, A.z>, <B.x, B.y, B.z> } triangle { <B.x, A.y, A.z>, <B.x, B.y, B.z>, <B.x, A.y, B.z> }
  triangle { <A.x, A.y, A.z>, <B.x, A.y, A.z>, <B.x, A.y, B.z> } triangle { <A.x, A.y, A.z>, <B.x, A.y, B.z>, <A.x, A.y, B.z> }
  triangle { <A.x, B.y, A.z>, <B.x, B.y, A.z>, <B.x, B.y, B.z> } triangle { <A.x, B.y, A.z>, <B.x, B.y, B.z>, <A.x, B.y, B.z> }
#end
// A clear, hollow box of glowing media around the camera.
mesh { BoxMesh(<-1.5, 0.2, -2>, <1.5, 2.5, 1.5>) inside_vector y
  pigment { rgbt 1 } hollow interior { media { emission <0.15, 0.05, 0.02> } } }
// A room without inside_vector: no inside, so the camera is in the open.
mesh { BoxMesh(<-4, 0, -4>, <4, 4, 12>) pigment { rgb <0.8, 0.75, 0.7> } }
sphere { <0.5, 0.8, 6>, 0.8 pigment { rgb <0.9, 0.3, 0.2> } }
