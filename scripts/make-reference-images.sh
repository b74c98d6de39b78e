#!/usr/bin/env bash
# Remakes the reference images in tests/reference_images/: every examples/*.json
# rendered small (112 × 63, the examples' 16:9 kept; each scene's own samples_per_axis,
# so edge refinement is exercised) to EXR, which the test
# tests/render/reference_images_test.cpp renders again and compares. Builds first.
#
# Run it only when a change is meant to move pixels, and commit the new images in the
# same commit as that change, saying in its message why the pixels moved.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
skylit=build/bin/skylit
out=tests/reference_images
# Small enough that the whole set renders in about 10 s and the folder stays near
# 1 MB (float EXR hardly compresses); the odd height cuts the 32-pixel tiles and the
# sky-light cache's 16-pixel grid at a partial row, as real sizes do.
width=112
height=63
mkdir -p "$out"
rm -f "$out"/*.exr
for scene in examples/*.json; do
  name=$(basename "$scene" .json)
  "$skylit" render "$scene" --set render.width=$width --set render.height=$height --quiet -o "$out/$name.exr"
done

commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
if [ -n "$(git status --porcelain -- src apps data examples CMakeLists.txt 2>/dev/null)" ]; then
  commit="$commit plus uncommitted changes to the renderer or examples (the commit that adds these images)"
fi
cat > "$out/README.md" <<EOF
# Reference images

One EXR per scene in \`examples/\`, rendered by the program itself at ${width} × ${height}
pixels (the scenes' 16:9 kept, each scene's own \`render.samples_per_axis\`):

    skylit render examples/NAME.json --set render.width=${width} --set render.height=${height} --quiet -o tests/reference_images/NAME.exr

Made by \`scripts/make-reference-images.sh\` from commit ${commit}.
Each file holds float R, G, B (linear sRGB primaries) and Y (luminance, cd/m²); see
docs/images.md.

\`tests/render/reference_images_test.cpp\` renders every example again at the same size
and compares it with its reference in X, Y and Z, with the tolerance stated and
justified in that file (per pixel 10⁻³ relative above a floor of 10⁻⁵ of the image's
log-average luminance; at most 0.2 % of pixels, edge pixels whose antialiasing decision
flipped, up to 5 %; image means within 10⁻³). A new example without a reference fails
too.

**A change that moves pixels beyond that tolerance must regenerate these images
(\`scripts/make-reference-images.sh\`) in the same commit and say in its commit message
why the pixels moved.** A change that is meant to keep pixels (a refactoring, a
speed-up) must pass the test with the images as they are. When the test fails it
prints the scene, how many pixels differ, the worst pixel with both values, and the
paths of the new render and of a difference image (PFM: R, G, B = (new − reference) /
(|reference| + floor) of X, Y, Z, so ±0.001 is the per-pixel tolerance).
EOF
du -cb "$out"/*.exr | tail -1 | awk '{ printf "Remade %s: %.0f kB\n", "'"$out"'/", $1 / 1000 }'
