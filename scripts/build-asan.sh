#!/usr/bin/env bash
# Configures and builds the Clang build with AddressSanitizer, UndefinedBehaviorSanitizer
# and libFuzzer's coverage hooks into build-asan/: one build serves the sanitized test
# suite (scripts/test-sanitizers.sh) and the fuzz targets (scripts/fuzz.sh). Line tables
# and frame pointers for readable reports, without NDEBUG so that the library's
# assertions stay on. -gline-tables-only, not -g: a report names each frame's function,
# file and line either way, and without the variables' debug information a translation
# unit compiles 7–11 % faster and its object is 40–67 % smaller (CI builds this cold).
# -O2, not the usual -O1: at -O1 the tables' loops over spectral bins were not
# vectorised and the instrumented suite ran 50–77 times slower than Release (an
# atmosphere's tables 90 s against 1.3 s), which took CI past its time limit; -O2 runs
# the same tests 4.5–5.6 times faster than -O1 (measured 2026-12-03). Arguments are
# passed to the build (e.g. --target fuzz_ies).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --clang
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only" \
  -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" \
  -DSKYLIT_SANITIZE=address,undefined -DSKYLIT_BUILD_FUZZ=ON -DSKYLIT_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j2 "$@"
