#!/usr/bin/env bash
# Installs every Debian 12 package lancer needs to build, test and benchmark.
# Safe to run again; needs root or sudo.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git ca-certificates clang-format
  clang libclang-rt-14-dev
  flex bison
  libglm-dev libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools
  # A palette PNG's indices (OpenImageIO gives only its colours).
  libpng-dev
  # JPEG images read without loading OpenImageIO (render/src/film/jpeg_reader.h).
  libjpeg-dev
  libtinyobjloader-dev libcli11-dev libfreetype-dev fonts-povray
  # Number parsing in the scanner (as strtod rounds, faster).
  libfast-float-dev
  povray-includes
  libgtest-dev libgmock-dev libbenchmark-dev
  # The live preview's HTTP server, and the headless browser its tests and
  # the trade report's drive (tests/browser/).
  libcpp-httplib-dev chromium chromium-driver python3-selenium
  # Optional: rendering over several processes (docs/distributed.md).
  libopenmpi-dev openmpi-bin
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup-deps: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

# chromedriver reaches the browser it starts at "localhost" (the browser
# tests, tests/browser/): a bare root (debootstrap, some containers) has no
# /etc/hosts to say where that is.
if ! getent hosts localhost >/dev/null; then
  echo "setup-deps: 'localhost' does not resolve; adding it to /etc/hosts"
  echo "127.0.0.1 localhost" | "${sudo_cmd[@]}" tee -a /etc/hosts >/dev/null
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-deps: all packages already installed"
  exit 0
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
