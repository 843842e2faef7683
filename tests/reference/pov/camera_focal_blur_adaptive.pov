// Focal blur with a least and a most sample count and POV's confidence
// test, on a fisheye (every projection takes the lens).
#include "camera_world.inc"
camera { fisheye location <0, 2, -2> right x * 4 / 3 angle 150 look_at <0, 1.5, 4>
         aperture 0.6 blur_samples 8, 60 confidence 0.95 variance 1 / 2000 focal_point <0, 1, 4> }
