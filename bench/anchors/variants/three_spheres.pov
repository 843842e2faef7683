// Variant anchor of bench/pov_anchors.sh (FOLDER bench/anchors/variants): three
// spheres with phong and specular highlights on a checker plane, two point
// lights, hard shadows (lancer -i shadow; POV-Ray without anti-aliasing).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.7, 0> angle 45 }
light_source { <5, 9, -5> color rgb 0.8 }
light_source { <-6, 6, -3> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.3 scale 0.75 } finish { diffuse 0.8 ambient 0.1 } }
sphere { <-1.6, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 phong_size 40 } }
sphere { <0, 0.9, 0.6>, 0.9 pigment { rgb <0.2, 0.8, 0.3> } finish { specular 0.5 roughness 0.02 } }
sphere { <1.6, 0.7, 0>, 0.7 pigment { rgb <0.2, 0.3, 0.9> } finish { phong 0.8 } }
