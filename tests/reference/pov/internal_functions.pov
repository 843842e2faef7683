// POV-Ray's values of every internal function functions.inc declares, on
// a few points with representative parameters, for
// parser/src/internal_functions_test.cpp. Made with
//   povray +Iinternal_functions.pov -D -V +W1 +H1 -GA -GF
// in this folder (POV writes internal_functions.txt; the one-pixel image it
// renders is not kept). Each line: number, parameter count, x, y, z, the
// parameters, the value (15 decimals: str() writes fixed point).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1 }
#fopen Table "internal_functions.txt" write
#declare Points = array[14] {
  <-0.765, 0.3874, -0.3971>,
  <-0.7249, -0.0252, -0.0143>,
  <-0.0485, -0.1, -0.5651>,
  <-0.5909, 0.4605, -0.4213>,
  <0.4196, 0.6892, 0.8783>,
  <1.0657, -0.6371, -0.6302>,
  <0.5636, 0.1813, -0.7155>,
  <0.4263, 0.8958, 0.8059>,
  <-0.6814, -0.4825, -1.184>,
  <1.1416, -0.6709, 0.5451>,
  <0, 0.3, 0>,
  <0, 0, 0>,
  <2.7, -1.9, 3.3>,
  <0.35, 0.1, -0.05>
}
#macro S(V) str(V, 0, 15) #end
#macro Row(N, X, Y, Z, Params, V)
  #write(Table, N, " ", dimension_size(Params, 1) - 1, " ", S(X), " ", S(Y), " ", S(Z))
  #for (I, 1, dimension_size(Params, 1) - 1) #write(Table, " ", S(Params[I])) #end
  #write(Table, " ", S(V), "\n")
#end
#for (K, 0, dimension_size(Points, 1) - 1)
  #local X = Points[K].x; #local Y = Points[K].y; #local Z = Points[K].z;
  Row(0, X, Y, Z, array[6] {0, 1, 10, 0, 0, 0}, f_algbr_cyl1(X, Y, Z, 1, 10, 0, 0, 0))
  Row(0, X, Y, Z, array[6] {0, 1, 10, 1, 0.5, 30}, f_algbr_cyl1(X, Y, Z, 1, 10, 1, 0.5, 30))
  Row(1, X, Y, Z, array[6] {0, 1, 10, 0, 0, 0}, f_algbr_cyl2(X, Y, Z, 1, 10, 0, 0, 0))
  Row(1, X, Y, Z, array[6] {0, 1, 10, 1, 0.5, 30}, f_algbr_cyl2(X, Y, Z, 1, 10, 1, 0.5, 30))
  Row(2, X, Y, Z, array[6] {0, 1, 10, 0, 0, 0}, f_algbr_cyl3(X, Y, Z, 1, 10, 0, 0, 0))
  Row(2, X, Y, Z, array[6] {0, 1, 10, 1, 0.5, 30}, f_algbr_cyl3(X, Y, Z, 1, 10, 1, 0.5, 30))
  Row(3, X, Y, Z, array[6] {0, 1, 10, 0, 0, 0}, f_algbr_cyl4(X, Y, Z, 1, 10, 0, 0, 0))
  Row(3, X, Y, Z, array[6] {0, 2, 3, 1, 0.5, 0}, f_algbr_cyl4(X, Y, Z, 2, 3, 1, 0.5, 0))
  Row(4, X, Y, Z, array[3] {0, 1, 1}, f_bicorn(X, Y, Z, 1, 1))
  Row(5, X, Y, Z, array[3] {0, 1, 3}, f_bifolia(X, Y, Z, 1, 3))
  Row(6, X, Y, Z, array[6] {0, 0.6, 1, 1.2, 1, 0.9}, f_blob(X, Y, Z, 0.6, 1, 1.2, 1, 0.9))
  Row(7, X, Y, Z, array[5] {0, 1.5, 2, 1, 0.5}, f_blob2(X, Y, Z, 1.5, 2, 1, 0.5))
  Row(8, X, Y, Z, array[3] {0, 1, 1}, f_boy_surface(X, Y, Z, 1, 1))
  Row(9, X, Y, Z, array[2] {0, 1}, f_comma(X, Y, Z, 1))
  Row(10, X, Y, Z, array[5] {0, 0.5, 2, 1, 0.5}, f_cross_ellipsoids(X, Y, Z, 0.5, 2, 1, 0.5))
  Row(11, X, Y, Z, array[2] {0, 1}, f_crossed_trough(X, Y, Z, 1))
  Row(12, X, Y, Z, array[2] {0, 1}, f_cubic_saddle(X, Y, Z, 1))
  Row(13, X, Y, Z, array[2] {0, 1}, f_cushion(X, Y, Z, 1))
  Row(14, X, Y, Z, array[2] {0, 1}, f_devils_curve(X, Y, Z, 1))
  Row(15, X, Y, Z, array[7] {0, 1, 0.6, 0.5, 0, 0, 0}, f_devils_curve_2d(X, Y, Z, 1, 0.6, 0.5, 0, 0, 0))
  Row(15, X, Y, Z, array[7] {0, 1, 0.6, 0.5, 1, 0.5, 20}, f_devils_curve_2d(X, Y, Z, 1, 0.6, 0.5, 1, 0.5, 20))
  Row(16, X, Y, Z, array[7] {0, 1, 0.8, 0.5, 0.1, 0.2, 1.2}, f_dupin_cyclid(X, Y, Z, 1, 0.8, 0.5, 0.1, 0.2, 1.2))
  Row(17, X, Y, Z, array[4] {0, 1, 2, 0.5}, f_ellipsoid(X, Y, Z, 1, 2, 0.5))
  Row(18, X, Y, Z, array[2] {0, 1}, f_enneper(X, Y, Z, 1))
  Row(19, X, Y, Z, array[5] {0, 0.5, 2, 1, 0.5}, f_flange_cover(X, Y, Z, 0.5, 2, 1, 0.5))
  Row(20, X, Y, Z, array[4] {0, 1, 1, 1}, f_folium_surface(X, Y, Z, 1, 1, 1))
  Row(21, X, Y, Z, array[7] {0, 1, 1, 1, 0, 0, 0}, f_folium_surface_2d(X, Y, Z, 1, 1, 1, 0, 0, 0))
  Row(21, X, Y, Z, array[7] {0, 1, 1, 1, 1, 0.3, 15}, f_folium_surface_2d(X, Y, Z, 1, 1, 1, 1, 0.3, 15))
  Row(22, X, Y, Z, array[2] {0, 1}, f_glob(X, Y, Z, 1))
  Row(23, X, Y, Z, array[2] {0, 1}, f_heart(X, Y, Z, 1))
  Row(24, X, Y, Z, array[11] {0, 1, 6, 1, 0.1, 0.2, -0.3, 1, 3, 0.2, 0.5}, f_helical_torus(X, Y, Z, 1, 6, 1, 0.1, 0.2, -0.3, 1, 3, 0.2, 0.5))
  Row(24, X, Y, Z, array[11] {0, 0.8, 4, 0, 0.2, 0.1, 0.1, 0.5, 2, 0.3, 0}, f_helical_torus(X, Y, Z, 0.8, 4, 0, 0.2, 0.1, 0.1, 0.5, 2, 0.3, 0))
  Row(25, X, Y, Z, array[8] {0, 2, 5, 0.1, 0.5, 1, 1, 0}, f_helix1(X, Y, Z, 2, 5, 0.1, 0.5, 1, 1, 0))
  Row(25, X, Y, Z, array[8] {0, 3, 4, 0.15, 0.6, 1.5, 0.5, 45}, f_helix1(X, Y, Z, 3, 4, 0.15, 0.6, 1.5, 0.5, 45))
  Row(25, X, Y, Z, array[8] {0, 1, 3, 0.1, 0.4, 1, 0, 0}, f_helix1(X, Y, Z, 1, 3, 0.1, 0.4, 1, 0, 0))
  Row(26, X, Y, Z, array[8] {0, 0, 3, 0.3, 0.5, 0, 1, 0}, f_helix2(X, Y, Z, 0, 3, 0.3, 0.5, 0, 1, 0))
  Row(26, X, Y, Z, array[8] {0, 0, 3, 0.3, 0.5, 0, 0.5, 0}, f_helix2(X, Y, Z, 0, 3, 0.3, 0.5, 0, 0.5, 0))
  Row(26, X, Y, Z, array[8] {0, 0, 3, 0.3, 0.5, 0, 0, 0}, f_helix2(X, Y, Z, 0, 3, 0.3, 0.5, 0, 0, 0))
  Row(27, X, Y, Z, array[2] {0, 0}, f_hex_x(X, Y, Z, 0))
  Row(28, X, Y, Z, array[2] {0, 0}, f_hex_y(X, Y, Z, 0))
  Row(29, X, Y, Z, array[7] {0, 0.5, 2, 6, 0.1, 1, 2}, f_hetero_mf(X, Y, Z, 0.5, 2, 6, 0.1, 1, 2))
  Row(29, X, Y, Z, array[7] {0, 0.7, 2.5, 4.5, 0.3, 2, 1}, f_hetero_mf(X, Y, Z, 0.7, 2.5, 4.5, 0.3, 2, 1))
  Row(29, X, Y, Z, array[7] {0, 0.5, 2, 3, 0, 0, 3}, f_hetero_mf(X, Y, Z, 0.5, 2, 3, 0, 0, 3))
  Row(30, X, Y, Z, array[2] {0, 1}, f_hunt_surface(X, Y, Z, 1))
  Row(31, X, Y, Z, array[4] {0, 1, 0.8, 0.3}, f_hyperbolic_torus(X, Y, Z, 1, 0.8, 0.3))
  Row(32, X, Y, Z, array[5] {0, 0.5, 2, 1, 0.5}, f_isect_ellipsoids(X, Y, Z, 0.5, 2, 1, 0.5))
  Row(33, X, Y, Z, array[4] {0, 1, 0.5, 1}, f_kampyle_of_eudoxus(X, Y, Z, 1, 0.5, 1))
  Row(34, X, Y, Z, array[7] {0, 1, 0.5, 1, 0, 0, 0}, f_kampyle_of_eudoxus_2d(X, Y, Z, 1, 0.5, 1, 0, 0, 0))
  Row(34, X, Y, Z, array[7] {0, 1, 0.5, 1, 1, 0.3, 10}, f_kampyle_of_eudoxus_2d(X, Y, Z, 1, 0.5, 1, 1, 0.3, 10))
  Row(35, X, Y, Z, array[2] {0, 1}, f_klein_bottle(X, Y, Z, 1))
  Row(36, X, Y, Z, array[2] {0, 1}, f_kummer_surface_v1(X, Y, Z, 1))
  Row(37, X, Y, Z, array[5] {0, 1, -0.5, -1, 0.3}, f_kummer_surface_v2(X, Y, Z, 1, -0.5, -1, 0.3))
  Row(38, X, Y, Z, array[2] {0, 1}, f_lemniscate_of_gerono(X, Y, Z, 1))
  Row(39, X, Y, Z, array[7] {0, 1, 0.8, 1, 0, 0, 0}, f_lemniscate_of_gerono_2d(X, Y, Z, 1, 0.8, 1, 0, 0, 0))
  Row(39, X, Y, Z, array[7] {0, 1, 0.8, 1, 1, 0.2, 25}, f_lemniscate_of_gerono_2d(X, Y, Z, 1, 0.8, 1, 1, 0.2, 25))
  Row(40, X, Y, Z, array[6] {0, 0.5, 0.5, 1, 0.2, 1}, f_mesh1(X, Y, Z, 0.5, 0.5, 1, 0.2, 1))
  Row(41, X, Y, Z, array[2] {0, 1}, f_mitre(X, Y, Z, 1))
  Row(42, X, Y, Z, array[2] {0, 1}, f_nodal_cubic(X, Y, Z, 1))
  Row(43, X, Y, Z, array[2] {0, 1}, f_odd(X, Y, Z, 1))
  Row(44, X, Y, Z, array[5] {0, 1, 0.6, 0.3, 4}, f_ovals_of_cassini(X, Y, Z, 1, 0.6, 0.3, 4))
  Row(45, X, Y, Z, array[2] {0, 1}, f_paraboloid(X, Y, Z, 1))
  Row(46, X, Y, Z, array[4] {0, 1, 0.8, 0.3}, f_parabolic_torus(X, Y, Z, 1, 0.8, 0.3))
  Row(47, X, Y, Z, array[1] {0}, f_ph(X, Y, Z))
  Row(48, X, Y, Z, array[2] {0, 1}, f_pillow(X, Y, Z, 1))
  Row(49, X, Y, Z, array[2] {0, 1}, f_piriform(X, Y, Z, 1))
  Row(50, X, Y, Z, array[8] {0, 1, 1, -1, 0.8, 0, 0, 0}, f_piriform_2d(X, Y, Z, 1, 1, -1, 0.8, 0, 0, 0))
  Row(50, X, Y, Z, array[8] {0, 1, 1, -1, 0.8, 1, 0.4, 30}, f_piriform_2d(X, Y, Z, 1, 1, -1, 0.8, 1, 0.4, 30))
  Row(51, X, Y, Z, array[6] {0, 0.5, 0.2, -0.3, 0.1, -0.05}, f_poly4(X, Y, Z, 0.5, 0.2, -0.3, 0.1, -0.05))
  Row(52, X, Y, Z, array[7] {0, 5, 0.3, 0.1, 0.2, 0, 0}, f_polytubes(X, Y, Z, 5, 0.3, 0.1, 0.2, 0, 0))
  Row(52, X, Y, Z, array[7] {0, 3, 0.5, 0, -0.1, 0.05, 0.01}, f_polytubes(X, Y, Z, 3, 0.5, 0, -0.1, 0.05, 0.01))
  Row(53, X, Y, Z, array[2] {0, 0}, f_quantum(X, Y, Z, 0))
  Row(54, X, Y, Z, array[2] {0, 1}, f_quartic_paraboloid(X, Y, Z, 1))
  Row(55, X, Y, Z, array[2] {0, 1}, f_quartic_saddle(X, Y, Z, 1))
  Row(56, X, Y, Z, array[4] {0, 1, 0.6, 0.4}, f_quartic_cylinder(X, Y, Z, 1, 0.6, 0.4))
  Row(57, X, Y, Z, array[1] {0}, f_r(X, Y, Z))
  Row(58, X, Y, Z, array[7] {0, 2, 4.5, 0.6, 0.3, 0.7, 2}, f_ridge(X, Y, Z, 2, 4.5, 0.6, 0.3, 0.7, 2))
  Row(58, X, Y, Z, array[7] {0, 2.2, 3, 0.5, 0.6, 0.4, 3}, f_ridge(X, Y, Z, 2.2, 3, 0.5, 0.6, 0.4, 3))
  Row(58, X, Y, Z, array[7] {0, 2, 5, 0.5, 0.5, 0.5, 1}, f_ridge(X, Y, Z, 2, 5, 0.5, 0.5, 0.5, 1))
  Row(59, X, Y, Z, array[7] {0, 0.5, 2, 6, 1, 2, 2}, f_ridged_mf(X, Y, Z, 0.5, 2, 6, 1, 2, 2))
  Row(59, X, Y, Z, array[7] {0, 0.5, 2, 6, 0.9, 1.5, 1}, f_ridged_mf(X, Y, Z, 0.5, 2, 6, 0.9, 1.5, 1))
  Row(59, X, Y, Z, array[7] {0, 0.5, 2, 4.5, 1.1, 2, 3}, f_ridged_mf(X, Y, Z, 0.5, 2, 4.5, 1.1, 2, 3))
  Row(60, X, Y, Z, array[5] {0, 0.1, 1, 0.8, 0.6}, f_rounded_box(X, Y, Z, 0.1, 1, 0.8, 0.6))
  Row(61, X, Y, Z, array[2] {0, 1}, f_sphere(X, Y, Z, 1))
  Row(62, X, Y, Z, array[6] {0, 0.02, 1, 1, 0.5, 0.5}, f_spikes(X, Y, Z, 0.02, 1, 1, 0.5, 0.5))
  Row(63, X, Y, Z, array[5] {0, 1, 3, 3, 0.5}, f_spikes_2d(X, Y, Z, 1, 3, 3, 0.5))
  Row(64, X, Y, Z, array[7] {0, 0.3, 0.1, 1, 0, 0, 1}, f_spiral(X, Y, Z, 0.3, 0.1, 1, 0, 0, 1))
  Row(64, X, Y, Z, array[7] {0, 0.3, 0.1, 1, 0, 0, 0}, f_spiral(X, Y, Z, 0.3, 0.1, 1, 0, 0, 0))
  Row(64, X, Y, Z, array[7] {0, 0.3, 0.1, 1, 0, 0, 0.5}, f_spiral(X, Y, Z, 0.3, 0.1, 1, 0, 0, 0.5))
  Row(65, X, Y, Z, array[2] {0, 1}, f_steiners_roman(X, Y, Z, 1))
  Row(66, X, Y, Z, array[5] {0, 1, 1, 0, 1}, f_strophoid(X, Y, Z, 1, 1, 0, 1))
  Row(67, X, Y, Z, array[8] {0, 1, 1, 0, 1, 0, 0, 0}, f_strophoid_2d(X, Y, Z, 1, 1, 0, 1, 0, 0, 0))
  Row(67, X, Y, Z, array[8] {0, 1, 1, 0.2, 1, 1, 0.3, 15}, f_strophoid_2d(X, Y, Z, 1, 1, 0.2, 1, 1, 0.3, 15))
  Row(68, X, Y, Z, array[3] {0, 0.5, 0.8}, f_superellipsoid(X, Y, Z, 0.5, 0.8))
  Row(69, X, Y, Z, array[1] {0}, f_th(X, Y, Z))
  Row(70, X, Y, Z, array[3] {0, 0.8, 0.2}, f_torus(X, Y, Z, 0.8, 0.2))
  Row(71, X, Y, Z, array[4] {0, 1, 0.8, 0.2}, f_torus2(X, Y, Z, 1, 0.8, 0.2))
  Row(72, X, Y, Z, array[2] {0, 1}, f_torus_gumdrop(X, Y, Z, 1))
  Row(73, X, Y, Z, array[2] {0, 1}, f_umbrella(X, Y, Z, 1))
  Row(74, X, Y, Z, array[3] {0, 1, 0.4}, f_witch_of_agnesi(X, Y, Z, 1, 0.4))
  Row(75, X, Y, Z, array[7] {0, 1, 0.4, 0.5, 0, 0, 0}, f_witch_of_agnesi_2d(X, Y, Z, 1, 0.4, 0.5, 0, 0, 0))
  Row(75, X, Y, Z, array[7] {0, 1, 0.4, 0.5, 1, 0.2, -20}, f_witch_of_agnesi_2d(X, Y, Z, 1, 0.4, 0.5, 1, 0.2, -20))
  Row(76, X, Y, Z, array[1] {0}, f_noise3d(X, Y, Z))
  Row(78, X, Y, Z, array[2] {0, 0}, f_noise_generator(X, Y, Z, 0))
  Row(78, X, Y, Z, array[2] {0, 1}, f_noise_generator(X, Y, Z, 1))
  Row(78, X, Y, Z, array[2] {0, 2}, f_noise_generator(X, Y, Z, 2))
  Row(78, X, Y, Z, array[2] {0, 3}, f_noise_generator(X, Y, Z, 3))
#end
#fclose Table

camera { location <0, 0, -2> look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
light_source { <1, 1, -1>, rgb 1 }
