// omnimax without an angle (it has none), a wide image: black outside the
// dome's circle and below 45 degrees under its axis.
#include "camera_world.inc"
camera { omnimax location <0, 2, 0> right x * 4 / 3 look_at <0, 3, 4> }
