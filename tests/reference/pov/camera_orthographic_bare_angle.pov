// orthographic `angle` without a value: POV reads 0 and sizes the view as
// the perspective camera's at the look_at distance, keeping direction.
#include "camera_world.inc"
camera { orthographic location <6, 12, -10> right x * 4 / 3 up y look_at <0, 1, 0> angle }
