#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and renders the
# default example scene into out/ (a PNG to look at, an EXR with absolute values).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
mkdir -p out
build/bin/skylit render examples/building.json -o out/building.png -o out/building.exr
echo "Wrote out/building.png and out/building.exr"
