#!/usr/bin/env bash
# Renders POV-Ray 3.7's reference image of every scene in this folder, the
# answers tests/pov_reference_test.cpp compares lancer's whitted with.
# Needs Debian's povray (apt-get install povray); not needed to run the tests.
#   tests/reference/pov/render-references.sh
set -euo pipefail
cd "$(dirname "$0")"
povray --version 2>&1 | grep -m1 "^POV-Ray"
for scene in *.pov; do
  # 160x120, no antialiasing (every pixel traced once, through its centre,
  # as lancer's deterministic integrators do at one sample), 8-bit sRGB PNG.
  povray +I"$scene" +O"${scene%.pov}.png" +FN +W160 +H120 -A -D -V +WT2 -GA 2>/dev/null
done
