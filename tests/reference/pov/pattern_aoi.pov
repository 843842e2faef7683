// The aoi pattern: the angle between the surface's outward normal and the
// ray that hit it, over pi. A wide perspective view, so the angle changes
// with the ray across a flat floor as well as over the balls' curvature.
// (The horizon is out of view: POV-Ray does not see a plane past 1e7,
// lancer does.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -2.6> look_at <0, 0, 0.6> angle 70 }
#declare AoiMap = color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [0.75 rgb <1, 1, 0>] [1 rgb <0, 0, 1>] };
plane { y, 0 pigment { aoi color_map { AoiMap } } finish { ambient 1 diffuse 0 } }
sphere { <-0.8, 0.6, 0.5>, 0.6 pigment { aoi color_map { AoiMap } } finish { ambient 1 diffuse 0 } }
sphere { <0.9, 0.5, 0.3>, 0.5 pigment { aoi color_map { AoiMap } } finish { ambient 1 diffuse 0 } scale <1, 1.5, 1> }
