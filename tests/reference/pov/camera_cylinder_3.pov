// Vertical cylinder from a vertical line of |up| = 6: 300 degrees around.
#include "camera_world.inc"
camera { cylinder 3 location <0, 3, 0> up y * 6 angle 300 look_at <1, 3, 4> }
