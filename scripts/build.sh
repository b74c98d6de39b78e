#!/usr/bin/env bash
# Configures and builds skylit in Release into build/ (two parallel jobs: the
# machines this project targets have two cores).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
