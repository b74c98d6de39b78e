#!/usr/bin/env bash
# Installs the Debian 12 packages skylit needs to build and test, if any is missing.
# As root it runs apt-get; otherwise it prints the exact command to run and stops.
# With --clang it also installs the checking tools CI runs: Clang 14 with its sanitizer
# runtimes and libFuzzer (libclang-rt-14-dev, only recommended by clang-14), for
# scripts/test-sanitizers.sh and scripts/fuzz.sh, and clang-format and clang-tidy for
# scripts/check-format.sh and scripts/tidy.sh.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libembree-dev libtbb-dev libopenexr-dev libpng-dev libjpeg62-turbo-dev
  nlohmann-json3-dev libtinyobjloader-dev libtinygltf-dev libcli11-dev
  libstb-dev
  libgtest-dev libbenchmark-dev
  libproj-dev proj-bin
  chromium  # the HTML report's test opens it in a real browser (docs/report.md)
  # Optional at build time, used when present (issue 20): Open MPI for mpirun runs
  # (docs/cluster.md), ffmpeg for skylit animate's MP4 (x264) and the tests' ffprobe.
  libopenmpi-dev openmpi-bin ffmpeg
  libexpat1-dev libgdal-dev  # CityGML is read with expat; DEMs (terrain) with GDAL
)
if [ "${1:-}" = "--clang" ]; then
  packages+=(clang-14 libclang-rt-14-dev clang-format clang-tidy)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "skylit needs these Debian packages; install them with:" >&2
  echo "  sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
echo "Installing: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
