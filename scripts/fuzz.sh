#!/usr/bin/env bash
# CI, after scripts/test-sanitizers.sh: runs each libFuzzer target in fuzz/ (one per
# parser; built with ASan and UBSan by scripts/build-asan.sh) for a fixed time from its
# seed corpus in fuzz/corpus/<target>/. Fails on any finding: a crash, a sanitizer
# report, an exception other than InputError, a leak, an input taking over 10 s or a
# process over 2 GB. What a target found is kept as build-asan/fuzz-findings/<target>-*
# (reproduce: build-asan/fuzz/fuzz_<target> FILE); new inputs it made go to
# build-asan/fuzz-corpus/<target>/, never into the tree.
#   scripts/fuzz.sh                       CI: a fixed number of inputs per target from a
#                                         fixed seed (about 30 s each here), so a run is
#                                         reproducible and a red CI is never chance
#   scripts/fuzz.sh SECONDS [TARGET ...]  exploring: that long per target, a new seed each
#                                         time; what it finds joins the corpus as a test
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-}
shift || true
targets=("$@")
# Inputs per target in CI's reproducible run: about 30 s each on this two-core machine.
declare -A ci_runs=([scene]=100000 [obj]=6000 [gltf]=40000 [ies]=300000 [eulumdat]=500000 [lamp_spectrum]=60000 [cli_numbers]=200000 [cityjson]=20000 [epw]=100000 [xyz_file]=100000 [citygml]=100000 [texture]=20000)
[ ${#targets[@]} -eq 0 ] && targets=(scene obj gltf ies eulumdat lamp_spectrum cli_numbers cityjson epw xyz_file citygml texture)

start=$SECONDS
scripts/build-asan.sh --target "${targets[@]/#/fuzz_}"
echo "fuzz: build took $((SECONDS - start)) s" >&2

findings=$PWD/build-asan/fuzz-findings
mkdir -p "$findings"
failed=()
for target in "${targets[@]}"; do
  work=build-asan/fuzz-corpus/$target
  mkdir -p "$work"
  if [ -n "$seconds" ]; then
    budget=(-max_total_time="$seconds")
    echo "fuzz: $target for $seconds s" >&2
  else
    rm -rf "$work" && mkdir -p "$work"  # the same start every time
    budget=(-runs="${ci_runs[$target]}" -seed=1)
    echo "fuzz: $target, ${ci_runs[$target]} inputs from seed 1" >&2
  fi
  if ! build-asan/fuzz/fuzz_"$target" "${budget[@]}" -rss_limit_mb=2048 -timeout=10 \
      -print_final_stats=1 -artifact_prefix="$findings/$target-" "$work" "fuzz/corpus/$target" \
      > "build-asan/fuzz-$target.log" 2>&1; then
    tail -n 60 "build-asan/fuzz-$target.log" >&2
    failed+=("$target")
  fi
done
echo "fuzz: took $((SECONDS - start)) s in all" >&2
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]} (inputs in $findings/)" >&2
  exit 1
fi
