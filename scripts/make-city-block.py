#!/usr/bin/env python3
"""Writes examples/models/city_block.city.json: a small CityJSON 2.0 city block in
Delft's coordinates (EPSG:7415, RD New + NAP height), for examples/city_block.json and
docs/city-models.md. Two rows of LoD2 gabled houses with semantic surfaces (roofs,
walls with window openings as holes and the windows set back in them, ground, a door),
a road with its traffic area, a canal, a lawn and trees placed as instances of one
template. Vertices are quantised to millimetres with a `transform`, as real files are.
Run from the repository root."""

import json
import os

ORIGIN = (85000.0, 447000.0)  # RD New, m: the block's south-west corner, in Delft
vertices, index = [], {}


def v(x, y, z):
    """The index of a vertex (x, y relative to ORIGIN, metres), quantised to mm."""
    key = (round((ORIGIN[0] + x) * 1000), round((ORIGIN[1] + y) * 1000), round(z * 1000))
    if key not in index:
        index[key] = len(vertices)
        vertices.append(list(key))
    return index[key]


def ring(points):
    return [v(*p) for p in points]


def house(x0, y0, width, depth, eaves, ridge, facing_south):
    """A gabled house, ridge along x; windows in the long walls, a door on the street side."""
    surfaces, values = [], []
    x1, y1, ym = x0 + width, y0 + depth, y0 + depth / 2

    def add(rings, semantic):
        surfaces.append([ring(r) for r in rings])
        values.append(semantic)

    add([[(x0, y0, 0), (x0, y1, 0), (x1, y1, 0), (x1, y0, 0)]], 0)  # ground, facing down
    for wall_y, outward in ((y0, -1), (y1, 1)):
        # the long walls, counter-clockwise seen from outside, with window holes
        corners = [(x0, wall_y, 0), (x1, wall_y, 0), (x1, wall_y, eaves), (x0, wall_y, eaves)]
        if outward > 0:
            corners = corners[::-1]
        holes = []
        for k in range(int(width // 3)):
            wx = x0 + 1.0 + 3.0 * k
            for wz in (1.0, 1.0 + eaves / 2):
                hole = [(wx, wall_y, wz), (wx, wall_y, wz + 1.4), (wx + 1.2, wall_y, wz + 1.4), (wx + 1.2, wall_y, wz)]
                holes.append(hole if outward < 0 else hole[::-1])
                pane = [(p[0], p[1] - outward * 0.1, p[2]) for p in hole[::-1]]  # set back 10 cm, facing out
                add([pane], 3)
        add([corners] + holes, 1)
        door_side = (outward < 0) == facing_south
        if door_side:
            dx = x0 + width - 1.6
            door = [(dx, wall_y, 0), (dx + 1.0, wall_y, 0), (dx + 1.0, wall_y, 2.2), (dx, wall_y, 2.2)]
            add([[(p[0], p[1] + outward * 0.02, p[2]) for p in (door if outward < 0 else door[::-1])]], 4)
    add([[(x0, y0, 0), (x0, y0, eaves), (x0, ym, ridge), (x0, y1, eaves), (x0, y1, 0)]], 1)  # west gable
    add([[(x1, y0, 0), (x1, y1, 0), (x1, y1, eaves), (x1, ym, ridge), (x1, y0, eaves)]], 1)  # east gable
    add([[(x0, y0, eaves), (x1, y0, eaves), (x1, ym, ridge), (x0, ym, ridge)]], 2)  # south roof
    add([[(x0, y1, eaves), (x0, ym, ridge), (x1, ym, ridge), (x1, y1, eaves)]], 2)  # north roof
    return {
        "type": "Building",
        "attributes": {"roofType": "gabled"},
        "geometry": [{
            "type": "MultiSurface", "lod": "2.2", "boundaries": surfaces,
            "semantics": {
                "surfaces": [{"type": t} for t in
                             ("GroundSurface", "WallSurface", "RoofSurface", "Window", "Door")],
                "values": values,
            },
        }],
    }


def flat(kind, points, semantic=None):
    geometry = {"type": "MultiSurface", "lod": "1", "boundaries": [[ring(points)]]}
    if semantic:
        geometry["semantics"] = {"surfaces": [{"type": semantic}], "values": [0]}
    return {"type": kind, "geometry": [geometry]}


objects = {}
for i, (width, eaves, ridge) in enumerate([(9, 6, 9), (12, 7, 10.5), (9, 5.5, 8.5), (15, 9, 12)]):
    x = [0, 10, 23, 33][i]
    objects[f"house-south-{i}"] = house(x, 12, width, 8, eaves, ridge, facing_south=True)
    objects[f"house-north-{i}"] = house(x, 34, width, 8, eaves, ridge, facing_south=False)
objects["street"] = flat("Road", [(-5, 2, 0), (55, 2, 0), (55, 10, 0), (-5, 10, 0)], "TrafficArea")
objects["canal"] = flat("WaterBody", [(-5, -12, -0.8), (55, -12, -0.8), (55, -2, -0.8), (-5, -2, -0.8)], "WaterSurface")
objects["lawn"] = flat("PlantCover", [(-5, 22, 0), (55, 22, 0), (55, 32, 0), (-5, 32, 0)])
objects["quay"] = flat("LandUse", [(-5, -2, 0), (55, -2, 0), (55, 2, 0), (-5, 2, 0)])

# A tree: a trunk and a crown (an octahedron) as one template, placed along the lawn.
template_vertices = [[0, 0, 0], [0.3, 0, 0], [0, 0.3, 0], [0, 0, 3], [0, 0, 9], [2.5, 0, 5.5],
                     [0, 2.5, 5.5], [-2.5, 0, 5.5], [0, -2.5, 5.5]]
crown = [[[4, 5, 6]], [[4, 6, 7]], [[4, 7, 8]], [[4, 8, 5]], [[3, 6, 5]], [[3, 7, 6]], [[3, 8, 7]], [[3, 5, 8]]]
template = {"type": "MultiSurface", "lod": "2", "boundaries": crown}
for k in range(5):
    objects[f"tree-{k}"] = {"type": "SolitaryVegetationObject", "geometry": [{
        "type": "GeometryInstance", "template": 0, "boundaries": [v(5 + 11 * k, 27, 0)],
        "transformationMatrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]}

document = {
    "type": "CityJSON",
    "version": "2.0",
    "transform": {"scale": [0.001, 0.001, 0.001], "translate": [0, 0, 0]},
    "metadata": {"referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415",
                 "title": "A city block for skylit's examples (scripts/make-city-block.py)"},
    "CityObjects": objects,
    "vertices": vertices,
    "geometry-templates": {"templates": [template], "vertices-templates": template_vertices},
}
os.makedirs("examples/models", exist_ok=True)
with open("examples/models/city_block.city.json", "w") as f:
    json.dump(document, f, separators=(",", ":"))
    f.write("\n")
print(f"examples/models/city_block.city.json: {len(objects)} objects, {len(vertices)} vertices")
