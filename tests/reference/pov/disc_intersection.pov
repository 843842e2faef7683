// A glass paperweight as advanced/desk.pov makes it: a ball intersected
// with a disc facing down. A disc's inside is POV-Ray's half-space behind
// it, so the object is the dome above the disc; but POV bounds the
// intersection by the overlap of its parts' boxes, the disc's a slab 0.001
// thick, and a ray that never crosses that slab misses the object: the far
// top of the dome is not drawn. Rays totally reflected off the flat bottom
// start inside the slab and find the dome from inside.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 8, -30> look_at <0, 0, 0> angle 40 }
light_source { <10, 30, -20> rgb 1 }
plane { y, -0.01 pigment { checker rgb 1 rgb <0.3, 0.5, 0.2> scale 2 } }
intersection {
   sphere { <0.0, -5.0, 0.0>, 10.0 }
   disc { 0, -y, 10.1 }
   material { texture { pigment {color rgbf <0.8, 1, 0.95, 0.9>} finish { specular 1 roughness 0.001 reflection 0.1 } } interior {ior 1.5} }
}
