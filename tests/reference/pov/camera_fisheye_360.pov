// A 360-degree fisheye with POV's default right (1.33) and a taller up:
// the circle becomes an ellipse of the image, and the edge looks backwards.
#include "camera_world.inc"
camera { fisheye location <0, 2, 0> up y * 1.2 angle 360 look_at <1, 2, 5> }
