#!/usr/bin/env bash
# Configures and builds the Clang build with AddressSanitizer, UndefinedBehaviorSanitizer
# and libFuzzer's coverage hooks into build-asan/: one build serves the sanitized test
# suite (scripts/test-sanitizers.sh) and the fuzz targets (scripts/fuzz.sh). -O1 -g
# without NDEBUG: readable reports, and the library's assertions stay on. Arguments
# are passed to the build (e.g. --target fuzz_ies).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --clang
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
  -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" \
  -DSKYLIT_SANITIZE=address,undefined -DSKYLIT_BUILD_FUZZ=ON -DSKYLIT_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j2 "$@"
