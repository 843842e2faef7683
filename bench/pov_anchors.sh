#!/bin/sh
# Whole-process cost against POV-Ray 3.7 on the anchor scenes of issue 21
# (bench/anchors/: three spheres with hard shadows, spheres between facing
# mirrors, an 8 x 8 adaptive area light), rendered by both at the same size
# without anti-aliasing, in one run: medians of wall time, CPU time (user +
# system) and peak memory, and lancer's ratios to POV-Ray's.
#
#   bench/pov_anchors.sh [LANCER] [RUNS] [WIDTH HEIGHT] [FOLDER]
#
# FOLDER holds the three scenes (default bench/anchors; bench/anchors/variants
# has a second set written apart from the first, with patterns, highlights,
# two lights and deeper mirrors), or names its own in a file `scenes`, one
# scene:integrator a line (bench/anchors/probes: seven scenes of other kinds,
# written after the first two sets were measured).
#
# POV-Ray runs with +WT<cores> (as many threads as lancer) and -D (no
# display). A 1x1 render of each scene with lancer gives the memory that
# does not grow with the image; the bytes per pixel above it are printed.
set -eu
lancer=$(realpath "${1:-build/bin/lancer}")
runs=${2:-5}
width=${3:-1280}
height=${4:-960}
anchors=$(realpath "${5:-$(dirname "$0")/anchors}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/measure.sh"
command -v povray > /dev/null || { echo "povray is not installed (apt-get install povray)" >&2; exit 1; }
cores=$(nproc)
pixels=$((width * height))
echo "${width}x$height, $runs runs each, medians; POV-Ray with +WT$cores"
printf '\n| scene | integrator | lancer wall s | CPU s | peak MB | bytes/pixel above 1x1 | POV-Ray wall s | CPU s | peak MB | wall ratio | CPU ratio | memory ratio |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n'
cd "$work"
scenes="three_spheres:shadow mirrors:whitted area_lit:shadow"
[ -f "$anchors/scenes" ] && scenes=$(grep -v '^#' "$anchors/scenes")
for anchor in $scenes; do
  scene=${anchor%%:*}
  integrator=${anchor#*:}
  cp "$anchors/$scene.pov" .
  lancer_run=$(measure "$lancer" render "$scene.pov" -i "$integrator" -o lancer.png --width "$width" --height "$height" -q)
  tiny=$(measure "$lancer" render "$scene.pov" -i "$integrator" -o tiny.png --width 1 --height 1 -q)
  pov_run=$(measure povray "+I$scene.pov" +Opov.png "+W$width" "+H$height" -A -D -V "+WT$cores" -GA)
  echo "$scene $integrator $lancer_run $tiny $pov_run $pixels" | awk '{
    printf "| %s | %s | %.2f | %.2f | %d | %.0f | %.2f | %.2f | %d | %.2f | %.2f | %.2f |\n",
      $1, $2, $3, $4, $5 / 1024, ($5 - $8) * 1024 / $12, $9, $10, $11 / 1024, $3 / $9, $4 / $10, $5 / $11 }'
done
