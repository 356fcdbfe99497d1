#!/usr/bin/env python3
"""Writes the demo mesh pair assets/demo_a.obj and assets/demo_b.obj (python3 standard library only).

demo_a.obj: a gently curved patch z = 0.15 sin(x) cos(y - 0.3) over [-2, 2]^2, 16 x 16 quads (512 triangles).
demo_b.obj: the flat simplification z = 0 over the same square, 4 x 4 quads (32 triangles).

h(A,B) is attained at a vertex of A (the top of a bump: B is a plane). h(B,A) is attained strictly
inside a triangle of B, below a bump, where no vertex or edge of either mesh is: the case the exact
algorithm exists for (sampling the vertices of B would miss it).
Run from anywhere: python3 scripts/make_demo.py
"""
import math
import os

HALF = 2.0


def grid(n, height):
    """(n+1)^2 vertices on [-HALF, HALF]^2 with z = height(x, y), two triangles per quad."""
    verts = []
    for j in range(n + 1):
        for i in range(n + 1):
            x = -HALF + 2 * HALF * i / n
            y = -HALF + 2 * HALF * j / n
            verts.append((x, y, height(x, y)))
    tris = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 1, a + n + 2
            tris.append((a, b, d))
            tris.append((a, d, c))
    return verts, tris


def write_obj(path, comment, verts, tris):
    with open(path, "w", newline="\n") as f:
        f.write("# %s\n# written by scripts/make_demo.py\n" % comment)
        for v in verts:
            f.write("v %.17g %.17g %.17g\n" % v)
        for t in tris:
            f.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    assets = os.path.join(root, "assets")
    os.makedirs(assets, exist_ok=True)
    a = grid(16, lambda x, y: 0.15 * math.sin(x) * math.cos(y - 0.3))
    b = grid(4, lambda x, y: 0.0)
    write_obj(os.path.join(assets, "demo_a.obj"), "demo A: z = 0.15 sin(x) cos(y - 0.3) over [-2, 2]^2, 16x16 quads", *a)
    write_obj(os.path.join(assets, "demo_b.obj"), "demo B: z = 0 over [-2, 2]^2, 4x4 quads", *b)
    print("wrote %d + %d triangles to %s" % (len(a[1]), len(b[1]), assets))


if __name__ == "__main__":
    main()
