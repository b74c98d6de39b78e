#!/usr/bin/env bash
# Remakes the fast-against-reference tables of docs/validation.md: every example
# rendered by the fast method (bands) and by the path-traced reference at the same
# size, then `skylit compare` per region (validation/regions/NAME.json), with the
# reference's standard error. Writes out/validation/ (images, ratio maps, JSON) and
# prints the tables in Markdown. Builds first.
#   scripts/validate.sh [WIDTH HEIGHT SAMPLES [EXAMPLE ...]]   (default 320 180 256, all)
# An example may be a variant NAME@PATH=VALUE (e.g. fig7@materials.walls=aluminium):
# the scene with that --set, compared in NAME's regions. The default list has Fig. 7's
# aluminium tower and the fog figures in the paper's single scattering too.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh >/dev/null
width=${1:-320}
height=${2:-180}
samples=${3:-256}
shift $(( $# >= 3 ? 3 : $# ))
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for f in validation/regions/*.json; do names+=("$(basename "$f" .json)"); done
  names+=("fig7@materials.walls=aluminium")
  # The fog figures in the paper's single scattering, for the brackets of docs/validation.md.
  for f in fig8a fig8b fig8c fig8d fig9; do names+=("$f@fog.multiple_scattering=false"); done
fi
skylit=build/bin/skylit
out=out/validation
mkdir -p "$out"
size=(--set render.width="$width" --set render.height="$height")
for entry in "${names[@]}"; do
  base=${entry%%@*}
  variant=()
  name=$base
  if [[ $entry == *@* ]]; then
    variant=(--set "${entry#*@}")
    name=$base-$(echo "${entry#*@}" | tr -c 'A-Za-z0-9\n' '-')
  fi
  scene=examples/$base.json
  start=$SECONDS
  $skylit render "$scene" --quiet "${size[@]}" "${variant[@]}" -o "$out/$name-bands.exr"
  $skylit render "$scene" --quiet "${size[@]}" "${variant[@]}" --set render.integrator=path \
    --set render.samples_per_pixel="$samples" -o "$out/$name-path.exr" -o "$out/$name-path.png" \
    --standard-error "$out/$name-path-se.exr"
  echo
  echo "### $entry ($width × $height, $samples paths per pixel, $((SECONDS - start)) s)"
  echo
  echo '```'
  $skylit compare "$out/$name-bands.exr" "$out/$name-path.exr" --standard-error-b "$out/$name-path-se.exr" \
    --regions "validation/regions/$base.json" -o "$out/$name-ratio.png" --json "$out/$name.json" | tail -n +4
  echo '```'
done
