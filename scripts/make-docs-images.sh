#!/usr/bin/env bash
# Remakes the pictures in docs/images/ from the scenes in examples/ and the sky and
# spectrum commands, so anyone can see what a change did to them. Builds first.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
skylit=build/bin/skylit
out=docs/images
mkdir -p "$out"
$skylit render examples/building.json --quiet -o "$out/building.png"
for altitude in 60 17 4 -4; do
  $skylit sky --sun-altitude "$altitude" --sun-azimuth 180 --projection fisheye --size 256 -o "$out/sky-fisheye-$altitude.png"
done
$skylit sky --sun-altitude 4 --sun-azimuth 180 --projection equirect --size 256 -o "$out/sky-equirect-4.png"
$skylit spectrum --sun-altitude 30 --plot "$out/spectrum-30.svg"
$skylit spectrum --sun-altitude 30 --plot "$out/spectrum-30.png"
# The paper's Fig. 7 as a sweep: the sheet as fig7.png, its cells in fig7/.
rm -rf "$out/fig7" && mkdir -p "$out/fig7"
$skylit sweep examples/fig7.json --vary sun.altitude_deg=17,60,4 --vary materials.walls=tile,aluminium \
  --set render.width=960 --set render.height=540 --title "Fig. 7: sun altitude × wall material" --quiet \
  -o "$out/fig7/fig7.png"
mv "$out/fig7/fig7.png" "$out/fig7.png"
# The paper's Fig. 8: fog thinning and thickening with height, and light beams.
for figure in fig8a fig8b fig8c fig8d; do
  $skylit render "examples/$figure.json" --quiet --set render.width=960 --set render.height=540 -o "$out/$figure.png"
done
# The paper's Fig. 9: a street at night, lamps and headlights in light fog.
$skylit render examples/fig9.json --quiet --set render.width=960 --set render.height=540 -o "$out/fig9.png"
# The assessment outputs (docs/images.md, docs/statistics.md): Fig. 9 as a person in the
# street would see it, in false colour, and the building in a 180° fisheye.
$skylit render examples/fig9.json --quiet --set render.width=480 --set render.height=270 \
  --set render.display=human -o "$out/fig9-human.png" -o "$out/fig9.falsecolor.png"
$skylit render examples/fig9.json --quiet --set render.width=480 --set render.height=270 -o "$out/fig9-photographic.png"
$skylit render examples/building.json --quiet --set camera.projection=fisheye_equidistant \
  --set camera.vertical_fov_deg=180 --set render.width=320 --set render.height=320 -o "$out/building-fisheye.png"
# The illuminance on the surfaces seen (docs/statistics.md).
$skylit render examples/building.json --quiet --set render.width=480 --set render.height=270 \
  --set render.false_colour.quantity=illuminance -o "$out/building-illuminance.falsecolor.png"
# The paper's Fig. 10: clouds with the sun in front of and behind the camera.
for figure in fig10a fig10b; do
  $skylit render "examples/$figure.json" --quiet --set render.width=960 --set render.height=540 -o "$out/$figure.png"
done
# An architect's model with its own materials (examples/models/house.obj, from
# scripts/make-house-model.py).
$skylit render examples/house.json --quiet --set render.width=960 --set render.height=540 -o "$out/house.png"
# A city block read from CityJSON in its own CRS (examples/models/city_block.city.json,
# from scripts/make-city-block.py).
$skylit render examples/city_block.json --quiet --set render.width=960 --set render.height=540 -o "$out/city-block.png"
# A city block read from CityGML in PLATEAU's form, on its own TIN relief
# (examples/models/city_block.gml, from scripts/make-citygml-example.py).
$skylit render examples/citygml_block.json --quiet --set render.width=960 --set render.height=540 -o "$out/citygml-block.png"
# The same house at night, its ground floor's windows lit (emission, docs/model-materials.md).
$skylit render examples/house-night.json --quiet --set render.width=960 --set render.height=540 \
  -o "$out/house-night.png"
# A street under a full moon, with a car's low beams (docs/night-sky.md).
$skylit render examples/moonlit.json --quiet --set render.width=960 --set render.height=540 -o "$out/moonlit.png"
echo "Remade $out/"
