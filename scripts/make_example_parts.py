#!/usr/bin/env python3
"""Writes the example cells' own parts and fixture as binary STL in millimetres
(resources/cells/parts): shapes a user could have drawn in CAD, not YCB-V objects.

  bracket.stl          an L-shaped angle bracket, 60 x 40 x 50 mm, 6 mm plate
  flanged_cylinder.stl a 40 mm cylinder, 60 mm tall, on a 70 mm flange 8 mm thick
  slotted_fixture.stl  a 200 x 150 x 40 mm block with a 60 mm wide, 20 mm deep slot across its top
Every mesh is closed with outward normals; its origin is the centre of its bounding box.
"""
import math
import os
import struct
import sys


def write_stl(path, triangles):
    lo = [min(v[i] for t in triangles for v in t) for i in range(3)]
    hi = [max(v[i] for t in triangles for v in t) for i in range(3)]
    c = [(a + b) / 2 for a, b in zip(lo, hi)]
    with open(path, "wb") as f:
        f.write(b"demoplan example part, millimetres".ljust(80, b" "))
        f.write(struct.pack("<I", len(triangles)))
        for t in triangles:
            p = [[v[i] - c[i] for i in range(3)] for v in t]
            u = [p[1][i] - p[0][i] for i in range(3)]
            w = [p[2][i] - p[0][i] for i in range(3)]
            n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            ln = math.sqrt(sum(x * x for x in n)) or 1.0
            f.write(struct.pack("<3f", *[x / ln for x in n]))
            for v in p:
                f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")


def quad(a, b, c, d):
    return [(a, b, c), (a, c, d)]


def prism(profile, y0, y1, convex_parts):
    """Extrudes a counter-clockwise (x, z) profile along y; caps from convex parts (index lists)."""
    tris = []
    n = len(profile)
    for i in range(n):
        (x0, z0), (x1, z1) = profile[i], profile[(i + 1) % n]
        # Outward for a counter-clockwise (x, z) profile.
        tris += quad((x0, y0, z0), (x0, y1, z0), (x1, y1, z1), (x1, y0, z1))
    for part in convex_parts:
        for k in range(1, len(part) - 1):
            a, b, c = profile[part[0]], profile[part[k]], profile[part[k + 1]]
            tris.append(((a[0], y0, a[1]), (b[0], y0, b[1]), (c[0], y0, c[1])))  # faces -y
            tris.append(((a[0], y1, a[1]), (c[0], y1, c[1]), (b[0], y1, b[1])))  # faces +y
    return tris


def revolve(profile, segments=48):
    """Revolves an (r, z) profile from the axis at the bottom to the axis at the top about z."""
    tris = []
    for s in range(segments):
        a0, a1 = 2 * math.pi * s / segments, 2 * math.pi * (s + 1) / segments
        for (r0, z0), (r1, z1) in zip(profile, profile[1:]):
            p = lambda r, z, a: (r * math.cos(a), r * math.sin(a), z)
            if r0 == 0:
                tris.append((p(0, z0, 0), p(r1, z1, a1), p(r1, z1, a0)))
            elif r1 == 0:
                tris.append((p(r0, z0, a0), p(r0, z0, a1), p(0, z1, 0)))
            else:
                tris += quad(p(r0, z0, a0), p(r0, z0, a1), p(r1, z1, a1), p(r1, z1, a0))
    return tris


def main(out):
    os.makedirs(out, exist_ok=True)
    bracket = [(0, 0), (60, 0), (60, 6), (6, 6), (6, 50), (0, 50)]
    # Profile in (x, z), counter-clockwise; caps: the foot and the upright.
    write_stl(os.path.join(out, "bracket.stl"), prism(bracket, -20, 20, [[0, 1, 2, 3], [0, 3, 4, 5]]))
    write_stl(os.path.join(out, "flanged_cylinder.stl"),
              revolve([(0, 0), (35, 0), (35, 8), (20, 8), (20, 60), (0, 60)]))
    fixture = [(0, 0), (200, 0), (200, 40), (130, 40), (130, 20), (70, 20), (70, 40), (0, 40)]
    write_stl(os.path.join(out, "slotted_fixture.stl"),
              prism(fixture, -75, 75, [[0, 1, 2, 3, 4], [0, 4, 5], [0, 5, 6, 7]]))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "resources", "cells", "parts"))
