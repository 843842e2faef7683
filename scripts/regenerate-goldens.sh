#!/usr/bin/env bash
# Re-renders golden images (tests/golden/) from the current renderer.
#
#   scripts/regenerate-goldens.sh [BUILD_DIR] [ID_GLOB]
#
# BUILD_DIR defaults to build/. ID_GLOB selects rows of tests/golden/matrix.txt
# by test name (the row's id with every non-alphanumeric replaced by '_',
# e.g. 'cornell_box_path' or 'textures_*'); default: all rows.
#
# A golden is a claim that an image is right. Regenerating overwrites that
# claim with whatever the renderer does today, so it is a deliberate step:
# look at every changed image (tests/golden/ diff, or the failure PNGs under
# BUILD_DIR/golden_failures/), say in the commit why the new one is right and
# how it was checked, and have it reviewed. See docs/testing.md.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
glob="${2:-*}"
cmake --build "$build" --target lancer_tests -j"${LANCER_JOBS:-2}"
LANCER_REGENERATE_GOLDENS=1 "$build/bin/lancer_tests" --gtest_filter="Corpus/GoldenImage.MatchesGolden/$glob"
# Goldens of stochastic integrators are checked against an independent
# render at 4x their samples before they are trusted.
LANCER_VERIFY_GOLDENS=1 "$build/bin/lancer_tests" --gtest_filter="Corpus/GoldenVerify.*/$glob:GoldenConsistency.*"
echo "Regenerated goldens under $root/tests/golden/; review them (git diff --stat tests/golden) before committing."
