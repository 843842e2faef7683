#!/bin/sh
# The classic integrators' cost per light against POV-Ray 3.7's (issue 21):
# bench/lights/point_lights.pov with 1, 16, 64 and 256 point lights over
# 400 spheres, rendered by both at the same size without anti-aliasing, in
# one run: medians of wall and CPU time (user + system), and lancer's CPU
# ratio to POV-Ray's.
#
#   bench/pov_lights.sh [LANCER] [RUNS] [WIDTH HEIGHT] [INTEGRATOR]
set -eu
lancer=$(realpath "${1:-build/bin/lancer}")
runs=${2:-3}
width=${3:-640}
height=${4:-480}
integrator=${5:-shadow}
scene=$(realpath "$(dirname "$0")/lights/point_lights.pov")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/measure.sh"
command -v povray > /dev/null || { echo "povray is not installed (apt-get install povray)" >&2; exit 1; }
cores=$(nproc)
echo "${width}x$height, $integrator, $runs runs each, medians; POV-Ray with +WT$cores"
printf '\n| lights | lancer wall s | CPU s | POV-Ray wall s | CPU s | CPU ratio |\n'
printf '|---|---|---|---|---|---|\n'
cd "$work"
for lights in 1 16 64 256; do
  lancer_run=$(measure "$lancer" render "$scene" -i "$integrator" -o lancer.png --width "$width" --height "$height" \
    -q --declare "Lights=$lights")
  pov_run=$(measure povray "+I$scene" +Opov.png "+W$width" "+H$height" -A -D -V "+WT$cores" -GA "Declare=Lights=$lights")
  echo "$lights $lancer_run $pov_run" | awk '{
    printf "| %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n", $1, $2, $3, $5, $6, $3 / $6 }'
done
