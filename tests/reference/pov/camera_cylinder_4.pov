// Horizontal cylinder from a horizontal line of |right| = 10: 200 degrees high.
#include "camera_world.inc"
camera { cylinder 4 location <0, 4, -2> right x * 10 angle 200 look_at <0, 4, 5> }
