#!/bin/sh
# Many lights in `path` (issue 21): small sphere lamps in a grid over a
# floor with a few blocks, 1, 16, 256 and 4096 of them, rendered with each
# light selection at the same samples per pixel. Prints the render time,
# the true relative RMSE against a reference (per pixel and channel, the
# squared error over the reference's square plus 0.01, as lancer's own
# estimate and lancer trade measure it: render/src/film/estimate.cpp), the
# renderer's estimate of it (--stats) as a share of the truth, and the efficiency 1 / (time x error^2): how much less time the
# same error takes. With one light a sample costs whatever it costs; with
# many, only the choice of the light per sample grows (a binary search for
# "power", a walk down the tree for "tree"), so time per sample stays
# nearly flat and the error is what differs.
#
# Each count's reference is the mean of a "power" and a "tree" render at
# 8 x SPP each: neither rule is favoured, and with 16 x the samples its own
# noise adds about 3% to the errors measured, alike for both rules.
#
#   bench/many_lights.sh [LANCER] [SPP] [WIDTH HEIGHT]
set -eu
lancer=$(realpath "${1:-build/bin/lancer}")
spp=${2:-16}
width=${3:-320}
height=${4:-240}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v oiiotool > /dev/null || { echo "oiiotool is not installed (apt-get install openimageio-tools)" >&2; exit 1; }
echo "${width}x$height, $spp spp, -i path; one run each"
printf '\n| lights | selection | render s | rel. RMSE | estimate / true | efficiency vs power |\n|---|---|---|---|---|---|\n'
# The mean over the pixels and the three channels of an image.
image_mean() {
  oiiotool --stats "$1" 2>/dev/null | sed -n 's/.*Stats Avg: \([^(]*\)(float).*/\1/p' | head -1 |
    awk '{ print ($1 + $2 + $3) / 3 }'
}
render() {  # SELECTION SPP OUTPUT [STATS]
  "$lancer" render "$work/lights.pov" -i path -p "light_sampling=$1" --spp "$2" \
    --width "$width" --height "$height" -q -o "$3" ${4:+--stats "$4"}
}
for count in 1 16 256 4096; do
  awk -v n="$count" 'BEGIN {
    print "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }"
    print "camera { location <0, 12, -14> look_at <0, 0, 0> angle 60 }"
    print "plane { y, 0 texture { pigment { color rgb 0.7 } finish { ambient 0 diffuse 1 } } }"
    side = int(sqrt(n) + 0.5)
    for (i = 0; i < side; i++) for (j = 0; j < side; j++) {
      x = (i - (side - 1) / 2) * 16 / side; z = (j - (side - 1) / 2) * 16 / side; c = (i + j) % 3
      # The same total power whatever the count.
      k = 40 / n
      printf "light_source { <%g, 0.6, %g> color rgb <%g, %g, %g> area_sphere 0.1 }\n", x, z, k * (4 * (c == 0) + 0.5), k * (4 * (c == 1) + 0.5), k * (4 * (c == 2) + 0.5)
    }
    print "#declare Block = box { <-0.2, 0, -0.2>, <0.2, 0.8, 0.2> texture { pigment { color rgb 0.8 } finish { ambient 0 } } }"
    for (i = 0; i < 5; i++) printf "object { Block translate <%g, 0, %g> }\n", i * 3 - 6, (i % 2) * 2 - 1
  }' > "$work/lights.pov"
  render power $((8 * spp)) "$work/reference_power.exr"
  render tree $((8 * spp)) "$work/reference_tree.exr"
  oiiotool "$work/reference_power.exr" "$work/reference_tree.exr" --add --mulc 0.5 -o "$work/reference.exr"
  oiiotool "$work/reference.exr" --powc 2 --addc 0.01 -o "$work/scale.exr"
  base=""
  for selection in power tree; do
    render "$selection" "$spp" "$work/out.exr" "$work/stats.json"
    seconds=$(sed -n 's/.*"render": \([0-9.e+-]*\).*/\1/p' "$work/stats.json")
    estimate=$(sed -n 's/.*"estimated_rel_rmse": \([0-9.e+-]*\).*/\1/p' "$work/stats.json")
    oiiotool "$work/out.exr" "$work/reference.exr" --sub --powc 2 "$work/scale.exr" --div -o "$work/relative.exr"
    error=$(awk -v m="$(image_mean "$work/relative.exr")" 'BEGIN { print sqrt(m) }')
    efficiency=$(awk -v t="$seconds" -v e="$error" 'BEGIN { print 1 / (t * e * e) }')
    [ -z "$base" ] && base=$efficiency
    awk -v n="$count" -v s="$selection" -v t="$seconds" -v e="$error" -v x="$estimate" -v f="$efficiency" \
      -v b="$base" 'BEGIN { printf "| %d | %s | %.2f | %.3f | %.2f | %.2f |\n", n, s, t, e, x / e, f / b }'
  done
done
