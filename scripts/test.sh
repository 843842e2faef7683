#!/usr/bin/env bash
# Quick start, part two: the whole test suite (installs dependencies,
# checks the C++ formatting, and builds with warnings as errors first, so it
# works on a fresh machine), then a sanitizer stage: a
# subset of the suite built with AddressSanitizer + UBSan in build-asan
# (tests/sanitize/CMakeLists.txt lists it; docs/robustness.md says why),
# then a short fuzzing stage: each libFuzzer target for LANCER_FUZZ_SECONDS
# (default 30) from the seed corpora, failing on any crash, leak or hang.
# LANCER_SKIP_SANITIZE=1 and LANCER_SKIP_FUZZ=1 skip those stages.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-deps.sh
scripts/check-format.sh
# Warnings are errors here, so a new one fails the suite (a plain build
# only prints them). MPI is required here so that the distributed tests
# (ctest label mpi, docs/distributed.md) run rather than skip.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DLANCER_WARNINGS_AS_ERRORS=ON -DLANCER_MPI=ON
cmake --build build
ctest --test-dir build --output-on-failure -j "$(nproc)"

if [ "${LANCER_SKIP_SANITIZE:-0}" != 1 ]; then
  start=$SECONDS
  # -O1 keeps ASan's reports exact and the build fast; no benchmarks.
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DLANCER_SANITIZE=ON -DLANCER_BUILD_BENCH=OFF -DLANCER_MPI=OFF
  cmake --build build-asan --target lancer_sanitize_tests
  # Leak checking stays on. Embree, TBB and OpenImageIO are not instrumented;
  # ASan intercepts their allocations all the same. One check is off:
  # Debian's OpenImageIO 2.4 itself frees its TextureSystem with a sized
  # delete of the wrong size (TextureSystem::destroy, reproduced without any
  # lancer code), which ASan reports as new-delete-type-mismatch; and its PNG
  # reader leaks an error message when libpng longjmps out of a truncated file
  # (tests/sanitize/lsan.supp says how it was reproduced). Nothing else is
  # suppressed; a UBSan finding fails the test (-fno-sanitize-recover).
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:new_delete_type_mismatch=0} \
  LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/sanitize/lsan.supp} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    ctest --test-dir build-asan -L sanitize --output-on-failure -j "$(nproc)"
  echo "test.sh: sanitizer stage took $((SECONDS - start)) s"
fi

if [ "${LANCER_SKIP_FUZZ:-0}" != 1 ]; then
  start=$SECONDS
  for target in scene obj shapes patterns; do
    # A finding makes libFuzzer exit non-zero and leaves the input in
    # build-fuzz/artifacts/<target>/ (docs/robustness.md says how to replay it).
    log="${TMPDIR:-/tmp}/lancer-fuzz-$target.log"
    # A fixed seed: a run repeats its mutations (up to how many fit in the
    # time), so a finding here can be replayed; LANCER_FUZZ_SEED=0 draws one.
    tests/fuzz/run.sh "$target" "${LANCER_FUZZ_SECONDS:-30}" -seed="${LANCER_FUZZ_SEED:-1}" >"$log" 2>&1 ||
      { tail -40 "$log"; echo "test.sh: fuzz_$target failed: a build error or a failing input (log: $log)" >&2; exit 1; }
  done
  echo "test.sh: fuzzing stage took $((SECONDS - start)) s"
fi
