#!/bin/bash
# CPU time of lancer against POV-Ray 3.7 on POV-Ray's own sample scenes
# (Debian's povray-examples), one thread each, without anti-aliasing, at
# 320x240: every STEP-th scene of the sorted list (animations and include
# folders left out), each rendered once by each, in its own folder as
# POV-Ray expects. Prints one line per scene, slowest ratio first, and the
# sums. Outliers here are what a scene written for POV-Ray pays that the
# anchor scenes do not show (bench/README.md).
#
#   bench/pov_samples.sh [LANCER] [STEP] [JOBS]
#
# LANCER: the lancer binary (default build/bin/lancer); STEP: take every
# STEP-th scene (default 9: 43 scenes); JOBS: scenes run at once (default 1;
# 2 on two cores halves the wall time but makes the two renderers share
# the machine's noise).
set -eu
lancer=$(realpath "${1:-build/bin/lancer}")
step=${2:-9}
jobs=${3:-1}
command -v povray >/dev/null || { echo "pov_samples: povray is not installed" >&2; exit 1; }
examples=/usr/share/doc/povray/examples
[ -d "$examples" ] || { echo "pov_samples: $examples is missing (povray-examples)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

find "$examples" -name '*.pov' | grep -v -E 'animations|/include/|incdemo' | sort | awk -v s="$step" '(NR - 1) % s == 0' \
  > "$work/list"

one_scene() {
  local scene=$1 lancer=$2 work=$3 name
  name=$(basename "$scene" .pov)
  cd "$(dirname "$scene")"
  /usr/bin/time -o "$work/$name.lancer" -f "%U %S" timeout 120 "$lancer" render "$scene" -i whitted \
    --width 320 --height 240 -q --threads 1 -o "$work/$name.l.png" >/dev/null 2>&1 || true
  /usr/bin/time -o "$work/$name.pov" -f "%U %S" timeout 120 povray "+I$scene" "+O$work/$name.p.png" +FN \
    +W320 +H240 -A -D -V +WT1 -GA >/dev/null 2>&1 || true
  local l p
  l=$(tail -1 "$work/$name.lancer" | awk '{print $1 + $2}')
  p=$(tail -1 "$work/$name.pov" | awk '{print $1 + $2}')
  echo "$name $l $p"
}
export -f one_scene
xargs -P "$jobs" -I{} bash -c 'one_scene "$@"' _ {} "$lancer" "$work" < "$work/list" > "$work/times"

echo "POV-Ray's samples, every ${step}th ($(wc -l < "$work/list") scenes), 320x240, one thread, CPU seconds"
echo
echo "| scene | lancer | POV-Ray | ratio |"
echo "|---|---|---|---|"
awk '$3 > 0 { printf "| %s | %.2f | %.2f | %.2f |\n", $1, $2, $3, $2 / $3 }' "$work/times" | sort -t'|' -k5 -g -r
awk '{ l += $2; p += $3 } END { printf "\nsums: lancer %.2f s, POV-Ray %.2f s, ratio %.2f\n", l, p, l / p }' "$work/times"
