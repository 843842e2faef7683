// POV's finish terms side by side: phong, specular, metallic, brilliance,
// albedo, reflection with metallic, exponent and fresnel, conserve_energy.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 4, -9> look_at <0, 0.6, 0> angle 55 }
light_source { <-4, 6, -5> color rgb 1 }
light_source { <5, 3, -2> color rgb 0.4 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.3 scale 1.5 } finish { diffuse 0.7 } }
plane { z, 6 pigment { color rgb <0.4, 0.5, 0.7> } }
#declare Red = pigment { color rgb <0.8, 0.2, 0.1> };
sphere { <-3.3, 0.7, 1>, 0.7 pigment { Red } finish { phong 1 phong_size 10 } }
sphere { <-1.65, 0.7, 1>, 0.7 pigment { Red } finish { specular 0.8 roughness 0.1 metallic } }
sphere { <0, 0.7, 1>, 0.7 pigment { Red } finish { diffuse albedo 0.7 brilliance 3 phong albedo 0.3 phong_size 60 } }
sphere { <1.65, 0.7, 1>, 0.7 pigment { color rgb <0.9, 0.7, 0.2> } finish { diffuse 0.2 reflection { 0.7 metallic 1 } } }
sphere { <3.3, 0.7, 1>, 0.7 pigment { color rgb 0.9 } finish { diffuse 0.3 reflection { 0.1, 0.9 falloff 3 exponent 0.7 } } }
sphere { <-1.6, 0.6, -1.5>, 0.6 pigment { color rgbf <0.9, 1, 0.9, 0.9> } finish { diffuse 0.1 reflection { 0.5 } conserve_energy }
         interior { ior 1.5 } }
sphere { <1.6, 0.6, -1.5>, 0.6 pigment { color rgbt <1, 1, 1, 0.8> } finish { diffuse 0.1 reflection { 0, 1 fresnel on } }
         interior { ior 1.33 } }
