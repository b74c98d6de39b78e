#!/usr/bin/env python3
"""Writes examples/models/house.obj and house.mtl with the textures brick.png and
render.png: a two-storey house with a gable roof, brick below and render above, glass
windows with white frames set back in their reveals (the ground floor's lit from inside:
Ke, seen in examples/house-night.json), a wooden door and a standing-seam metal roof. z is up, metres, the front faces south
(-y). The south wall's ground floor is one concave face around the door, so the house
also exercises skylit's polygon triangulation. Run from the repository root."""

import os
import random
import struct
import zlib

W, D = 10.0, 8.0  # footprint: x from -W/2 to W/2, y from -D/2 to D/2
FLOOR = 3.0  # the brick storey; render above
EAVES, RIDGE = 6.0, 9.0
OVERHANG = 0.4
RECESS, FRAME = 0.12, 0.07  # window reveal depth, frame width (m)

vertices, faces = [], []  # faces: (material, [vertex indices, 1-based])


def vertex(p):
    vertices.append(p)
    return len(vertices)


def face(material, points):
    faces.append((material, [vertex(p) for p in points]))


def wall_point(side, u, z, depth=0.0):
    """A point on a wall: u along it (left to right seen from outside), z up, depth
    into the wall. side is 'S', 'N', 'E' or 'W'."""
    if side == "S":
        return (-W / 2 + u, -D / 2 + depth, z)
    if side == "N":
        return (W / 2 - u, D / 2 - depth, z)
    if side == "E":
        return (W / 2 - depth, -D / 2 + u, z)
    return (-W / 2 + depth, D / 2 - u, z)


def wall_length(side):
    return W if side in "SN" else D


def rectangles_around(u0, u1, z0, z1, holes):
    """The wall rectangle [u0, u1] × [z0, z1] minus rectangular holes, as rectangles on
    the grid of every hole edge (cells outside every hole)."""
    us = sorted({u0, u1, *[h[0] for h in holes], *[h[1] for h in holes]})
    zs = sorted({z0, z1, *[h[2] for h in holes], *[h[3] for h in holes]})
    for a, b in zip(us, us[1:]):
        for c, d in zip(zs, zs[1:]):
            if not any(h[0] <= a and b <= h[1] and h[2] <= c and d <= h[3] for h in holes):
                yield a, b, c, d


def window(side, u0, u1, z0, z1, wall_material, glass="Window_Glass"):
    """Reveal, frame and pane of a window opening [u0, u1] × [z0, z1]."""
    p = lambda u, z, depth=0.0: wall_point(side, u, z, depth)
    # The reveal: four strips from the wall face back to the frame.
    face(wall_material, [p(u0, z0), p(u0, z0, RECESS), p(u1, z0, RECESS), p(u1, z0)])  # sill
    face(wall_material, [p(u1, z1), p(u1, z1, RECESS), p(u0, z1, RECESS), p(u0, z1)])  # head
    face(wall_material, [p(u0, z1), p(u0, z1, RECESS), p(u0, z0, RECESS), p(u0, z0)])
    face(wall_material, [p(u1, z0), p(u1, z0, RECESS), p(u1, z1, RECESS), p(u1, z1)])
    # The frame: a ring of four bars in the recessed plane, and a mullion.
    f = FRAME
    for a, b, c, d in rectangles_around(u0, u1, z0, z1, [(u0 + f, u1 - f, z0 + f, z1 - f)]):
        face("Frame_White", [p(a, c, RECESS), p(b, c, RECESS), p(b, d, RECESS), p(a, d, RECESS)])
    mid = 0.5 * (u0 + u1)
    face("Frame_White", [p(mid - f / 2, z0 + f, RECESS), p(mid + f / 2, z0 + f, RECESS),
                         p(mid + f / 2, z1 - f, RECESS), p(mid - f / 2, z1 - f, RECESS)])
    for a, b in ((u0 + f, mid - f / 2), (mid + f / 2, u1 - f)):
        face(glass, [p(a, z0 + f, RECESS), p(b, z0 + f, RECESS), p(b, z1 - f, RECESS), p(a, z1 - f, RECESS)])


def quads(side, material, rectangles):
    for a, b, c, d in rectangles:
        face(material, [wall_point(side, a, c), wall_point(side, b, c), wall_point(side, b, d), wall_point(side, a, d)])


def walls():
    door = (4.4, 5.6, 0.0, 2.1)  # on the south wall
    for side in "SENW":
        length = wall_length(side)
        # Two windows per storey on each wall, at a quarter and three quarters along.
        lower = [(length * k / 4 - 0.7, length * k / 4 + 0.7, 0.9, 2.3) for k in (1, 3)]
        upper = [(length * k / 4 - 0.7, length * k / 4 + 0.7, 3.8, 5.2) for k in (1, 3)]
        if side == "S":
            # Either side of the door, rectangles around the windows; round the door,
            # one concave face whose outline runs under the lintel.
            middle = (3.5, 6.5)
            quads(side, "Brick", rectangles_around(0, middle[0], 0, FLOOR, lower[:1]))
            quads(side, "Brick", rectangles_around(middle[1], length, 0, FLOOR, lower[1:]))
            u0, u1, z0, z1 = door
            face("Brick", [wall_point(side, u, z) for (u, z) in
                           [(middle[0], 0), (u0, 0), (u0, z1), (u1, z1), (u1, 0), (middle[1], 0),
                            (middle[1], FLOOR), (middle[0], FLOOR)]])
            # The door, set back like the windows, with its reveal.
            p = lambda u, z, depth=0.0: wall_point(side, u, z, depth)
            face("Brick", [p(u1, z1), p(u1, z1, RECESS), p(u0, z1, RECESS), p(u0, z1)])
            face("Brick", [p(u0, z1), p(u0, z1, RECESS), p(u0, z0, RECESS), p(u0, z0)])
            face("Brick", [p(u1, z0), p(u1, z0, RECESS), p(u1, z1, RECESS), p(u1, z1)])
            face("Door_Wood", [p(u0, z0, RECESS), p(u1, z0, RECESS), p(u1, z1, RECESS), p(u0, z1, RECESS)])
        else:
            quads(side, "Brick", rectangles_around(0, length, 0, FLOOR, lower))
        quads(side, "Render", rectangles_around(0, length, FLOOR, EAVES, upper))
        for h in lower:
            window(side, *h, "Brick", "Window_Lit")
        for h in upper:
            window(side, *h, "Render")
        if side in "EW":  # the gable: a triangle of render above the eaves
            face("Render", [wall_point(side, 0, EAVES), wall_point(side, length, EAVES), wall_point(side, length / 2, RIDGE)])


def roof():
    """Two pitches with the overhang, each a thin slab (top and underside), and the
    standing seams as shallow ribs."""
    x0, x1 = -W / 2 - OVERHANG, W / 2 + OVERHANG
    slope = (RIDGE - EAVES) / (D / 2)
    y_edge = D / 2 + OVERHANG
    z_edge = EAVES - slope * OVERHANG
    for s in (-1, 1):  # south pitch (y < 0), north pitch
        ridge, edge = (0.0, RIDGE), (s * y_edge, z_edge)
        top = [(x0, edge[0], edge[1]), (x1, edge[0], edge[1]), (x1, ridge[0], ridge[1]), (x0, ridge[0], ridge[1])]
        if s > 0:
            top = top[::-1]
        face("Roof_Metal", top)
        face("Roof_Metal", [(x, y, z - 0.05) for (x, y, z) in top[::-1]])  # underside
        # Seams every 0.5 m: a 3 cm ridge of two narrow faces.
        x = x0 + 0.5
        while x < x1 - 0.25:
            for dx in (-0.015, 0.015):
                rib = [(x + dx, edge[0], edge[1]), (x, edge[0], edge[1] + 0.03), (x, ridge[0], ridge[1] + 0.03),
                       (x + dx, ridge[0], ridge[1])]
                face("Roof_Metal", rib if (dx > 0) == (s < 0) else rib[::-1])
            x += 0.5


MTL = """# Materials of the example house (docs/model-materials.md gives their mapping).
newmtl Brick
Kd 1 1 1
map_Kd brick.png
illum 1
newmtl Render
Kd 1 1 1
map_Kd render.png
illum 1
newmtl Frame_White
Kd 0.80 0.80 0.78
Ks 0.05 0.05 0.05
Ns 60
illum 2
newmtl Window_Glass
Kd 0.1 0.1 0.1
d 0.2
Ni 1.52
# A lit room behind the glass: 25 cd/m² of warm white (Ke is cd/m² per linear sRGB
# channel in skylit, docs/model-materials.md).
newmtl Window_Lit
Kd 0.1 0.1 0.1
d 0.2
Ni 1.52
Ke 30 24 16
newmtl Door_Wood
Kd 0.20 0.09 0.04
Ks 0.04 0.04 0.04
Ns 30
illum 2
newmtl Roof_Metal
Kd 0 0 0
Ks 0.50 0.53 0.56
Ns 80
illum 3
"""


TEXTURE_REPEAT_M = 0.9  # both textures span 0.9 m × 0.9 m of wall


def uv(points):
    """Texture coordinates of a face's corners: its points projected onto the plane of
    the two axes it is most parallel to, in units of TEXTURE_REPEAT_M (OBJ's v up)."""
    (ax, ay, az), (bx, by, bz), (cx, cy, cz) = points[0], points[1], points[2]
    n = ((by - ay) * (cz - az) - (bz - az) * (cy - ay), (bz - az) * (cx - ax) - (bx - ax) * (cz - az),
         (bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    if abs(n[2]) >= max(abs(n[0]), abs(n[1])):
        pick = lambda p: (p[0], p[1])
    elif abs(n[0]) >= abs(n[1]):
        pick = lambda p: (p[1], p[2])
    else:
        pick = lambda p: (p[0], p[2])
    return [(a / TEXTURE_REPEAT_M, b / TEXTURE_REPEAT_M) for a, b in map(pick, points)]


def write_png(path, width, height, pixel):
    """An 8-bit RGB PNG; pixel(x, y) gives (r, g, b) in sRGB 0–255, y from the top."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def srgb(linear):
    c = max(0.0, min(1.0, linear))
    return round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055))


def textures():
    """brick.png: stretcher bond, 4 bricks of 225 mm across and 12 courses of 75 mm in
    0.9 m, each brick its own shade of red-brown (linear mean about 0.40, 0.16, 0.09),
    light mortar joints. render.png: an off-white lime render with a fine grain."""
    random.seed(7)
    size = 192  # texels over 0.9 m: 4.7 mm each
    shade = {(i, j): random.uniform(0.75, 1.2) for i in range(5) for j in range(12)}
    joint = 2  # texels of mortar (about 10 mm)

    def brick(x, y):
        course = y * 12 // size
        offset = size // 8 if course % 2 else 0  # half a brick
        column = ((x + offset) % size) * 4 // size
        if (y * 12) % size < joint * 12 or (((x + offset) % size) * 4) % size < joint * 4:
            return [srgb(0.55), srgb(0.53), srgb(0.48)]
        k = shade[(column, course)] * random.uniform(0.93, 1.07)
        return [srgb(0.42 * k), srgb(0.16 * k), srgb(0.09 * k)]

    def render(x, y):
        k = random.uniform(0.96, 1.04)
        return [srgb(0.78 * k), srgb(0.74 * k), srgb(0.66 * k)]

    write_png("examples/models/brick.png", size, size, brick)
    write_png("examples/models/render.png", 64, 64, render)


def main():
    walls()
    roof()
    os.makedirs("examples/models", exist_ok=True)
    textures()
    with open("examples/models/house.mtl", "w") as f:
        f.write(MTL)
    with open("examples/models/house.obj", "w") as f:
        f.write("# Written by scripts/make-house-model.py: a two-storey house, z up, metres, front to the south.\n")
        f.write("mtllib house.mtl\no house\n")
        for v in vertices:
            f.write("v %.4f %.4f %.4f\n" % v)
        # One texture coordinate per vertex (every face has its own vertices).
        coordinates = {}
        for _, indices in faces:
            for i, t in zip(indices, uv([vertices[i - 1] for i in indices])):
                coordinates[i] = t
        for i in range(1, len(vertices) + 1):
            f.write("vt %.4f %.4f\n" % coordinates.get(i, (0.0, 0.0)))
        current = None
        for material, indices in faces:
            if material != current:
                f.write("usemtl %s\n" % material)
                current = material
            f.write("f " + " ".join("%d/%d" % (i, i) for i in indices) + "\n")
    print("examples/models/house.obj: %d vertices, %d faces" % (len(vertices), len(faces)))


if __name__ == "__main__":
    main()
