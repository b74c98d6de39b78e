#!/usr/bin/env bash
# The sun-study benchmark (issue 20): a 24-frame day (00:00 to 23:00 every hour) of the
# default example, examples/building.json, at 640 × 360, timed end to end: loading,
# 24 renders, the labelled PNGs, the viewer and (when ffmpeg is there) the MP4. With
# RANKS=2 the same under `mpirun -n 2` (Open MPI). Prints the wall-clock seconds of each
# of REPEATS runs (default 3) and their median. Target: at most 20 s; two ranks on this
# 2-core machine no slower than one process.
#   bench/animate_day.sh [build/bin/skylit]
set -euo pipefail
cd "$(dirname "$0")/.."
skylit=${1:-build/bin/skylit}
repeats=${REPEATS:-3}
launcher=()
if [ "${RANKS:-1}" -gt 1 ]; then
  launcher=(mpirun -n "$RANKS" --oversubscribe)
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
times=()
for _ in $(seq "$repeats"); do
  start=$(date +%s.%N)
  "${launcher[@]}" "$skylit" animate examples/building.json --site 48.14,11.58 \
    --from 2026-06-21T00:00+02:00 --to 2026-06-21T23:00+02:00 --every 1h \
    --set render.width=640 --set render.height=360 -q -o "$out/day"
  times+=("$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN {printf "%.2f", b - a}')")
done
printf 'run: %s s\n' "${times[@]}"
printf '%s\n' "${times[@]}" | sort -n | awk '{t[NR]=$1} END {printf "median: %.2f s (%d runs, ranks %s)\n", t[int((NR+1)/2)], NR, ENVIRON["RANKS"] ? ENVIRON["RANKS"] : 1}'
