#!/usr/bin/env bash
# Renders POV-Ray 3.7's reference of every scene in this folder with an
# alpha channel (+UA), the answers tests/render_outputs_test.cpp compares
# lancer's --alpha with. Needs Debian's povray; not needed to run the tests.
#   tests/reference/pov/alpha/render-references.sh
set -euo pipefail
cd "$(dirname "$0")"
povray --version 2>&1 | grep -m1 "^POV-Ray"
for scene in *.pov; do
  # As ../render-references.sh, with +UA: a 16-bit RGBA PNG keeps the
  # alpha exact enough to compare.
  povray +I"$scene" +O"${scene%.pov}.png" +FN16 +UA +W160 +H120 -A -D -V +WT2 -GA 2>/dev/null
done
