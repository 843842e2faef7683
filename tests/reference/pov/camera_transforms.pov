// Transforms inside the camera come after look_at, in their order; a left-
// handed right (right -x with up y) mirrors the picture, as POV-Ray does.
#include "camera_world.inc"
camera { perspective location <0, 4, -2> right -x * 4 / 3 up y angle 70 look_at <0, 0, 4>
         rotate y * 30 translate <0.5, 0.5, 0> matrix <1, 0, 0, 0.1, 1, 0, 0, 0, 1, 0, 0, 0> }
