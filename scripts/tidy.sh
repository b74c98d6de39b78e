#!/usr/bin/env bash
# Runs clang-tidy with the checks of .clang-tidy over the library's sources (src/:
# libskylit and skylit_figures, and the headers they include) and fails on any
# finding (WarningsAsErrors). Needs a configured build for compile_commands.json:
#   scripts/tidy.sh [BUILD_DIR]      (default build/; configured here if missing)
# JOBS=N sets the number of parallel clang-tidy processes (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
jobs=${JOBS:-2}

scripts/install-deps.sh --clang
if [ ! -f "$build_dir/compile_commands.json" ]; then
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
fi

# The files to check: the compile database's entries below src/ (not the generated
# embedded data, not tests, apps or benchmarks).
src_regex="^$(pwd)/src/.*\.cpp$"
runner=$(command -v run-clang-tidy || command -v run-clang-tidy-14 || true)
start=$(date +%s)
set +e +o pipefail
if [ -n "$runner" ]; then
  # run-clang-tidy exits non-zero if any clang-tidy run does.
  "$runner" -p "$build_dir" -j "$jobs" -quiet "$src_regex" 2>&1 | grep -v -E '^([0-9]+ warnings? generated|Suppressed [0-9]+ warnings|Use -header-filter)'
  status=${PIPESTATUS[0]}
else
  python3 -c 'import json,sys; [print(e["file"]) for e in json.load(open(sys.argv[1]))]' \
      "$build_dir/compile_commands.json" | grep -E "$src_regex" | sort -u |
    xargs -P "$jobs" -n 4 clang-tidy -p "$build_dir" --quiet
  status=$?
fi
echo "clang-tidy: $(( $(date +%s) - start )) s, status $status" >&2
exit "$status"
