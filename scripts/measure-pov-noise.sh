#!/bin/sh
# Recovers POV-Ray 3.7's noise tables by measuring povray (Debian's 3.7.0.10:
# apt-get install povray) and writes
#   render/src/materials/pov_noise_tables.inc  the tables lancer's noise uses
#   tests/reference/pov/noise/*.txt            POV's own output, for noise_test.cpp
# docs/noise.md explains the method. Takes a few minutes.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/measure-pov-noise.XXXXXX")
trap 'rm -rf "$work"' EXIT
command -v povray >/dev/null || { echo "measure-pov-noise.sh: povray is not installed" >&2; exit 1; }
povray --version 2>&1 | grep -q "POV-Ray 3\.7" || echo "measure-pov-noise.sh: warning: not POV-Ray 3.7" >&2
${CXX:-g++} -std=c++17 -O2 -o "$work/measure_pov_noise" "$root/scripts/measure_pov_noise.cpp"
mkdir -p "$root/tests/reference/pov/noise"
"$work/measure_pov_noise" "$work" "$root/render/src/materials/pov_noise_tables.inc" "$root/tests/reference/pov/noise"
