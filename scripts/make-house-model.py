#!/usr/bin/env python3
"""Writes examples/models/house.obj and house.mtl: a two-storey house with a gable roof,
brick below and render above, glass windows with white frames set back in their reveals,
a wooden door and a standing-seam metal roof. z is up, metres, the front faces south
(-y). The south wall's ground floor is one concave face around the door, so the house
also exercises skylit's polygon triangulation. Run from the repository root."""

import os

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


def window(side, u0, u1, z0, z1, wall_material):
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
        face("Window_Glass", [p(a, z0 + f, RECESS), p(b, z0 + f, RECESS), p(b, z1 - f, RECESS), p(a, z1 - f, RECESS)])


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
            window(side, *h, "Brick")
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
Kd 0.42 0.17 0.10
illum 1
newmtl Render
Kd 0.78 0.74 0.66
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


def main():
    walls()
    roof()
    os.makedirs("examples/models", exist_ok=True)
    with open("examples/models/house.mtl", "w") as f:
        f.write(MTL)
    with open("examples/models/house.obj", "w") as f:
        f.write("# Written by scripts/make-house-model.py: a two-storey house, z up, metres, front to the south.\n")
        f.write("mtllib house.mtl\no house\n")
        for v in vertices:
            f.write("v %.4f %.4f %.4f\n" % v)
        current = None
        for material, indices in faces:
            if material != current:
                f.write("usemtl %s\n" % material)
                current = material
            f.write("f " + " ".join(str(i) for i in indices) + "\n")
    print("examples/models/house.obj: %d vertices, %d faces" % (len(vertices), len(faces)))


if __name__ == "__main__":
    main()
