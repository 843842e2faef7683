#!/usr/bin/env bash
# Builds the fuzzers if needed, assembles the seed corpora, then runs one
# target for a given time (docs/robustness.md).
#   tests/fuzz/run.sh scene|obj|shapes|patterns SECONDS [extra libFuzzer flags...]
# Environment: BUILD (default build-fuzz), JOBS (build jobs, default 2).
# Findings go to $BUILD/artifacts/<target>/; the growing corpus to
# $BUILD/corpus/<target>/ (kept between runs).
set -euo pipefail
cd "$(dirname "$0")/../.."
target=${1:?usage: tests/fuzz/run.sh scene|obj|shapes|patterns SECONDS [flags...]}
seconds=${2:?usage: tests/fuzz/run.sh scene|obj|shapes|patterns SECONDS [flags...]}
shift 2
build=${BUILD:-build-fuzz}
if [ ! -f "$build/build.ninja" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DLANCER_FUZZ=ON -DLANCER_BUILD_TESTS=OFF -DLANCER_BUILD_BENCH=OFF
fi
cmake --build "$build" -j "${JOBS:-2}" --target "fuzz_$target"
python3 tests/fuzz/make_corpus.py "$build/seeds" >/dev/null
build=$(cd "$build" && pwd)
mkdir -p "$build/corpus/$target" "$build/artifacts/$target" "$build/work"
flags=(-max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -max_len=65536
       -artifact_prefix="$build/artifacts/$target/" -print_final_stats=1)
# Both scene-text targets share the grammar's dictionary.
case "$target" in scene | patterns) flags+=(-dict="$build/seeds/scene.dict") ;; esac
# The scene-text fuzzers' safe_root is the current folder: an empty work folder.
cd "$build/work"
exec "$build/tests/fuzz/fuzz_$target" "${flags[@]}" "$@" "$build/corpus/$target" "$build/seeds/$target"
