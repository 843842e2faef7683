// Focal blur with POV's 37-point hexagonal lens grid: the ball at the focal
// point stays sharp, the pillars in front and behind blur.
#include "camera_world.inc"
camera { location <0, 2, -4> right x * 4 / 3 angle 60 look_at <0, 1, 4>
         aperture 1.2 blur_samples 37 focal_point <0, 1, 4> }
