// Layered textures lit as POV-Ray lights them: each layer with its own
// pigment, finish and normal, its own light dimmed by the layers above,
// its mirror undimmed; what passes every layer refracted through the top
// layer's normal; shadows dimmed by every layer. stones.inc's T_Stone21
// (a granite under layers with their own phong), a bumpy mirror under a
// striped matte layer, a glass under a tinted layer, and a layer with
// conserve_energy.
// Reference: povray +Ilayered_finishes.pov +Olayered_finishes.png +FN +W160 +H120 -A -D -V +WT2 -GA
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "stones.inc"
camera { location <0, 3.5, -7.5> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.35 }
plane { y, 0 pigment { checker rgb <0.9, 0.85, 0.7> rgb <0.4, 0.5, 0.6> scale 1.2 } finish { diffuse 0.8 } }
sphere { <-2.2, 1, 0>, 1 texture { T_Stone21 } }
sphere { <0, 1, 0.8>, 1
  texture { pigment { rgb <0.8, 0.2, 0.1> } normal { bumps 0.8 scale 0.2 } finish { diffuse 0.3 reflection 0.5 specular 0.6 roughness 0.02 } }
  texture { pigment { gradient y color_map { [0.5 rgbt <0.2, 0.7, 0.3, 0>] [0.5 rgbt <1, 1, 1, 1>] } scale 0.3 } finish { phong 0.8 phong_size 10 diffuse 0.7 } }
}
sphere { <2.2, 1, 0>, 1
  texture { pigment { rgbf <1, 1, 1, 0.9> } finish { phong 0.9 reflection 0.1 } }
  texture { pigment { bozo color_map { [0.4 rgbf <0.3, 0.6, 1, 0.8>] [0.6 rgbt <1, 1, 1, 1>] } scale 0.4 } normal { dents 0.6 scale 0.3 } finish { specular 0.7 } }
  interior { ior 1.5 }
}
box { <-0.6, 0, -2.2>, <0.6, 1.2, -1.2>
  texture { pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.5 } }
  texture { pigment { rgbf <0.2, 0.4, 1, 0.5> } finish { reflection { 0.6 } conserve_energy diffuse 0.5 } }
}
