#!/bin/sh
# Writes POV-Ray 3.7's own pattern values, the reference of
# render/src/materials/pattern_test.cpp: for each pattern below, povray
# evaluates `function { pattern { ... } }` at fixed pseudo-random points and
# #writes "x y z value" lines (17 significant digits) to
# tests/reference/pov/patterns/<name>.txt. No image is rendered, so the
# values are exact. Needs Debian's povray (3.7.0.10); run from anywhere:
#   scripts/measure-pov-patterns.sh [name ...]   (default: every pattern)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/tests/reference/pov/patterns"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# name | points (box: in [-3,3]^3; plane: x,y in [-2,2], z 0; unit: in
# [-0.1,1.1]^3) | pattern body. density_file reads the small df3 files
# committed beside the values (made once by a script with random voxels:
# 5x4x3 of 8 bits, 3x3x2 of 16 bits, 2x3x4 of 32 bits).
# This povray does not take square, triangular, tiling and pavement in pattern
# functions: a body starting PIGMENT is a pigment whose red channel is the
# block index (or, through a 0..1 grey map, the value in single precision).
patterns() {
cat <<'LIST'
gradient|box|gradient x
gradient_diagonal|box|gradient <1,2,-1> frequency 2 phase 0.3
onion|box|onion
spherical|box|spherical scale 2
cylindrical|box|cylindrical scale 2
boxed|box|boxed scale 2
planar|box|planar scale 2
radial|box|radial
radial_frequency|box|radial frequency 3 phase 0.2
spiral1|box|spiral1 3
spiral2|box|spiral2 2
leopard|box|leopard scale 0.3
marble_plain|box|marble
wood_plain|box|wood
checker|box|checker
hexagon|box|hexagon
brick|box|brick scale 0.5
brick_sized|box|brick brick_size <1,0.5,0.7> mortar 0.1
cubic|box|cubic
square|box|PIGMENT square rgb 0, rgb 1, rgb 2, rgb 3
triangular|box|PIGMENT triangular rgb 0, rgb 1, rgb 2, rgb 3, rgb 4, rgb 5
quilted|box|quilted control0 0.5 control1 0.8
cells|box|cells scale 0.7
crackle|box|crackle
crackle_form|box|crackle form <1,0,0> metric 1 offset 0.1
crackle_metric3|box|crackle form <0.5,0.8,-0.3> metric 3
mandel|plane|mandel 30
mandel3|plane|mandel 30 exponent 3
mandel4|plane|mandel 30 exponent 4
mandel5|plane|mandel 20 exponent 5
mandel_colours|plane|mandel 30 exterior 6, 0.5 interior 1, 2
mandel_types|plane|mandel 40 exterior 3, 0.5 interior 6, 0.5
julia|plane|julia <0.3,0.5>, 30
julia4|plane|julia <0.3,0.5>, 30 exponent 4
magnet1_mandel|plane|magnet 1 mandel 30
magnet1_julia|plane|magnet 1 julia <0.3,0.2>, 30
magnet2_mandel|plane|magnet 2 mandel 30
magnet2_julia|plane|magnet 2 julia <0.3,0.2>, 30 interior 1, 1
wave_sine|box|gradient x sine_wave
wave_triangle|box|gradient x triangle_wave frequency 1.5
wave_scallop|box|gradient x scallop_wave
wave_cubic|box|gradient x cubic_wave
wave_poly|box|gradient x poly_wave 2.5
frequency_negative|box|gradient x frequency -1.5 phase 0.25
warp_repeat|box|gradient x warp { repeat x*1.5 flip x offset <0.2,0.3,0> }
warp_repeat_y|box|gradient <1,1,1> warp { repeat y*0.8 flip <1,1,0> }
warp_black_hole|box|gradient x warp { black_hole <0.5,0,0>, 1.5 strength 1.5 falloff 3 }
warp_black_hole_inverse|box|gradient <1,1,0> warp { black_hole <0,0.5,0>, 2 inverse }
warp_black_hole_repeat|box|gradient x warp { black_hole <0,0,0>, 0.7 repeat <2,2,2> turbulence <0.5,0.4,0.3> strength 0.8 }
warp_cylindrical|box|gradient x warp { cylindrical }
warp_cylindrical_oriented|box|gradient x warp { cylindrical orientation y dist_exp 1 }
warp_spherical|box|onion warp { spherical orientation <1,1,0> dist_exp 0.5 }
warp_toroidal|box|gradient y warp { toroidal major_radius 2 }
warp_planar|box|gradient x warp { planar y, 0.3 }
warp_order_scale_after|box|gradient x warp { repeat x*1 flip x } scale 2
warp_order_scale_before|box|gradient x scale 2 warp { repeat x*1 flip x }
warp_stack|box|gradient x rotate 30*z warp { repeat x*1.5 } translate 0.3 warp { black_hole 0, 1 } scale 1.5
bozo|box|bozo
bozo_generator1|box|bozo noise_generator 1
bozo_generator3|box|bozo noise_generator 3
spotted|box|spotted scale 0.4
bumps|box|bumps
dents|box|dents
granite|box|granite
granite_generator1|box|granite noise_generator 1
agate|box|agate
agate_turb|box|agate agate_turb 0.5 octaves 4 omega 0.6 lambda 2.5
marble|box|marble turbulence 0.5
wood|box|wood turbulence 0.3 octaves 3
wrinkles|box|wrinkles
wrinkles_generator1|box|wrinkles noise_generator 1
crackle_solid|box|crackle solid
ripples|box|ripples frequency 2 phase 0.1
waves|box|waves
waves_scaled|box|waves scale 0.3 frequency 1.5
turbulence_gradient|box|gradient x turbulence 0.6
turbulence_onion|box|onion turbulence <0.3,0.5,0.1> octaves 3 omega 0.7 lambda 3
turbulence_spiral|box|spiral1 2 turbulence 0.4
warp_turbulence|box|gradient x warp { turbulence 0.5 octaves 4 } scale 0.5
tiling1|box|PIGMENT tiling 1 color_map { [0 rgb 0] [1 rgb 1] }
tiling2|box|PIGMENT tiling 2 color_map { [0 rgb 0] [1 rgb 1] }
tiling3|box|PIGMENT tiling 3 color_map { [0 rgb 0] [1 rgb 1] }
tiling4|box|PIGMENT tiling 4 color_map { [0 rgb 0] [1 rgb 1] }
tiling5|box|PIGMENT tiling 5 color_map { [0 rgb 0] [1 rgb 1] }
tiling6|box|PIGMENT tiling 6 color_map { [0 rgb 0] [1 rgb 1] }
tiling7|box|PIGMENT tiling 7 color_map { [0 rgb 0] [1 rgb 1] }
tiling8|box|PIGMENT tiling 8 color_map { [0 rgb 0] [1 rgb 1] }
tiling9|box|PIGMENT tiling 9 color_map { [0 rgb 0] [1 rgb 1] }
tiling10|box|PIGMENT tiling 10 color_map { [0 rgb 0] [1 rgb 1] }
tiling11|box|PIGMENT tiling 11 color_map { [0 rgb 0] [1 rgb 1] }
tiling12|box|PIGMENT tiling 12 color_map { [0 rgb 0] [1 rgb 1] }
tiling13|box|PIGMENT tiling 13 color_map { [0 rgb 0] [1 rgb 1] }
tiling14|box|PIGMENT tiling 14 color_map { [0 rgb 0] [1 rgb 1] }
tiling15|box|PIGMENT tiling 15 color_map { [0 rgb 0] [1 rgb 1] }
tiling16|box|PIGMENT tiling 16 color_map { [0 rgb 0] [1 rgb 1] }
tiling17|box|PIGMENT tiling 17 color_map { [0 rgb 0] [1 rgb 1] }
tiling18|box|PIGMENT tiling 18 color_map { [0 rgb 0] [1 rgb 1] }
tiling19|box|PIGMENT tiling 19 color_map { [0 rgb 0] [1 rgb 1] }
tiling20|box|PIGMENT tiling 20 color_map { [0 rgb 0] [1 rgb 1] }
tiling21|box|PIGMENT tiling 21 color_map { [0 rgb 0] [1 rgb 1] }
tiling22|box|PIGMENT tiling 22 color_map { [0 rgb 0] [1 rgb 1] }
tiling23|box|PIGMENT tiling 23 color_map { [0 rgb 0] [1 rgb 1] }
tiling24|box|PIGMENT tiling 24 color_map { [0 rgb 0] [1 rgb 1] }
tiling25|box|PIGMENT tiling 25 color_map { [0 rgb 0] [1 rgb 1] }
tiling26|box|PIGMENT tiling 26 color_map { [0 rgb 0] [1 rgb 1] }
tiling27|box|PIGMENT tiling 27 color_map { [0 rgb 0] [1 rgb 1] }
tiling25_deep|box|PIGMENT tiling 25 scale 0.04 color_map { [0 rgb 0] [1 rgb 1] }
tiling26_deep|box|PIGMENT tiling 26 scale 0.04 color_map { [0 rgb 0] [1 rgb 1] }
tiling27_deep|box|PIGMENT tiling 27 scale 0.04 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_1|box|PIGMENT pavement number_of_sides 4 number_of_tiles 1 pattern 1 exterior 0 interior 0 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_2|box|PIGMENT pavement number_of_sides 4 number_of_tiles 2 pattern 1 exterior 0 interior 0 form 1 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_3_2|box|PIGMENT pavement number_of_sides 4 number_of_tiles 3 pattern 2 exterior 1 interior 1 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_4_3|box|PIGMENT pavement number_of_sides 4 number_of_tiles 4 pattern 3 exterior 2 interior 2 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_4_5|box|PIGMENT pavement number_of_sides 4 number_of_tiles 4 pattern 5 exterior 2 interior 2 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_5_7|box|PIGMENT pavement number_of_sides 4 number_of_tiles 5 pattern 7 exterior 2 interior 1 form 3 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_5_12|box|PIGMENT pavement number_of_sides 4 number_of_tiles 5 pattern 12 exterior 1 interior 0 form 1 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_6_15|box|PIGMENT pavement number_of_sides 4 number_of_tiles 6 pattern 15 exterior 0 interior 1 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_6_34|box|PIGMENT pavement number_of_sides 4 number_of_tiles 6 pattern 34 exterior 1 interior 2 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement4_6_35|box|PIGMENT pavement number_of_sides 4 number_of_tiles 6 pattern 35 exterior 2 interior 0 form 3 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_1|box|PIGMENT pavement number_of_sides 3 number_of_tiles 1 pattern 1 exterior 0 interior 0 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_2|box|PIGMENT pavement number_of_sides 3 number_of_tiles 2 pattern 1 exterior 1 interior 1 form 1 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_3|box|PIGMENT pavement number_of_sides 3 number_of_tiles 3 pattern 1 exterior 2 interior 2 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_4_3|box|PIGMENT pavement number_of_sides 3 number_of_tiles 4 pattern 3 exterior 1 interior 2 form 1 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_5_4|box|PIGMENT pavement number_of_sides 3 number_of_tiles 5 pattern 4 exterior 2 interior 1 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_6_8|box|PIGMENT pavement number_of_sides 3 number_of_tiles 6 pattern 8 exterior 1 interior 0 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement3_6_12|box|PIGMENT pavement number_of_sides 3 number_of_tiles 6 pattern 12 exterior 2 interior 2 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_1|box|PIGMENT pavement number_of_sides 6 number_of_tiles 1 pattern 1 exterior 0 interior 1 form 1 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_2|box|PIGMENT pavement number_of_sides 6 number_of_tiles 2 pattern 1 exterior 2 interior 0 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_3_2|box|PIGMENT pavement number_of_sides 6 number_of_tiles 3 pattern 2 exterior 1 interior 2 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_4_4|box|PIGMENT pavement number_of_sides 6 number_of_tiles 4 pattern 4 exterior 2 interior 0 form 1 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_4_7|box|PIGMENT pavement number_of_sides 6 number_of_tiles 4 pattern 7 exterior 1 interior 1 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_5_8|box|PIGMENT pavement number_of_sides 6 number_of_tiles 5 pattern 8 exterior 0 interior 2 form 0 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
pavement6_5_22|box|PIGMENT pavement number_of_sides 6 number_of_tiles 5 pattern 22 exterior 2 interior 1 form 2 scale 0.3 color_map { [0 rgb 0] [1 rgb 1] }
tiling_scaled|box|PIGMENT tiling 5 scale 0.4 rotate 20*y color_map { [0 rgb 0] [1 rgb 1] }
density8|unit|density_file df3 "density8.df3" interpolate 0
density8_trilinear|unit|density_file df3 "density8.df3" interpolate 1
density8_tricubic|unit|density_file df3 "density8.df3" interpolate 2
density16_trilinear|unit|density_file df3 "density16.df3" interpolate 1
density16_tricubic|unit|density_file df3 "density16.df3" interpolate 2
density32|unit|density_file df3 "density32.df3"
density32_tricubic|unit|density_file df3 "density32.df3" interpolate 2
LIST
}

# 150 points per pattern, from POV's own rand() so the script alone fixes them.
write_scene() {
    name=$1 points=$2 body=$3
    case $body in
    PIGMENT*)
        declare="#declare F = function { pigment { ${body#PIGMENT } } }"
        value="F(P.x,P.y,P.z).red" ;;
    *)
        declare="#declare F = function { pattern { $body } }"
        value="F(P.x,P.y,P.z)" ;;
    esac
    case $points in
    plane) range="<4,4,0>" low="<-2,-2,0>" ;;
    unit) range="<1.2,1.2,1.2>" low="<-0.1,-0.1,-0.1>" ;;
    *) range="<6,6,6>" low="<-3,-3,-3>" ;;
    esac
    cat >"$work/$name.pov" <<POV
#version 3.7;
global_settings { assumed_gamma 1 }
$declare
#declare S = seed(1234);
#fopen O "$out/$name.txt" write
#write (O, "# povray 3.7 pattern { $(printf '%s' "$body" | sed 's/"/\\"/g') }: x y z value\n")
#declare I = 0;
#while (I < 150)
  #declare P = $low + $range * <rand(S), rand(S), rand(S)>;
  #write (O, str(P.x,0,17), " ", str(P.y,0,17), " ", str(P.z,0,17), " ", str($value,0,17), "\n")
  #declare I = I + 1;
#end
#fclose O
camera { location <0,0,-1> look_at 0 }
POV
}

patterns | while IFS='|' read -r name points body; do
    if [ $# -gt 0 ]; then
        case " $* " in *" $name "*) ;; *) continue ;; esac
    fi
    write_scene "$name" "$points" "$body"
    (cd "$work" && povray -D -GA +W1 +H1 +L"$out" "$name.pov" >/dev/null 2>&1) || {
        echo "povray failed on $name" >&2
        exit 1
    }
    echo "$name"
done
