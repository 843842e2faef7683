// Participating media (docs/scene-language.md, "Media"): a glowing ball of
// emitting medium with a density falling off from its centre, a glass
// sphere holding an absorbing medium, and a light beam in a faint
// scattering atmosphere. whitted renders POV-Ray's picture; path the same
// media physically:
//     lancer render scenes/media.pov -o media.png
//     lancer render scenes/media.pov -i path --spp 64 -o media_path.png
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 1, 0> angle 55 }
light_source { <2, 6, -2> color rgb 1.2 spotlight point_at <0, 0, 0> radius 15 falloff 25 }
background { rgb <0.02, 0.02, 0.05> }
media { scattering { 1, 0.02 } }
plane { y, 0 pigment { rgb 0.6 } }
sphere { 0, 1
  pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { media { emission <1.2, 0.6, 0.2> density { spherical color_map { [0 rgb 0] [1 rgb 1] } } } }
  hollow
  translate <-1.5, 1.2, 0>  // after the interior: the density moves with the ball
}
sphere { <1.4, 1, 0>, 1
  pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 phong 0.5 }
  interior { ior 1.4 media { absorption <0.1, 0.5, 0.9> } }
  hollow
}
