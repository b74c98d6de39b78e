#!/usr/bin/env bash
# Remakes the pictures in docs/images/ from the scenes in examples/, so anyone can
# see what a change did to them. Builds first.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
build/bin/skylit render examples/building.json --quiet -o docs/images/building.png
echo "Remade docs/images/"
