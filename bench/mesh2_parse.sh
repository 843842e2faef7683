#!/bin/sh
# Big-scene reading (issue 21): one mesh2 of ~1M triangles in a 41 MB
# include, as exporters write them, and the same mesh as an OBJ. Times
# `lancer check` (parse and evaluate) of each, a lancer render and POV-Ray's
# render of the mesh2 scene at 1280x960, in one run, and prints medians,
# peak memory and the ratios.
#
#   bench/mesh2_parse.sh [LANCER] [RUNS] [COLUMNS ROWS]
#
# The mesh is a COLUMNS x ROWS grid of vertices (default 1000 x 500:
# 998,002 triangles), a wavy sheet so every triangle is seen.
set -eu
lancer=$(realpath "${1:-build/bin/lancer}")
runs=${2:-5}
columns=${3:-1000}
rows=${4:-500}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

awk -v nx="$columns" -v ny="$rows" 'BEGIN {
  printf "#declare BigMesh = mesh2 {\n vertex_vectors { %d,\n", nx * ny
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
    u = i / (nx - 1); v = j / (ny - 1)
    printf "  <%.6f,%.6f,%.6f>,\n", u * 4 - 2, 0.2 * sin(u * 20) * cos(v * 13), v * 2 - 1
  }
  printf " }\n face_indices { %d,\n", 2 * (nx - 1) * (ny - 1)
  for (j = 0; j < ny - 1; j++) for (i = 0; i < nx - 1; i++) {
    a = j * nx + i
    printf "  <%d,%d,%d>, <%d,%d,%d>,\n", a, a + 1, a + nx, a + 1, a + nx + 1, a + nx
  }
  printf " }\n}\n"
}' > "$work/big.inc"
awk -v nx="$columns" -v ny="$rows" 'BEGIN {
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
    u = i / (nx - 1); v = j / (ny - 1)
    printf "v %.6f %.6f %.6f\n", u * 4 - 2, 0.2 * sin(u * 20) * cos(v * 13), v * 2 - 1
  }
  for (j = 0; j < ny - 1; j++) for (i = 0; i < nx - 1; i++) {
    a = j * nx + i + 1
    printf "f %d %d %d\nf %d %d %d\n", a, a + 1, a + nx, a + 1, a + nx + 1, a + nx
  }
}' > "$work/big.obj"
# The same grid as exporters write it with texture coordinates and normals
# (v, vt, vn, then f v/vt/vn): about three times the text.
awk -v nx="$columns" -v ny="$rows" 'BEGIN {
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
    u = i / (nx - 1); v = j / (ny - 1)
    printf "v %.6f %.6f %.6f\n", u * 4 - 2, 0.2 * sin(u * 20) * cos(v * 13), v * 2 - 1
  }
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) printf "vt %.6f %.6f\n", i / (nx - 1), j / (ny - 1)
  for (j = 0; j < ny; j++) for (i = 0; i < nx; i++) {
    u = i / (nx - 1); v = j / (ny - 1)
    a = -cos(u * 20) * cos(v * 13); c = 1.3 * sin(u * 20) * sin(v * 13); l = sqrt(a * a + 1 + c * c)
    printf "vn %.6f %.6f %.6f\n", a / l, 1 / l, c / l
  }
  for (j = 0; j < ny - 1; j++) for (i = 0; i < nx - 1; i++) {
    a = j * nx + i + 1; b = a + 1; c = a + nx; d = a + nx + 1
    printf "f %d/%d/%d %d/%d/%d %d/%d/%d\nf %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, a, b, b, b, c, c, c, b, b, b, d, d, d, c, c, c
  }
}' > "$work/full.obj"
cat > "$work/obj_full.pov" <<'EOF'
#version 3.7;
camera { location <0, 3, -3> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
obj_mesh { "full.obj" pigment { rgb <0.8, 0.6, 0.4> } }
EOF
cat > "$work/obj.pov" <<'EOF'
#version 3.7;
camera { location <0, 3, -3> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
obj_mesh { "big.obj" pigment { rgb <0.8, 0.6, 0.4> } }
EOF
cat > "$work/big.pov" <<'EOF'
#version 3.7;
#include "big.inc"
camera { location <0, 3, -3> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
object { BigMesh pigment { rgb <0.8, 0.6, 0.4> } }
EOF
# The same mesh written in the scene file itself, as some exporters do.
{ echo '#version 3.7;'; cat "$work/big.inc"; sed -n '/^camera/,$p' "$work/big.pov"; } > "$work/big_main.pov"
triangles=$((2 * (columns - 1) * (rows - 1)))
echo "scene: $triangles triangles, include of $(du -m "$work/big.inc" | cut -f1) MB; $runs runs each, medians"

. "$(dirname "$0")/measure.sh"

cd "$work"
check=$(measure "$lancer" check big.pov)
check_main=$(measure "$lancer" check big_main.pov)
check_obj=$(measure "$lancer" check obj.pov)
check_obj_full=$(measure "$lancer" check obj_full.pov)
render=$(measure "$lancer" render big.pov -o lancer.png --width 1280 --height 960 -i raycast -q)
# A 1x1 render is the issue's "parse + evaluate + build": all but the tracing.
build=$(measure "$lancer" render big.pov -o lancer.png --width 1 --height 1 -i raycast -q)
build_obj=$(measure "$lancer" render obj.pov -o lancer.png --width 1 --height 1 -i raycast -q)
build_obj_full=$(measure "$lancer" render obj_full.pov -o lancer.png --width 1 --height 1 -i raycast -q)
render_obj_full=$(measure "$lancer" render obj_full.pov -o lancer.png --width 1280 --height 960 -i raycast -q)
empty_scene=$(printf '#version 3.7;\ncamera { location -z look_at 0 }\n' > empty.pov; measure "$lancer" check empty.pov)
if command -v povray > /dev/null; then
  pov=$(measure povray +Ibig.pov +Opov.png +W1280 +H960 -A -D -V +WT2 -GA)
else
  pov=""
fi

printf '\n| command | wall s | CPU s | peak MB | bytes per triangle |\n|---|---|---|---|---|\n'
row() {
  set -- "$1" $2
  printf '| %s | %s | %s | %d | %d |\n' "$1" "$2" "$3" $(($4 / 1024)) $(($4 * 1024 / triangles))
}
row "lancer check (mesh2)" "$check"
row "lancer check (mesh2 in the scene file)" "$check_main"
row "lancer check (OBJ)" "$check_obj"
row "lancer check (OBJ with vt and vn)" "$check_obj_full"
row "lancer check, empty scene" "$empty_scene"
row "lancer render raycast 1x1 (mesh2)" "$build"
row "lancer render raycast 1x1 (OBJ)" "$build_obj"
row "lancer render raycast 1x1 (OBJ with vt and vn)" "$build_obj_full"
row "lancer render raycast 1280x960 (OBJ with vt and vn)" "$render_obj_full"
row "lancer render raycast 1280x960" "$render"
[ -n "$pov" ] && row "povray 1280x960 (+WT2 -A)" "$pov"
if [ -n "$pov" ]; then
  echo
  echo "$render $pov" | awk '{ printf "lancer render / POV-Ray: wall %.2f, CPU %.2f, peak memory %.2f\n", $1 / $4, $2 / $5, $3 / $6 }'
fi
