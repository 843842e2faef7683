// One angle: the vertical span defaults to half of it.
#include "camera_world.inc"
camera { spherical location <0, 2, -1> angle 150 look_at <1, 2.5, 4> }
