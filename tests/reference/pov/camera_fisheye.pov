// A fisheye of 180 degrees looking up and ahead: outside the inscribed
// circle POV traces no ray and the corners are black (not the background).
#include "camera_world.inc"
camera { fisheye location <0.5, 1.5, -1> right x * 4 / 3 angle 180 look_at <0, 3, 6> }
