#include "camera_world.inc"
camera { panoramic location <0, 2, 0> right x * 4 / 3 angle 120 look_at <1, 2, 4> }
