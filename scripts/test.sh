#!/usr/bin/env bash
# The README's second command: installs what is missing, builds, and runs the
# whole test suite (CTest running GoogleTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build
ctest --output-on-failure -j2
