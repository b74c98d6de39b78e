#!/usr/bin/env bash
# CI, after scripts/test-sanitizers.sh: runs each libFuzzer target in fuzz/ (one per
# parser; built with ASan and UBSan by scripts/build-asan.sh) for a fixed time from its
# seed corpus in fuzz/corpus/<target>/. Fails on any finding: a crash, a sanitizer
# report, an exception other than InputError, a leak, an input taking over 10 s or a
# process over 2 GB. What a target found is kept as build-asan/fuzz-findings/<target>-*
# (reproduce: build-asan/fuzz/fuzz_<target> FILE); new inputs it made go to
# build-asan/fuzz-corpus/<target>/, never into the tree.
#   scripts/fuzz.sh [SECONDS_PER_TARGET (default 30)] [TARGET ...]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene obj gltf ies eulumdat lamp_spectrum)

start=$SECONDS
scripts/build-asan.sh --target "${targets[@]/#/fuzz_}"
echo "fuzz: build took $((SECONDS - start)) s" >&2

findings=$PWD/build-asan/fuzz-findings
mkdir -p "$findings"
failed=()
for target in "${targets[@]}"; do
  work=build-asan/fuzz-corpus/$target
  mkdir -p "$work"
  echo "fuzz: $target for $seconds s" >&2
  if ! build-asan/fuzz/fuzz_"$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
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
