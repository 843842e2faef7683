// normal { } on a camera bends every ray as a surface normal, the pattern
// read at the ray's image point (x0, y0, 0): here waves across the image.
#include "camera_world.inc"
camera { location <0, 2.5, -3> right x * 4 / 3 angle 70 look_at <0, 1.5, 4>
         normal { waves 0.6 scale 0.08 } }
