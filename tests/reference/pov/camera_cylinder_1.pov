// Vertical cylinder from one point: 240 degrees around, |up| = 1.5 high.
#include "camera_world.inc"
camera { cylinder 1 location <0, 2, 0> up y * 1.5 angle 240 look_at <0, 2.5, 5> }
