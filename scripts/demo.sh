#!/usr/bin/env bash
# Quick start, part one: install dependencies, build lancer, render the demo
# scene to demo.png in the project folder.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
./build/bin/lancer render scenes/demo.pov -o demo.png
echo "demo: wrote $(pwd)/demo.png"
