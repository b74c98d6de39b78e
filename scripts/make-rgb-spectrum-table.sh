#!/usr/bin/env bash
# Remakes data/rgb_spectrum_coefficients.csv, the Jakob–Hanika fit at the nodes of the
# RGB → spectrum table (src/skylit/spectrum/rgb_spectrum_table.h), after a change to the
# fit. tests/spectrum/rgb_spectrum_table_test.cpp fails while the file is stale.
# Usage: scripts/make-rgb-spectrum-table.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
# The tool reads the fit's colour tables from the library, which embeds data/*.csv; a
# placeholder keeps the library building the first time.
[ -f data/rgb_spectrum_coefficients.csv ] || echo "r,g,b,c0,c1,c2" > data/rgb_spectrum_coefficients.csv
cmake --build "$build" --target skylit_make_rgb_table -j2
"$build/bin/skylit_make_rgb_table" > data/rgb_spectrum_coefficients.csv.tmp
mv data/rgb_spectrum_coefficients.csv.tmp data/rgb_spectrum_coefficients.csv
echo "wrote data/rgb_spectrum_coefficients.csv" >&2
