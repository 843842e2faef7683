// The camera inside a solid (not hollow) sphere used as a sky: POV-Ray
// draws no fog, atmosphere or rainbow along a ray that runs inside a solid
// object, and a camera ray starts inside every object that contains the
// camera. The second sphere contains the camera too, hollow: it alone
// would let the fog through.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1, 0> }
light_source { <-5, 10, -5> color rgb 1 }
sphere { 0, 100 pigment { rgb <0.3, 0.5, 0.9> } finish { ambient 1 diffuse 0 } }
sphere { <0, 0, -5>, 3 pigment { rgbt 1 } hollow }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 } }
sphere { <0, 1, 3>, 1 pigment { rgb <1, 0.3, 0.2> } }
fog { distance 5 color rgb <0.8, 0.8, 0.8> }
media { absorption 0.2 }
