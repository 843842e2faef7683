#!/usr/bin/env bash
# Quick start, part two: the whole test suite (installs dependencies and
# builds first, so it works on a fresh machine).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
ctest --test-dir build --output-on-failure -j "$(nproc)"
