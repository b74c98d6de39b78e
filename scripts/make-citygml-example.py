#!/usr/bin/env python3
"""Writes examples/models/city_block.gml: a small CityGML 2.0 file in PLATEAU's form
(EPSG:6697, latitude, longitude, height), made here so that the project has a CityGML
example of its own. Around a point near Tokyo station: a TIN relief (a plane rising
3 m per 100 m to the east), three LoD2 houses with gable roofs (boundary surfaces:
ground, walls, roof), a courtyard block whose roof and ground are polygons with a hole,
a road, and an X3D material on one roof. Metres are turned into degrees with the
GRS 80 ellipsoid's radii of curvature at the origin (good to millimetres over 100 m).
Run from the repository root."""

import math
import os

LAT0, LON0 = 35.6812, 139.7671  # degrees
A, F = 6378137.0, 1 / 298.257222101  # GRS 80
E2 = F * (2 - F)
S = math.sin(math.radians(LAT0))
M = A * (1 - E2) / (1 - E2 * S * S) ** 1.5  # meridian radius of curvature
N = A / math.sqrt(1 - E2 * S * S)  # prime vertical radius
M_PER_DEG_LAT = M * math.pi / 180
M_PER_DEG_LON = N * math.cos(math.radians(LAT0)) * math.pi / 180


def terrain_z(x, y):
    return 2.0 + 0.03 * x + 0.015 * y


def pos_list(points):
    """A closed ring as lat lon h."""
    ring = list(points) + [points[0]]
    return " ".join(
        f"{LAT0 + y / M_PER_DEG_LAT:.11f} {LON0 + x / M_PER_DEG_LON:.11f} {z:.4f}" for x, y, z in ring)


def polygon(pid, exterior, holes=()):
    text = f'<gml:Polygon gml:id="{pid}"><gml:exterior><gml:LinearRing><gml:posList>{pos_list(exterior)}' \
           '</gml:posList></gml:LinearRing></gml:exterior>'
    for h in holes:
        text += f'<gml:interior><gml:LinearRing><gml:posList>{pos_list(h)}</gml:posList></gml:LinearRing></gml:interior>'
    return text + '</gml:Polygon>'


def boundary(kind, pid, exterior, holes=()):
    return (f'<bldg:boundedBy><bldg:{kind}><bldg:lod2MultiSurface><gml:MultiSurface><gml:surfaceMember>'
            f'{polygon(pid, exterior, holes)}</gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface>'
            f'</bldg:{kind}></bldg:boundedBy>\n')


def wall(p, q, z0, z1):
    """A wall under the footprint edge p→q; its front faces right of p→q (outside for
    a counter-clockwise outer ring and for a clockwise hole)."""
    return [(p[0], p[1], z0), (q[0], q[1], z0), (q[0], q[1], z1), (p[0], p[1], z1)]


def member(feature):
    return f"<core:cityObjectMember>\n{feature}</core:cityObjectMember>\n"


def gable_house(bid, x0, y0, x1, y1, eaves, ridge):
    z0 = terrain_z((x0 + x1) / 2, (y0 + y1) / 2)
    e, r, ym = z0 + eaves, z0 + ridge, (y0 + y1) / 2
    parts = [boundary("GroundSurface", f"{bid}_g", [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)])]
    parts.append(boundary("WallSurface", f"{bid}_ws", wall((x0, y0), (x1, y0), z0, e)))
    parts.append(boundary("WallSurface", f"{bid}_wn", wall((x1, y1), (x0, y1), z0, e)))
    parts.append(boundary("WallSurface", f"{bid}_ww", [(x0, y1, z0), (x0, y0, z0), (x0, y0, e), (x0, ym, r), (x0, y1, e)]))
    parts.append(boundary("WallSurface", f"{bid}_we", [(x1, y0, z0), (x1, y1, z0), (x1, y1, e), (x1, ym, r), (x1, y0, e)]))
    parts.append(boundary("RoofSurface", f"{bid}_rs", [(x0, y0, e), (x1, y0, e), (x1, ym, r), (x0, ym, r)]))
    parts.append(boundary("RoofSurface", f"{bid}_rn", [(x1, y1, e), (x0, y1, e), (x0, ym, r), (x1, ym, r)]))
    return member(f'<bldg:Building gml:id="{bid}"><bldg:measuredHeight uom="m">{ridge}</bldg:measuredHeight>\n'
                  + "".join(parts) + "</bldg:Building>\n")


def courtyard_block(bid, a0, a1, b0, b1, height):
    z0 = terrain_z((a0 + a1) / 2, (a0 + a1) / 2)
    top = z0 + height
    outer = [(a0, a0), (a1, a0), (a1, a1), (a0, a1)]  # counter-clockwise seen from above
    inner = [(b0, b0), (b0, b1), (b1, b1), (b1, b0)]  # clockwise
    parts = [boundary("RoofSurface", f"{bid}_roof", [(x, y, top) for x, y in outer], [[(x, y, top) for x, y in inner]])]
    parts.append(boundary("GroundSurface", f"{bid}_ground", [(x, y, z0) for x, y in reversed(outer)],
                          [[(x, y, z0) for x, y in reversed(inner)]]))
    for ring, name in ((outer, "o"), (inner, "i")):
        for k in range(4):
            parts.append(boundary("WallSurface", f"{bid}_w{name}{k}", wall(ring[k], ring[(k + 1) % 4], z0, top)))
    return member(f'<bldg:Building gml:id="{bid}">\n' + "".join(parts) + "</bldg:Building>\n")


def tin_relief(half, step):
    n = int(2 * half / step)
    triangles = []
    for i in range(n):
        for j in range(n):
            x0, y0 = -half + i * step, -half + j * step
            p = [(x0, y0), (x0 + step, y0), (x0 + step, y0 + step), (x0, y0 + step)]
            p = [(x, y, terrain_z(x, y)) for x, y in p]
            for tri in ((p[0], p[1], p[2]), (p[0], p[2], p[3])):  # counter-clockwise seen from above
                triangles.append(f'<gml:Triangle><gml:exterior><gml:LinearRing><gml:posList>{pos_list(tri)}'
                                 '</gml:posList></gml:LinearRing></gml:exterior></gml:Triangle>')
    return member('<dem:ReliefFeature gml:id="relief"><dem:lod>1</dem:lod><dem:reliefComponent>'
                  '<dem:TINRelief gml:id="terrain"><dem:lod>1</dem:lod><dem:tin><gml:TriangulatedSurface>'
                  '<gml:trianglePatches>\n' + "\n".join(triangles) +
                  '\n</gml:trianglePatches></gml:TriangulatedSurface></dem:tin></dem:TINRelief>'
                  '</dem:reliefComponent></dem:ReliefFeature>\n')


def road(x0, x1, y0, y1):
    lift = 0.05  # asphalt above the relief
    ring = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    return member('<tran:Road gml:id="road"><tran:lod1MultiSurface><gml:MultiSurface><gml:surfaceMember>'
                  + polygon("road_surface", [(x, y, terrain_z(x, y) + lift) for x, y in ring])
                  + '</gml:surfaceMember></gml:MultiSurface></tran:lod1MultiSurface></tran:Road>\n')


HEADER = """<?xml version="1.0" encoding="UTF-8"?>
<!-- Written by scripts/make-citygml-example.py: a small city block in PLATEAU's form. -->
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml"
 xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:dem="http://www.opengis.net/citygml/relief/2.0"
 xmlns:tran="http://www.opengis.net/citygml/transportation/2.0" xmlns:app="http://www.opengis.net/citygml/appearance/2.0"
 xmlns:uro="https://www.geospatial.jp/iur/uro/3.0" xmlns:xlink="http://www.w3.org/1999/xlink">
<gml:boundedBy><gml:Envelope srsName="http://www.opengis.net/def/crs/EPSG/0/6697" srsDimension="3">
<gml:lowerCorner>{s} {w} 0</gml:lowerCorner><gml:upperCorner>{n} {e} 30</gml:upperCorner></gml:Envelope></gml:boundedBy>
"""

APPEARANCE = """<app:appearanceMember><app:Appearance><app:theme>rgbTexture</app:theme><app:surfaceDataMember>
<app:X3DMaterial gml:id="red_tiles"><gml:name>red_tiles</gml:name><app:diffuseColor>0.55 0.2 0.12</app:diffuseColor>
<app:target>#house_a_rs</app:target><app:target>#house_a_rn</app:target></app:X3DMaterial>
</app:surfaceDataMember></app:Appearance></app:appearanceMember>
"""

HALF = 60.0
text = HEADER.format(s=LAT0 - HALF / M_PER_DEG_LAT, w=LON0 - HALF / M_PER_DEG_LON, n=LAT0 + HALF / M_PER_DEG_LAT,
                     e=LON0 + HALF / M_PER_DEG_LON)
text += tin_relief(HALF, 20.0)
text += gable_house("house_a", -40, 5, -28, 13, 5.5, 8.5)
text += gable_house("house_b", -22, 8, -8, 16, 6.0, 9.5)
text += gable_house("house_c", 25, 20, 37, 30, 4.5, 7.0)
text += courtyard_block("block", -5, 25, 5, 15, 12.0)
text += road(-HALF, HALF, -30, -22)
text += APPEARANCE + "</core:CityModel>\n"

out = os.path.join("examples", "models", "city_block.gml")
with open(out, "w", encoding="utf-8") as f:
    f.write(text)
print(f"wrote {out} ({len(text)} bytes)")
