#include "camera_world.inc"
camera { ultra_wide_angle location <0.5, 2, -1> right x * 4 / 3 angle 200 look_at <0, 2.5, 3> }
