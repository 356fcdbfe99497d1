#!/usr/bin/env python3
"""Random generator of *degenerate* triangle-mesh pairs for hlens_check_pairs (set 10).

Usage:  python3 generate_pairs10.py OUTDIR SEED_FROM SEED_TO

For every seed s in [SEED_FROM, SEED_TO) writes OUTDIR/<%06d s>_<kind>_a.obj and ..._b.obj
('v x y z' with %.17g, 'f i j k' 1-based), kind = KINDS[s % len(KINDS)], all randomness from
random.Random(s) only.  Python 3 standard library only.

Kinds (each pair is then put through a common random similarity transform: none / exact power
of two scale+shift / random rotation, scale 1e-6..1e6 and offset up to 1e8 x size; plus a few
random "decorations": face order shuffle, corner rotation, orientation flips, unused vertices,
A/B swap):

  retri_square      same planar rectangle, two different triangulations (grid diagonals,
                    resolution, centre-split cells, fans from an interior / boundary point)
  tjunction_strip   coplanar strips / triangles whose vertices lie on the other's edges
                    (exact midpoints and inexact 1/3 points -> T-junctions)
  partial_overlap   two coplanar convex polygons (fan triangulated) partially overlapping,
                    sometimes sharing a supporting line
  tilted_grid       grid vs a grid tilted about an in-plane axis by 1e-12..1e-2 rad
  lifted_grid       grid vs a grid lifted by 1e-14..1e-3 x size (maybe also shifted / tilted)
  scan_noise        noisy height field (amplitude 1e-12..1e-3) vs its simplification
  ulp_copy          mesh vs its own copy with a few coordinates moved by 1..3 ulp (after the
                    transform)
  sliver_vs_tri     sliver (aspect 1e-13..1e-3) vs an ordinary triangle in various positions
  sliver_vs_sliver  two slivers: shared long edge, parallel, crossing, stacked
  needle_star       star of needles around a point vs a disc / polygon
  fin_exact         fins at exactly 90 degrees on an edge / vertex / face interior of a grid
  fin_near          fins at 90 deg +- 1e-12..1e-2 rad, slightly lifted or penetrating
  dihedral_exact    two triangles sharing an edge at dihedral 0, pi/2, pi, 3pi/2 exactly
  dihedral_near     the same with the angle perturbed by 1e-12..1e-3 rad
  zero_area_mix     ordinary mesh plus collinear / repeated-vertex / single-point triangles
  degenerate_only   meshes made only of zero-area triangles (points, segments) vs each other
                    or vs an ordinary mesh
  dup_faces         duplicated triangles (same indices, reversed, duplicated coordinates)
  near_dup_faces    triangles plus near duplicates (relative 1e-15..1e-8)
  unused_verts      simple pair with many unused vertices (far away, on the other mesh, ...)
  cube_perturbed    subdivided closed cube vs perturbed / rescaled / resubdivided copy
  cylinder_thin     cylinders with long thin side triangles vs different segmentation
  stacked_layers    stacks of parallel grids 1e-12..1e-2 apart vs subsets / staggered copies
  cad_plate         CAD-like rectangle (or thin plate) of long thin triangles vs grid
  retri_nonplanar   non-planar height-field quads with opposite / random diagonals
  big_heightfield   300..2000 triangle height fields at different resolutions
  far_small         small ordinary pair translated 1e4..1e8 x size away from the origin
  icosphere         subdivided icosahedra (80..1280 triangles) vs other level / rotated
  segment_in_face   zero-area triangles lying in faces / on edges of the other mesh
  thin_box          box collapsed to thickness 1e-13..1e-3 vs a rectangle / another box
  equidistant_ties  symmetric configurations with many exactly tied nearest features
  coplanar_soup     random overlapping coplanar triangle soups
  folded_sheet      grid folded back onto itself (dihedral ~0) vs the flat grid
  mirror_pair       a mesh vs its mirror image (ties across the mirror plane)
  fan_thin          fan of many very thin triangles around a centre vs a coarse polygon
"""
import math
import os
import random
import sys

# ----------------------------------------------------------------------------- vector helpers


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def logu(rng, lo, hi):
    """10**uniform(lo, hi)."""
    return 10.0 ** rng.uniform(lo, hi)


def rand_unit(rng):
    while True:
        v = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        n = norm(v)
        if n > 1e-6:
            return mul(v, 1.0 / n)


def rot_matrix_axis(axis, ang):
    x, y, z = unit(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def rand_rot(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(t * t for t in q))
    w, x, y, z = (t / n for t in q)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def matvec(M, v):
    return (M[0][0] * v[0] + M[0][1] * v[1] + M[0][2] * v[2],
            M[1][0] * v[0] + M[1][1] * v[1] + M[1][2] * v[2],
            M[2][0] * v[0] + M[2][1] * v[1] + M[2][2] * v[2])


def rotate_about(p, center, axis, ang):
    M = rot_matrix_axis(axis, ang)
    return add(center, matvec(M, sub(p, center)))


# ----------------------------------------------------------------------------- mesh helpers
# A mesh is a pair (verts, faces): verts a list of 3-tuples, faces a list of 0-based triples.


def mesh():
    return ([], [])


def append(m, other):
    """Appends mesh other to m (in place), returns m."""
    base = len(m[0])
    m[0].extend(other[0])
    m[1].extend((a + base, b + base, c + base) for a, b, c in other[1])
    return m


def tri_mesh(*tris):
    m = mesh()
    for t in tris:
        base = len(m[0])
        m[0].extend(t)
        m[1].append((base, base + 1, base + 2))
    return m


def map_verts(m, f):
    return ([f(v) for v in m[0]], list(m[1]))


def copy_mesh(m):
    return (list(m[0]), list(m[1]))


def grid(nx, ny, x0=0.0, y0=0.0, w=1.0, h=1.0, diag="same", zf=None, rng=None, xs=None, ys=None):
    """Grid of (nx x ny) cells on [x0,x0+w]x[y0,y0+h]; diag: same, alt, random, anti, centre."""
    if xs is None:
        xs = [x0 + w * i / nx for i in range(nx + 1)]
    if ys is None:
        ys = [y0 + h * j / ny for j in range(ny + 1)]
    nx, ny = len(xs) - 1, len(ys) - 1
    verts = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            z = zf(xs[i], ys[j]) if zf else 0.0
            verts.append((xs[i], ys[j], z))
    faces = []

    def vid(i, j):
        return j * (nx + 1) + i

    for j in range(ny):
        for i in range(nx):
            a, b, c, d = vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)
            if diag == "same":
                d1 = True
            elif diag == "anti":
                d1 = False
            elif diag == "alt":
                d1 = (i + j) % 2 == 0
            elif diag == "random":
                d1 = rng.random() < 0.5
            else:  # centre
                cx, cy = 0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1])
                cz = zf(cx, cy) if zf else 0.0
                e = len(verts)
                verts.append((cx, cy, cz))
                faces += [(a, b, e), (b, c, e), (c, d, e), (d, a, e)]
                continue
            if d1:
                faces += [(a, b, c), (a, c, d)]
            else:
                faces += [(a, b, d), (b, c, d)]
    return (verts, faces)


def fan(center, ring, closed=True):
    verts = [center] + list(ring)
    n = len(ring)
    faces = []
    for i in range(n if closed else n - 1):
        faces.append((0, 1 + i, 1 + (i + 1) % n))
    return (verts, faces)


def polygon_fan_from_vertex(ring):
    verts = list(ring)
    return (verts, [(0, i, i + 1) for i in range(1, len(ring) - 1)])


def box(lo, hi, n=1):
    """Closed axis-aligned box, each face an n x n grid (outward orientation not guaranteed)."""
    m = mesh()
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    for axis in range(3):
        for side in (0, 1):
            g = grid(n, n)
            def f(v, axis=axis, side=side):
                u, w = v[0], v[1]
                c = [0.0, 0.0, 0.0]
                o = [(axis + 1) % 3, (axis + 2) % 3]
                c[axis] = (lo, hi)[side][axis]
                c[o[0]] = lo[o[0]] + (hi[o[0]] - lo[o[0]]) * u
                c[o[1]] = lo[o[1]] + (hi[o[1]] - lo[o[1]]) * w
                return tuple(c)
            g = map_verts(g, f)
            if side == 0:
                g = (g[0], [(a, c, b) for a, b, c in g[1]])
            append(m, g)
    return m


def cylinder(r, h, n, caps=True, phase=0.0, rings=1):
    verts, faces = [], []
    for k in range(rings + 1):
        z = h * k / rings
        for i in range(n):
            t = phase + 2 * math.pi * i / n
            verts.append((r * math.cos(t), r * math.sin(t), z))
    for k in range(rings):
        for i in range(n):
            a, b = k * n + i, k * n + (i + 1) % n
            c, d = a + n, b + n
            faces += [(a, b, d), (a, d, c)]
    if caps:
        c0 = len(verts)
        verts.append((0.0, 0.0, 0.0))
        c1 = len(verts)
        verts.append((0.0, 0.0, h))
        top = rings * n
        for i in range(n):
            faces.append((c0, (i + 1) % n, i))
            faces.append((c1, top + i, top + (i + 1) % n))
    return (verts, faces)


def icosphere(level, r=1.0):
    t = (1 + math.sqrt(5)) / 2
    vs = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
          (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    vs = [mul(unit(v), r) for v in vs]
    fs = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
          (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
          (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(level):
        cache = {}
        nf = []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                cache[key] = len(vs)
                vs.append(mul(unit(lerp(vs[a], vs[b], 0.5)), r))
            return cache[key]

        for a, b, c in fs:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        fs = nf
    return (vs, fs)


def convex_polygon(rng, n, cx=0.0, cy=0.0, r=1.0):
    angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    return [(cx + r * math.cos(a) * rng.uniform(0.7, 1.0), cy + r * math.sin(a) * rng.uniform(0.7, 1.0), 0.0)
            for a in angs]


def regular_polygon(n, r=1.0, phase=0.0, z=0.0):
    return [(r * math.cos(phase + 2 * math.pi * i / n), r * math.sin(phase + 2 * math.pi * i / n), z)
            for i in range(n)]


def rand_tri(rng, s=1.0):
    return [(rng.uniform(-s, s), rng.uniform(-s, s), rng.uniform(-s, s)) for _ in range(3)]


def heightfield(rng, amp=None):
    amp = amp if amp is not None else rng.uniform(0.05, 0.5)
    fx, fy, ph = rng.uniform(0.5, 3), rng.uniform(0.5, 3), rng.uniform(0, 6)
    return lambda x, y: amp * math.sin(fx * x * 3 + ph) * math.cos(fy * y * 3 - ph)


def ordinary_mesh(rng, small=True):
    """A random ordinary (non-degenerate) mesh."""
    c = rng.randrange(5)
    if c == 0:
        n = rng.randint(1, 4 if small else 8)
        return grid(n, rng.randint(1, n + 1), diag=rng.choice(["same", "alt", "random"]), rng=rng)
    if c == 1:
        n = rng.randint(2, 5 if small else 10)
        return grid(n, n, diag="random", rng=rng, zf=heightfield(rng))
    if c == 2:
        return box((0, 0, 0), (1, rng.uniform(0.3, 1), rng.uniform(0.3, 1)), rng.randint(1, 2 if small else 4))
    if c == 3:
        return icosphere(rng.randint(0, 1 if small else 2))
    return tri_mesh(*[rand_tri(rng) for _ in range(rng.randint(1, 4))])


# ----------------------------------------------------------------------------- kinds
# Each returns (A, B) or (A, B, post) where post(rng, A, B) -> (A, B) is applied after the
# common transform (for ulp-level edits that must survive the transform).


def k_retri_square(rng):
    w, h = 1.0, rng.choice([1.0, rng.uniform(0.1, 3.0)])
    nx, ny = rng.randint(1, 8), rng.randint(1, 8)
    A = grid(nx, ny, w=w, h=h, diag=rng.choice(["same", "alt", "random", "centre"]), rng=rng)
    c = rng.randrange(4)
    if c == 0:
        B = grid(nx, ny, w=w, h=h, diag=rng.choice(["anti", "random", "centre"]), rng=rng)
    elif c == 1:
        mx, my = rng.randint(1, 9), rng.randint(1, 9)
        B = grid(mx, my, w=w, h=h, diag=rng.choice(["same", "alt", "random", "centre"]), rng=rng)
    elif c == 2:
        # fan from an interior point over the boundary vertices of A's grid
        xs = [w * i / nx for i in range(nx + 1)]
        ys = [h * j / ny for j in range(ny + 1)]
        ring = [(x, 0.0, 0.0) for x in xs[:-1]] + [(w, y, 0.0) for y in ys[:-1]] + \
               [(x, h, 0.0) for x in reversed(xs[1:])] + [(0.0, y, 0.0) for y in reversed(ys[1:])]
        ctr = (rng.uniform(0.05, 0.95) * w, rng.uniform(0.05, 0.95) * h, 0.0)
        B = fan(ctr, ring)
    else:
        # fan from a boundary corner (long thin triangles) with random boundary points
        k = rng.randint(1, 12)
        ts = sorted(rng.random() for _ in range(k))
        ring = [(0.0, 0.0, 0.0), (w, 0.0, 0.0)] + [(w, h * t, 0.0) for t in ts] + [(w, h, 0.0)] + \
               [(w * (1 - t), h, 0.0) for t in ts] + [(0.0, h, 0.0)]
        B = polygon_fan_from_vertex(ring)
    if rng.random() < 0.2:  # slightly smaller / larger region
        e = logu(rng, -12, -2) * rng.choice([-1, 1])
        B = map_verts(B, lambda v: (v[0] * (1 + e), v[1] * (1 + e), v[2]))
    return A, B


def k_tjunction_strip(rng):
    c = rng.randrange(3)
    if c == 0:
        n, m = rng.randint(1, 10), rng.randint(1, 10)
        xa = sorted(set([0.0, 1.0] + [rng.random() for _ in range(n)]))
        xb = sorted(set([0.0, 1.0] + [rng.random() for _ in range(m)] + rng.sample(xa, min(len(xa), 2))))
        A = grid(0, 0, xs=xa, ys=[0.0, 0.1], diag=rng.choice(["same", "alt", "random"]), rng=rng)
        B = grid(0, 0, xs=xb, ys=[0.0, 0.1], diag=rng.choice(["same", "anti", "random"]), rng=rng)
        return A, B
    P = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.uniform(0.0, 1.0), rng.uniform(0.2, 1.0), 0.0)]
    A = tri_mesh(P)
    # split B at points on the edges: exact midpoints or 1/3 points (rounded -> off the edge)
    k = rng.randint(1, 3)
    pts = []
    for e in range(3):
        p, q = P[e], P[(e + 1) % 3]
        if c == 1:
            ts = [0.5] if rng.random() < 0.5 else [0.25, 0.5, 0.75][:k]
        else:
            ts = [1.0 / 3, 2.0 / 3, 0.1, 0.7][:k]
        pts.append(p)
        pts += [lerp(p, q, t) for t in ts]
    ctr = mul(add(add(P[0], P[1]), P[2]), 1.0 / 3)
    B = fan(ctr, pts)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def k_partial_overlap(rng):
    pa = convex_polygon(rng, rng.randint(3, 12))
    if rng.random() < 0.3:
        pb = convex_polygon(rng, rng.randint(3, 12), pa[0][0], pa[0][1])
    else:
        d = rng.choice([0.0, rng.uniform(0, 1.5)])
        ang = rng.uniform(0, 2 * math.pi)
        pb = [(x + d * math.cos(ang), y + d * math.sin(ang), 0.0) for x, y, _ in
              convex_polygon(rng, rng.randint(3, 12))]
    if rng.random() < 0.3:
        # B shares the supporting line y = pa_min: project its lowest vertices onto it
        ymin = min(v[1] for v in pa)
        pb = [(x, max(y, ymin), 0.0) for x, y, _ in pb]
    A = fan(mul(add(pa[0], pa[len(pa) // 2]), 0.5), pa) if rng.random() < 0.5 else polygon_fan_from_vertex(pa)
    B = polygon_fan_from_vertex(pb)
    return A, B


def k_tilted_grid(rng):
    nx, ny = rng.randint(1, 8), rng.randint(1, 8)
    A = grid(nx, ny, diag=rng.choice(["same", "alt", "random"]), rng=rng)
    B = grid(rng.randint(1, 8), rng.randint(1, 8), diag=rng.choice(["same", "anti", "random", "centre"]), rng=rng) \
        if rng.random() < 0.5 else copy_mesh(A)
    ang = logu(rng, -12, -2) * rng.choice([-1, 1])
    c = rng.randrange(4)
    if c == 0:
        center, axis = (0.5, 0.5, 0.0), (1.0, 0.0, 0.0)
    elif c == 1:
        center, axis = (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)  # hinge on the grid's boundary edge
    elif c == 2:
        center, axis = (rng.random(), rng.random(), 0.0), (math.cos(rng.uniform(0, 3)), math.sin(rng.uniform(0, 3)), 0.0)
    else:
        center, axis = (0.0, 0.0, 0.0), (1.0, 1.0, 0.0)  # diagonal
    B = map_verts(B, lambda v: rotate_about(v, center, axis, ang))
    return A, B


def k_lifted_grid(rng):
    nx, ny = rng.randint(1, 8), rng.randint(1, 8)
    A = grid(nx, ny, diag=rng.choice(["same", "alt", "random", "centre"]), rng=rng)
    d = logu(rng, -14, -3) * rng.choice([-1, 1])
    B = grid(rng.randint(1, 8), rng.randint(1, 8), diag=rng.choice(["same", "anti", "random"]), rng=rng) \
        if rng.random() < 0.5 else copy_mesh(A)
    sx = rng.choice([0.0, 0.0, rng.uniform(-0.5, 0.5), logu(rng, -14, -4)])
    sy = rng.choice([0.0, 0.0, rng.uniform(-0.5, 0.5)])
    B = map_verts(B, lambda v: (v[0] + sx, v[1] + sy, v[2] + d))
    if rng.random() < 0.3:
        ang = logu(rng, -12, -4)
        B = map_verts(B, lambda v: rotate_about(v, (0.5, 0.5, d), (0.3, 1.0, 0.0), ang))
    return A, B


def k_scan_noise(rng):
    n = rng.randint(2, 20)
    amp = logu(rng, -12, -3)
    A = grid(n, n, diag=rng.choice(["same", "random"]), rng=rng, zf=lambda x, y: amp * rng.uniform(-1, 1))
    c = rng.randrange(3)
    if c == 0:
        B = grid(1, 1, diag=rng.choice(["same", "anti"]))
    elif c == 1:
        m = rng.randint(2, 4)
        B = grid(m, m, diag="random", rng=rng)
    else:
        # simplification: keep the boundary noise, flat interior (decimated-looking fan)
        vs = A[0]
        ring = [vs[i] for i in range(n + 1)] + [vs[j * (n + 1) + n] for j in range(1, n + 1)] + \
               [vs[n * (n + 1) + i] for i in range(n - 1, -1, -1)] + [vs[j * (n + 1)] for j in range(n - 1, 0, -1)]
        B = fan((0.5, 0.5, 0.0), ring)
    return A, B


def k_ulp_copy(rng):
    A = ordinary_mesh(rng, small=rng.random() < 0.7)
    B = copy_mesh(A)

    def post(rng, A, B):
        vs = list(B[0])
        used = sorted(set(i for f in B[1] for i in f))
        for _ in range(rng.randint(1, 4)):
            i = rng.choice(used)
            v = list(vs[i])
            k = rng.randrange(3)
            for _ in range(rng.randint(1, 3)):
                v[k] = math.nextafter(v[k], rng.choice([math.inf, -math.inf]))
            vs[i] = tuple(v)
        return A, (vs, B[1])

    return A, B, post


def sliver(rng, L=1.0):
    """Sliver with long edge (0,0,0)-(L,0,0) and apex at height aspect*L (or near-collinear)."""
    asp = logu(rng, -13, -3)
    t = rng.choice([0.5, rng.uniform(-0.5, 1.5), rng.random()])
    return [(0.0, 0.0, 0.0), (L, 0.0, 0.0), (L * t, asp * L, 0.0)]


def k_sliver_vs_tri(rng):
    S = sliver(rng)
    c = rng.randrange(5)
    if c == 0:  # big coplanar triangle containing the sliver
        B = tri_mesh([(-0.5, -0.5, 0.0), (2.0, -0.5, 0.0), (0.5, 1.5, 0.0)])
    elif c == 1:  # coplanar triangle whose edge cuts across the sliver
        B = tri_mesh([(0.3, -1.0, 0.0), (0.6, 1.0, 0.0), (-1.0, 0.0, 0.0)])
    elif c == 2:  # triangle above, tilted
        B = tri_mesh([(0.0, -0.5, 0.2), (1.0, 0.0, 0.1), (0.5, 0.5, 0.5)])
    elif c == 3:  # sliver standing perpendicular in a triangle
        S = [(p[0], 0.0, p[1]) for p in S]
        B = tri_mesh([(-0.5, -0.5, 0.0), (2.0, -0.5, 0.0), (0.5, 1.5, 0.0)])
    else:  # ordinary grid with the sliver in the grid plane, sharing an edge with it
        B = grid(2, 2, x0=0.0, y0=-1.0, w=1.0, h=1.0, diag="random", rng=rng)
    A = tri_mesh(S)
    if rng.random() < 0.3:
        A = append(A, tri_mesh(sliver(rng)))
    return A, B


def k_sliver_vs_sliver(rng):
    S = sliver(rng)
    c = rng.randrange(5)
    asp = logu(rng, -13, -3)
    if c == 0:  # shared long edge, apex on the other side
        T = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.random(), -asp, 0.0)]
    elif c == 1:  # shared long edge, apex on the same side (overlap)
        T = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.random(), asp, 0.0)]
    elif c == 2:  # parallel, lifted
        d = logu(rng, -14, -2)
        T = [(p[0] + rng.uniform(-0.3, 0.3), p[1], p[2] + d) for p in sliver(rng)]
    elif c == 3:  # crossing at an angle in plane
        a = rng.uniform(0.01, 3.0)
        T = [rotate_about(p, (0.5, 0.0, 0.0), (0, 0, 1), a) for p in sliver(rng)]
    else:  # crossing at a tiny angle out of plane
        a = logu(rng, -12, -3)
        T = [rotate_about(p, (0.5, 0.0, 0.0), (1, 0, 0), a) for p in sliver(rng)]
    return tri_mesh(S), tri_mesh(T)


def k_needle_star(rng):
    n = rng.randint(3, 40)
    eps = logu(rng, -13, -3)
    A = mesh()
    for i in range(n):
        a = 2 * math.pi * i / n + rng.uniform(-0.1, 0.1)
        tip = (math.cos(a), math.sin(a), 0.0)
        b = a + math.pi / 2
        # needle: two base vertices eps apart at the centre, far tip
        append(A, tri_mesh([(eps * math.cos(b), eps * math.sin(b), 0.0),
                            (-eps * math.cos(b), -eps * math.sin(b), 0.0), tip]))
    c = rng.randrange(3)
    if c == 0:
        B = fan((0.0, 0.0, 0.0), regular_polygon(rng.randint(3, 16)))
    elif c == 1:
        B = polygon_fan_from_vertex(regular_polygon(rng.randint(3, 16), 1.0, rng.uniform(0, 1)))
    else:
        z = logu(rng, -12, -2)
        B = fan((0.0, 0.0, z), regular_polygon(rng.randint(3, 16), 1.0))
    return A, B


def fin_on(rng, base_p, base_q, up, height, lean=0.0):
    """Fin triangle with base p-q, apex above the midpoint along 'up' (leaned by angle lean)."""
    m = lerp(base_p, base_q, rng.choice([0.5, rng.random()]))
    apex = add(m, mul(up, height))
    if lean:
        apex = rotate_about(apex, m, sub(base_q, base_p), lean)
    return [base_p, base_q, apex]


def k_fin_exact(rng):
    n = rng.randint(1, 5)
    G = grid(n, n, diag=rng.choice(["same", "alt", "random"]), rng=rng)
    c = rng.randrange(4)
    h = rng.choice([1.0, logu(rng, -6, 0)])
    vs = G[0]
    if c == 0:  # fin standing on a grid edge
        f = rng.choice(G[1])
        F = fin_on(rng, vs[f[0]], vs[f[1]], (0, 0, 1), h)
    elif c == 1:  # fin touching at a vertex only
        p = rng.choice(vs)
        F = [p, add(p, (0.2, 0.1, h)), add(p, (-0.1, 0.2, h))]
    elif c == 2:  # fin standing in a face interior
        f = rng.choice(G[1])
        cc = mul(add(add(vs[f[0]], vs[f[1]]), vs[f[2]]), 1.0 / 3)
        F = [cc, add(cc, (0.3 / n, 0.0, 0.0)), add(cc, (0.1 / n, 0.0, h))]
    else:  # fin hanging down through the plane
        F = [(0.3, 0.4, -h / 2), (0.6, 0.4, -h / 2), (0.45, 0.4, h / 2)]
    Fm = tri_mesh(F)
    if rng.random() < 0.3:
        Fm = append(Fm, tri_mesh([F[0], F[1], add(F[2], (0.0, 0.0, -2 * h))]))
    mode = rng.randrange(3)
    if mode == 0:
        return G, Fm
    if mode == 1:
        return append(copy_mesh(G), Fm), G
    return append(copy_mesh(G), Fm), append(copy_mesh(G), tri_mesh([F[0], F[1], add(F[2], (1e-3, 0, 0))]))


def k_fin_near(rng):
    n = rng.randint(1, 5)
    G = grid(n, n, diag=rng.choice(["same", "alt", "random"]), rng=rng)
    vs = G[0]
    lean = logu(rng, -12, -2) * rng.choice([-1, 1])
    f = rng.choice(G[1])
    F = fin_on(rng, vs[f[0]], vs[f[1]], (0, 0, 1), rng.choice([1.0, 0.1]), lean)
    off = rng.choice([0.0, logu(rng, -14, -3), -logu(rng, -14, -3)])
    F = [add(p, (0.0, 0.0, off)) for p in F]
    Fm = tri_mesh(F)
    mode = rng.randrange(3)
    if mode == 0:
        return G, Fm
    if mode == 1:
        return append(copy_mesh(G), Fm), G
    F2 = fin_on(rng, vs[f[0]], vs[f[1]], (0, 0, 1), 1.0, 0.0)
    return append(copy_mesh(G), Fm), append(copy_mesh(G), tri_mesh(F2))


def hinge_pair(rng, ang):
    """T1 in z=0 plane with edge (0,0,0)-(1,0,0) and apex at y>0; T2 shares the edge at dihedral ang."""
    L = rng.choice([1.0, rng.uniform(0.3, 3)])
    x1, y1 = rng.uniform(-0.5, 1.5), rng.uniform(0.2, 1.5)
    x2, r2 = rng.uniform(-0.5, 1.5), rng.uniform(0.2, 1.5)
    T1 = [(0.0, 0.0, 0.0), (L, 0.0, 0.0), (x1, y1, 0.0)]
    # exact coordinates for the special angles
    special = {0.0: (r2, 0.0), math.pi / 2: (0.0, r2), math.pi: (-r2, 0.0), 3 * math.pi / 2: (0.0, -r2)}
    if ang in special:
        yy, zz = special[ang]
    else:
        yy, zz = r2 * math.cos(ang), r2 * math.sin(ang)
    T2 = [(0.0, 0.0, 0.0), (L, 0.0, 0.0), (x2, yy, zz)]
    return T1, T2


def hinge_meshes(rng, T1, T2):
    c = rng.randrange(4)
    if c == 0:
        return tri_mesh(T1), tri_mesh(T2)
    if c == 1:
        return tri_mesh(T1, T2), tri_mesh(T1)
    if c == 2:
        return tri_mesh(T1, T2), tri_mesh(T2)
    # strips: two rows of triangles each side, sharing the hinge line at several vertices
    k = rng.randint(2, 6)
    xs = [T1[1][0] * i / k for i in range(k + 1)]
    a = [(x, 0.0, 0.0) for x in xs]
    b1 = [add(p, (0.0, T1[2][1], 0.0)) for p in a]
    b2 = [add(p, (0.0, T2[2][1], T2[2][2])) for p in a]
    A, B = mesh(), mesh()
    for i in range(k):
        append(A, tri_mesh([a[i], a[i + 1], b1[i]], [a[i + 1], b1[i + 1], b1[i]]))
        append(B, tri_mesh([a[i], a[i + 1], b2[i + 1]], [a[i], b2[i + 1], b2[i]]))
    if rng.random() < 0.5:
        A = append(A, copy_mesh(B))
    return A, B


def k_dihedral_exact(rng):
    ang = rng.choice([0.0, math.pi / 2, math.pi, 3 * math.pi / 2])
    return hinge_meshes(rng, *hinge_pair(rng, ang))


def k_dihedral_near(rng):
    ang = rng.choice([0.0, math.pi / 2, math.pi, 3 * math.pi / 2]) + logu(rng, -12, -3) * rng.choice([-1, 1])
    if ang < 0:
        ang += 2 * math.pi
    return hinge_meshes(rng, *hinge_pair(rng, ang))


def degenerate_tris(rng, M, k):
    """k zero-area triangles related to mesh M: collinear / repeated vertex / single point."""
    vs = M[0]
    out = mesh()
    for _ in range(k):
        c = rng.randrange(6)
        f = rng.choice(M[1])
        p, q, r = vs[f[0]], vs[f[1]], vs[f[2]]
        if c == 0:
            t = [p, q, lerp(p, q, rng.choice([0.5, rng.random()]))]  # collinear on an edge
        elif c == 1:
            t = [p, p, q]  # repeated vertex (welded to the same index)
        elif c == 2:
            t = [p, p, p]  # single point
        elif c == 3:
            t = [p, lerp(p, q, 2.0), lerp(p, q, -1.0)]  # collinear, sticking out of the mesh
        elif c == 4:
            cc = mul(add(add(p, q), r), 1.0 / 3)
            t = [cc, cc, cc]  # point in face interior (not a mesh vertex)
        else:
            d = rand_unit(rng)
            t = [p, add(p, mul(d, 0.3)), add(p, mul(d, 0.6))]  # collinear spike
        if rng.random() < 0.5:
            rng.shuffle(t)
        append(out, tri_mesh(t))
    return out


def k_zero_area_mix(rng):
    M = ordinary_mesh(rng)
    A = append(copy_mesh(M), degenerate_tris(rng, M, rng.randint(1, 8)))
    c = rng.randrange(3)
    if c == 0:
        B = copy_mesh(M)
    elif c == 1:
        e = logu(rng, -12, -3)
        B = map_verts(M, lambda v: (v[0], v[1], v[2] + e))
    else:
        B = append(copy_mesh(M), degenerate_tris(rng, M, rng.randint(1, 8)))
    # also express repeated-vertex triangles with literal index repetition
    if rng.random() < 0.5 and A[1]:
        f = rng.choice(A[1])
        A[1].append((f[0], f[0], f[1]))
        A[1].append((f[2], f[2], f[2]))
    return A, B


def k_degenerate_only(rng):
    def deg_mesh(k):
        m = mesh()
        for _ in range(k):
            c = rng.randrange(3)
            p = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
            if c == 0:
                t = [p, p, p]
            elif c == 1:
                q = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
                t = [p, q, lerp(p, q, rng.choice([0.5, rng.random(), 1.5]))]
            else:
                q = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
                t = [p, q, q]
            append(m, tri_mesh(t))
        return m

    c = rng.randrange(5)
    if c == 0:
        return deg_mesh(rng.randint(1, 6)), deg_mesh(rng.randint(1, 6))
    if c == 1:
        return deg_mesh(rng.randint(1, 6)), ordinary_mesh(rng)
    if c == 2:  # single point vs single point
        p = (rng.random(), rng.random(), rng.random())
        q = rng.choice([p, (rng.random(), rng.random(), rng.random())])
        return tri_mesh([p, p, p]), tri_mesh([q, q, q])
    if c == 3:  # segments crossing exactly / nearly
        e = rng.choice([0.0, logu(rng, -14, -4)])
        return tri_mesh([(-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)]), \
            tri_mesh([(0.0, -1.0, e), (0.0, 1.0, e), (0.0, 0.5, e)])
    # collinear triangle overlapping a real edge of B
    B = ordinary_mesh(rng)
    f = rng.choice(B[1])
    p, q = B[0][f[0]], B[0][f[1]]
    return tri_mesh([lerp(p, q, -0.2), lerp(p, q, 0.5), lerp(p, q, 1.3)]), B


def k_dup_faces(rng):
    M = ordinary_mesh(rng)
    A = copy_mesh(M)
    for _ in range(rng.randint(1, max(1, len(M[1])))):
        f = rng.choice(M[1])
        c = rng.randrange(3)
        if c == 0:
            A[1].append(f)
        elif c == 1:
            A[1].append((f[0], f[2], f[1]))
        else:  # duplicated vertex coordinates (the loader welds them back)
            append(A, tri_mesh([M[0][i] for i in f]))
    c = rng.randrange(3)
    if c == 0:
        B = copy_mesh(M)
    elif c == 1:
        B = copy_mesh(A)
        B = (B[0], B[1][::-1])
    else:
        B = append(copy_mesh(M), copy_mesh(M))
    return A, B


def k_near_dup_faces(rng):
    M = ordinary_mesh(rng)
    A = copy_mesh(M)
    eps = logu(rng, -15, -8)
    for f in rng.sample(M[1], rng.randint(1, len(M[1]))):
        t = [add(M[0][i], mul(rand_unit(rng), eps * rng.random())) for i in f]
        if rng.random() < 0.3:
            t = [M[0][f[0]], M[0][f[1]], t[2]]  # shares an edge exactly
        append(A, tri_mesh(t))
    B = copy_mesh(M) if rng.random() < 0.6 else map_verts(M, lambda v: add(v, (0.0, 0.0, eps)))
    return A, B


def k_unused_verts(rng):
    A, B = ordinary_mesh(rng), ordinary_mesh(rng)
    if rng.random() < 0.5:
        B = map_verts(A, lambda v: add(v, (0.0, 0.0, logu(rng, -8, 0))))
    for m, o in ((A, B), (B, A)):
        for _ in range(rng.randint(0, 30)):
            c = rng.randrange(4)
            if c == 0:
                m[0].append(mul(rand_unit(rng), logu(rng, 0, 8)))
            elif c == 1:
                m[0].append(rng.choice(o[0]))  # on a vertex of the other mesh
            elif c == 2:
                m[0].append(rng.choice(m[0]))  # duplicate of own vertex (welded)
            else:
                m[0].insert(0, (rng.random(), rng.random(), rng.random()))
                m[1][:] = [(a + 1, b + 1, c + 1) for a, b, c in m[1]]
    return A, B


def perturb(rng, m, eps):
    return map_verts(m, lambda v: add(v, mul(rand_unit(rng), eps * rng.random())) if rng.random() < 0.5 else v)


def k_cube_perturbed(rng):
    n = rng.randint(1, 6)
    A = box((0, 0, 0), (1, 1, 1), n)
    c = rng.randrange(4)
    if c == 0:
        B = perturb(rng, A, logu(rng, -14, -4))
    elif c == 1:
        s = 1 + logu(rng, -14, -3) * rng.choice([-1, 1])
        B = map_verts(box((0, 0, 0), (1, 1, 1), rng.randint(1, 6)), lambda v: mul(sub(v, (0.5, 0.5, 0.5)), s))
        A = map_verts(A, lambda v: sub(v, (0.5, 0.5, 0.5)))
    elif c == 2:
        B = box((0, 0, 0), (1, 1, 1), rng.randint(1, 6))
    else:
        a = logu(rng, -12, -3)
        B = map_verts(A, lambda v: rotate_about(v, (0.5, 0.5, 0.5), (0.2, 0.3, 1.0), a))
    return A, B


def k_cylinder_thin(rng):
    r = rng.choice([1.0, logu(rng, -3, 0)])
    h = rng.choice([1.0, logu(rng, 0, 3)])
    n = rng.randint(3, 64)
    caps = rng.random() < 0.6
    A = cylinder(r, h, n, caps)
    c = rng.randrange(3)
    if c == 0:
        B = cylinder(r, h, rng.randint(3, 64), caps)
    elif c == 1:
        B = cylinder(r, h, n, caps, phase=math.pi / n)
    else:
        B = perturb(rng, A, logu(rng, -13, -4) * r)
    return A, B


def k_stacked_layers(rng):
    k = rng.randint(2, 6)
    gap = logu(rng, -12, -2)
    n = rng.randint(1, 4)
    layers = []
    for i in range(k):
        g = grid(n, n, diag=rng.choice(["same", "anti", "random"]), rng=rng)
        sh = rng.choice([0.0, 0.0, rng.uniform(-0.3, 0.3)])
        layers.append(map_verts(g, lambda v, i=i, sh=sh: (v[0] + sh, v[1], v[2] + i * gap)))
    A = mesh()
    for L in layers:
        append(A, L)
    c = rng.randrange(3)
    if c == 0:
        B = copy_mesh(layers[rng.randrange(k)])
    elif c == 1:
        B = mesh()
        for L in rng.sample(layers, rng.randint(1, k)):
            append(B, L)
    else:
        B = map_verts(A, lambda v: (v[0], v[1], v[2] + gap / 2))
    return A, B


def k_cad_plate(rng):
    w, h = rng.uniform(1, 50), 1.0
    k = rng.randint(2, 40)
    xs_bot = sorted(set([0.0, w] + [rng.uniform(0, w) for _ in range(k)]))
    xs_top = sorted(set([0.0, w] + [rng.uniform(0, w) for _ in range(k)]))
    # strip triangulation between the two boundary rows (long thin triangles)
    verts = [(x, 0.0, 0.0) for x in xs_bot] + [(x, h, 0.0) for x in xs_top]
    nb = len(xs_bot)
    faces = []
    i, j = 0, 0
    while i < nb - 1 or j < len(xs_top) - 1:
        if j >= len(xs_top) - 1 or (i < nb - 1 and xs_bot[i + 1] <= xs_top[j + 1]):
            faces.append((i, i + 1, nb + j))
            i += 1
        else:
            faces.append((i, nb + j + 1, nb + j))
            j += 1
    A = (verts, faces)
    c = rng.randrange(3)
    if c == 0:
        B = grid(1, 1, w=w, h=h, diag=rng.choice(["same", "anti"]))
    elif c == 1:
        B = grid(rng.randint(1, 10), 1, w=w, h=h, diag="random", rng=rng)
    else:  # thin plate (box) of thickness t
        t = logu(rng, -9, -2)
        B = box((0, 0, -t / 2), (w, h, t / 2), 1)
    if rng.random() < 0.3:
        sq = logu(rng, -6, -2)  # squash: very long thin plate
        A = map_verts(A, lambda v: (v[0], v[1] * sq, v[2]))
        B = map_verts(B, lambda v: (v[0], v[1] * sq, v[2]))
    return A, B


def k_retri_nonplanar(rng):
    nx, ny = rng.randint(1, 10), rng.randint(1, 10)
    amp = rng.choice([0.3, logu(rng, -10, -1)])
    if rng.random() < 0.5:
        zf = heightfield(rng, amp)
    else:
        zs = {}
        zf = lambda x, y: zs.setdefault((x, y), amp * rng.uniform(-1, 1))
    A = grid(nx, ny, diag="same", zf=zf)
    B = grid(nx, ny, diag=rng.choice(["anti", "random", "alt"]), zf=zf, rng=rng)
    return A, B


def k_big_heightfield(rng):
    na = rng.randint(13, 31)
    nb = rng.randint(13, 31)
    zf = heightfield(rng, rng.choice([0.2, logu(rng, -9, -2)]))
    A = grid(na, na, diag=rng.choice(["same", "alt", "random"]), zf=zf, rng=rng)
    B = grid(nb, rng.randint(10, 31), diag=rng.choice(["same", "anti", "random", "centre"]) if nb < 22 else "random",
             zf=zf, rng=rng)
    return A, B


def k_far_small(rng):
    c = rng.randrange(3)
    if c == 0:
        A, B = tri_mesh(rand_tri(rng)), tri_mesh(rand_tri(rng))
    elif c == 1:
        A = grid(2, 2, diag="random", rng=rng)
        B = map_verts(A, lambda v: (v[0], v[1], v[2] + logu(rng, -6, -1)))
    else:
        A, B = ordinary_mesh(rng), ordinary_mesh(rng)
    return A, B


def k_icosphere(rng):
    la = rng.randint(1, 3)
    A = icosphere(la)
    c = rng.randrange(4)
    if c == 0:
        B = icosphere(rng.randint(1, 3))
    elif c == 1:
        R = rot_matrix_axis(rand_unit(rng), logu(rng, -12, -1))
        B = map_verts(A, lambda v: matvec(R, v))
    elif c == 2:
        B = map_verts(icosphere(max(1, la - 1)), lambda v: mul(v, 1 + logu(rng, -12, -2)))
    else:
        B = perturb(rng, A, logu(rng, -14, -5))
    return A, B


def k_segment_in_face(rng):
    B = ordinary_mesh(rng)
    A = mesh()
    for _ in range(rng.randint(1, 8)):
        f = rng.choice(B[1])
        p, q, r = (B[0][i] for i in f)
        def bary():
            u, v = rng.random(), rng.random()
            if u + v > 1:
                u, v = 1 - u, 1 - v
            return add(p, add(mul(sub(q, p), u), mul(sub(r, p), v)))
        c = rng.randrange(4)
        if c == 0:
            x, y = bary(), bary()
            t = [x, y, lerp(x, y, 0.5)]
        elif c == 1:
            t = [p, q, lerp(p, q, rng.random())]
        elif c == 2:
            x = bary()
            t = [x, x, x]
        else:
            t = [p, r, r]
        append(A, tri_mesh(t))
    if rng.random() < 0.3:
        append(A, copy_mesh(B))
    return A, B


def k_thin_box(rng):
    t = logu(rng, -13, -3)
    w, h = rng.uniform(0.5, 2), rng.uniform(0.5, 2)
    A = box((0, 0, 0), (w, h, t), rng.randint(1, 3))
    c = rng.randrange(3)
    if c == 0:
        B = grid(rng.randint(1, 4), rng.randint(1, 4), w=w, h=h, diag="random", rng=rng)
    elif c == 1:
        B = box((0, 0, 0), (w, h, t * rng.choice([0.5, 2.0, 1 + 1e-9])), rng.randint(1, 3))
    else:
        B = grid(2, 2, w=w, h=h, diag="random", rng=rng)
        B = map_verts(B, lambda v: (v[0], v[1], t / 2))
    return A, B


def k_equidistant_ties(rng):
    c = rng.randrange(4)
    if c == 0:  # triangle in the mid plane between two parallel triangles
        A = tri_mesh([(0.2, 0.2, 0.5), (0.7, 0.2, 0.5), (0.3, 0.6, 0.5)])
        B = append(grid(1, 1), map_verts(grid(1, 1, diag="anti"), lambda v: (v[0], v[1], 1.0)))
    elif c == 1:  # small triangle / point at the centre of a regular octahedron
        ov = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
        of = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
        B = ([tuple(map(float, v)) for v in ov], of)
        s = rng.choice([0.0, 0.1, 1e-9])
        A = tri_mesh([(s, 0.0, 0.0), (0.0, s, 0.0), (0.0, 0.0, s)])
    elif c == 2:  # regular polygon ring vs its centre point / segment
        n = rng.randint(3, 12)
        B = fan((0.0, 0.0, 1.0), regular_polygon(n), closed=True)
        A = tri_mesh([(0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, rng.choice([0.0, 0.5, 2.0]))])
    else:  # two equal triangles symmetric about a plane vs a triangle in that plane
        T = rand_tri(rng)
        A = tri_mesh([(x, y, 0.0) for x, y, _ in T])
        B = tri_mesh([(x, y, abs(z) + 0.1) for x, y, z in T], [(x, y, -abs(z) - 0.1) for x, y, z in T])
    return A, B


def k_coplanar_soup(rng):
    def soup(k):
        m = mesh()
        for _ in range(k):
            t = [(rng.uniform(0, 1), rng.uniform(0, 1), 0.0) for _ in range(3)]
            if rng.random() < 0.2:
                t[2] = lerp(t[0], t[1], rng.random())  # collinear
            append(m, tri_mesh(t))
        return m
    A, B = soup(rng.randint(1, 30)), soup(rng.randint(1, 30))
    if rng.random() < 0.3:
        append(B, copy_mesh(A))
    return A, B


def k_folded_sheet(rng):
    n = rng.randint(2, 8)
    G = grid(n, n, diag=rng.choice(["same", "alt", "random"]), rng=rng)
    fold_x = rng.choice([0.5, (n // 2) / n])
    ang = math.pi - rng.choice([0.0, logu(rng, -12, -2)])
    if ang == math.pi:
        F = map_verts(G, lambda v: (2 * fold_x - v[0], v[1], v[2]) if v[0] > fold_x else v)
    else:
        F = map_verts(G, lambda v: rotate_about(v, (fold_x, 0.0, 0.0), (0.0, 1.0, 0.0), ang) if v[0] > fold_x else v)
    return (F, G) if rng.random() < 0.5 else (F, map_verts(G, lambda v: (min(v[0], fold_x), v[1], v[2])))


def k_mirror_pair(rng):
    M = ordinary_mesh(rng)
    c = rng.randrange(3)
    if c == 0:
        B = map_verts(M, lambda v: (-v[0], v[1], v[2]))
    elif c == 1:
        B = map_verts(M, lambda v: (v[0], v[1], -v[2]))
    else:
        B = map_verts(M, lambda v: (v[1], v[0], v[2]))  # mirror about x=y
    return M, B


def k_fan_thin(rng):
    n = rng.choice([rng.randint(20, 200), rng.randint(200, 1500)])
    ring = regular_polygon(n, 1.0, rng.uniform(0, 1))
    c = rng.randrange(3)
    ctr = (0.0, 0.0, rng.choice([0.0, logu(rng, -12, -3)]))
    A = fan(ctr, ring)
    if c == 0:
        B = fan((0.0, 0.0, 0.0), regular_polygon(rng.randint(3, 12)))
    elif c == 1:
        B = polygon_fan_from_vertex(ring)  # long thin fan from a rim vertex
    else:
        B = fan((0.0, 0.0, 0.0), regular_polygon(n, 1.0 + logu(rng, -13, -4)))
    return A, B


KINDS = [
    ("retri_square", k_retri_square),
    ("tjunction_strip", k_tjunction_strip),
    ("partial_overlap", k_partial_overlap),
    ("tilted_grid", k_tilted_grid),
    ("lifted_grid", k_lifted_grid),
    ("scan_noise", k_scan_noise),
    ("ulp_copy", k_ulp_copy),
    ("sliver_vs_tri", k_sliver_vs_tri),
    ("sliver_vs_sliver", k_sliver_vs_sliver),
    ("needle_star", k_needle_star),
    ("fin_exact", k_fin_exact),
    ("fin_near", k_fin_near),
    ("dihedral_exact", k_dihedral_exact),
    ("dihedral_near", k_dihedral_near),
    ("zero_area_mix", k_zero_area_mix),
    ("degenerate_only", k_degenerate_only),
    ("dup_faces", k_dup_faces),
    ("near_dup_faces", k_near_dup_faces),
    ("unused_verts", k_unused_verts),
    ("cube_perturbed", k_cube_perturbed),
    ("cylinder_thin", k_cylinder_thin),
    ("stacked_layers", k_stacked_layers),
    ("cad_plate", k_cad_plate),
    ("retri_nonplanar", k_retri_nonplanar),
    ("big_heightfield", k_big_heightfield),
    ("far_small", k_far_small),
    ("icosphere", k_icosphere),
    ("segment_in_face", k_segment_in_face),
    ("thin_box", k_thin_box),
    ("equidistant_ties", k_equidistant_ties),
    ("coplanar_soup", k_coplanar_soup),
    ("folded_sheet", k_folded_sheet),
    ("mirror_pair", k_mirror_pair),
    ("fan_thin", k_fan_thin),
]

# ----------------------------------------------------------------------------- transform / output


def bbox_size(*ms):
    pts = [v for m in ms for v in m[0]]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    return max(max(hi[i] - lo[i] for i in range(3)), 1e-300)


def transform(rng, A, B, force_far=False):
    mode = rng.random()
    if force_far:
        mode = 0.9
    if mode < 0.2:
        return A, B
    size = bbox_size(A, B)
    if mode < 0.4:
        # exact: power of two scale, shift by a multiple of a power of two (exact additions in
        # most cases: the shifted coordinates keep few mantissa bits)
        e = rng.randint(-20, 20)
        s = 2.0 ** e
        sh = tuple(float(rng.randint(-1000, 1000)) * 2.0 ** (e + rng.randint(-2, 8)) for _ in range(3))
        f = lambda v: (v[0] * s + sh[0], v[1] * s + sh[1], v[2] * s + sh[2])
        return map_verts(A, f), map_verts(B, f)
    R = rand_rot(rng) if rng.random() < 0.8 else ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    s = logu(rng, -6, 6) / size
    off_rel = 0.0
    r = rng.random()
    if force_far:
        off_rel = logu(rng, 4, 8)
    elif r < 0.3:
        off_rel = 0.0
    elif r < 0.8:
        off_rel = logu(rng, -3, 4)
    else:
        off_rel = logu(rng, 4, 8)
    d = rand_unit(rng) if rng.random() < 0.7 else (1.0, 0.0, 0.0)
    sh = mul(d, off_rel * size * s)
    f = lambda v: add(matvec(R, mul(v, s)), sh)
    return map_verts(A, f), map_verts(B, f)


def decorate(rng, m):
    vs, fs = list(m[0]), list(m[1])
    if rng.random() < 0.25:
        rng.shuffle(fs)
    if rng.random() < 0.2:
        fs = [(f[1], f[2], f[0]) if rng.random() < 0.5 else f for f in fs]
    if rng.random() < 0.15:
        fs = [(f[0], f[2], f[1]) if rng.random() < 0.5 else f for f in fs]
    if rng.random() < 0.1 and vs:
        for _ in range(rng.randint(1, 5)):
            vs.append(rng.choice(vs))  # unused duplicate
    if rng.random() < 0.15:
        # permute vertex order
        perm = list(range(len(vs)))
        rng.shuffle(perm)
        inv = [0] * len(vs)
        for new, old in enumerate(perm):
            inv[old] = new
        vs = [vs[old] for old in perm]
        fs = [(inv[a], inv[b], inv[c]) for a, b, c in fs]
    return (vs, fs)


def check_mesh(m, name):
    vs, fs = m
    if not fs:
        raise RuntimeError("%s: no faces" % name)
    for f in fs:
        for i in f:
            if not (0 <= i < len(vs)):
                raise RuntimeError("%s: index out of range" % name)
    for v in vs:
        for x in v:
            if not math.isfinite(x):
                raise RuntimeError("%s: non-finite vertex" % name)


def write_obj(path, m):
    with open(path, "w") as f:
        for v in m[0]:
            f.write("v %.17g %.17g %.17g\n" % (float(v[0]) + 0.0, float(v[1]) + 0.0, float(v[2]) + 0.0))
        for a, b, c in m[1]:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def generate(seed):
    name, fn = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    res = fn(rng)
    post = None
    if len(res) == 3:
        A, B, post = res
    else:
        A, B = res
    A, B = transform(rng, A, B, force_far=(name == "far_small"))
    if post:
        A, B = post(rng, A, B)
    A, B = decorate(rng, A), decorate(rng, B)
    if rng.random() < 0.3:
        A, B = B, A
    check_mesh(A, "A")
    check_mesh(B, "B")
    return name, A, B


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: %s OUTDIR SEED_FROM SEED_TO\n" % argv[0])
        return 2
    out, s0, s1 = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for s in range(s0, s1):
        name, A, B = generate(s)
        base = os.path.join(out, "%06d_%s" % (s, name))
        write_obj(base + "_a.obj", A)
        write_obj(base + "_b.obj", B)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
