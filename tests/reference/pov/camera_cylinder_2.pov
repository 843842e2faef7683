// Horizontal cylinder from one point: 150 degrees high, |right| 2 across.
#include "camera_world.inc"
camera { cylinder 2 location <0, 2, -1> right x * 2 angle 150 look_at <0, 2, 5> }
