// The whole sphere of directions (POV's default spans 360 and 180), seen
// from a tilted sky.
#include "camera_world.inc"
camera { spherical location <0, 2, 0> angle 360, 180 sky <0.2, 1, 0> look_at <-1, 2, 3> }
