#!/bin/sh
# Thread scaling (issue 21): samples per second of the render itself (the
# `seconds.render` of --stats, without parsing or writing the image) on 1
# and on 2 threads, for `path` on scenes/cornell_box.pov (4 spp) and
# `whitted` on bench/anchors/mirrors.pov, at 1280x960. The runs alternate
# 1 and 2 threads, so a drift in the machine's speed touches both; medians.
#
#   bench/thread_scaling.sh [LANCER] [RUNS]
set -eu
lancer=$(realpath "${1:-build/bin/lancer}")
runs=${2:-5}
root=$(realpath "$(dirname "$0")/..")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
render_seconds() {
  sed -n 's/.*"render": *\([0-9.e+-]*\).*/\1/p' "$1"
}
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
echo "1280x960, $runs runs each, medians of the render's own seconds"
printf '\n| integrator | scene | spp | 1 thread s | 2 threads s | speed-up |\n|---|---|---|---|---|---|\n'
for case in "path scenes/cornell_box.pov 4" "whitted bench/anchors/mirrors.pov 1"; do
  set -- $case
  : > "$work/1"
  : > "$work/2"
  i=0
  while [ "$i" -lt "$runs" ]; do
    for threads in 1 2; do
      "$lancer" render "$root/$2" -i "$1" --width 1280 --height 960 --spp "$3" --threads "$threads" -q \
        -o "$work/out.png" --stats "$work/stats.json" > /dev/null 2>&1
      render_seconds "$work/stats.json" >> "$work/$threads"
    done
    i=$((i + 1))
  done
  one=$(median < "$work/1")
  two=$(median < "$work/2")
  echo "$1 $2 $3 $one $two" | awk '{ printf "| %s | %s | %s | %.3f | %.3f | %.2f |\n", $1, $2, $3, $4, $5, $4 / $5 }'
done
