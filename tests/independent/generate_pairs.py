#!/usr/bin/env python3
"""Independent random generator of *degenerate* triangle-mesh pairs (issue 8).

Written by a second author who deliberately did not read the project's other
pair generators (tests/degenerate_pairs.h, tests/independent/check_pairs.cpp,
tests/test_degenerate.cpp), so that its blind spots differ from theirs.
Python 3 standard library only.

Usage:
    python3 tests/independent/generate_pairs.py OUTDIR SEED_FROM SEED_TO

For each seed s in [SEED_FROM, SEED_TO) it writes OUTDIR/<s>_<kind>_a.obj and
OUTDIR/<s>_<kind>_b.obj ('v x y z' with %.17g floats, 'f i j k' 1-based).
The kind is KINDS[s % len(KINDS)]; the RNG is random.Random(s) only, so the
output is deterministic.  Feed the directory to
`build/bin/hlens_check_pairs --pairs OUTDIR`.

Kinds:
  coplanar       different triangulations of overlapping regions in one plane
                 (convex polygons: fan / strip / random / centre fan; grids
                 with other diagonals; random points inserted differently)
  tiltgrid       grid vs grid tilted by 1e-10..1e-2 rad and/or lifted by
                 1e-12..1e-2 along the normal
  sliver         needles and caps with aspect 1e-12..1e-3 vs slivers or
                 ordinary triangles close by
  perp           fins standing exactly or nearly (1e-9..1e-3 rad off)
                 perpendicular on edges, vertices or interiors of a base mesh
  hinge          meshes sharing exact edges / one vertex, dihedral angle
                 exactly 0 (folded back), pi (flat), pi/2, near 0, near pi, any
  zeroarea       collinear / repeated-vertex / single-point triangles mixed in
                 (rarely a mesh made of zero-area triangles only)
  dupfaces       faces repeated (same, cycled, reversed, or on duplicated
                 vertex entries) in one or both meshes
  nearcoinc_far  small surface (size 10^U(-6,6)) and a copy offset by
                 1e-12..1e-4 of its size, both moved 10^U(2,8) sizes away
                 from the origin (the ONLY kind whose name ends in _far)
  tjunction      vertices on the interior of other edges, within and across
                 meshes
  fan            many triangles around one vertex (flat or cone, full or
                 partial, with duplicated / tiny angular gaps)
  mirror         a mesh and its mirror image (plane through or beside it)
  crossing       meshes crossing each other along a common edge or line
  identical      the same mesh twice (possibly re-ordered / re-oriented)
  subset         one mesh a subset of the faces of the other
  jitter         grid vs the same grid with vertices jittered 1e-13..1e-1
  touch          meshes touching at exactly (or nearly) one point
On top of every kind but nearcoinc_far a global similarity transform is
applied sometimes: rotation (random or exact signed axis permutation),
uniform scale 10^U(-6,6), translation up to 10^U(0,8) times the size.  It is
applied either once to the common vertex list (exact coincidences between A
and B survive) or separately to A and B with differently ordered float
arithmetic (exact coincidences may become near-coincidences).
"""

import math
import os
import random
import sys

# --------------------------------------------------------------------------
# small vector helpers (tuples of 3 floats)


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scl(a, k):
    return (a[0] * k, a[1] * k, a[2] * k)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return scl(a, 1.0 / n)


def lerp(a, b, t):
    return tuple(a[i] + (b[i] - a[i]) * t for i in range(len(a)))


def logu(rng, lo, hi):
    """10^U(lo, hi)."""
    return 10.0 ** rng.uniform(lo, hi)


def sgn(rng):
    return rng.choice((-1.0, 1.0))


def rand_unit(rng):
    while True:
        v = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        n = norm(v)
        if n > 1e-3:
            return scl(v, 1.0 / n)


def perp_unit(rng, a):
    """Random unit vector orthogonal to unit vector a."""
    while True:
        r = rand_unit(rng)
        r = sub(r, scl(a, dot(a, r)))
        if norm(r) > 1e-2:
            return unit(r)


def rotate(p, axis, ang):
    """Rodrigues rotation of p about the unit axis through the origin."""
    c = math.cos(ang)
    s = math.sin(ang)
    omc = 2.0 * math.sin(ang / 2.0) ** 2      # 1 - cos, accurate for tiny ang
    return add(add(scl(p, c), scl(cross(axis, p), s)),
               scl(axis, dot(axis, p) * omc))


def dyadic(rng, lo, hi, bits=6):
    """Random multiple of 2^-bits in [lo, hi] (exact in binary floats)."""
    return math.floor(rng.uniform(lo, hi) * 2 ** bits) / 2 ** bits


# --------------------------------------------------------------------------
# pair container: one common vertex list, face lists of A and B into it


class Pair:
    def __init__(self):
        self.V = []
        self.A = []
        self.B = []

    def v(self, p):
        self.V.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.V) - 1

    def vs(self, pts):
        return [self.v(p) for p in pts]

    def dup(self, i):
        """A new vertex entry with exactly the coordinates of vertex i."""
        return self.v(self.V[i])

    def tri(self, p, q, r):
        """Three new vertices, returns the face."""
        return (self.v(p), self.v(q), self.v(r))


# --------------------------------------------------------------------------
# planes / frames


class Frame:
    """Maps local (x, y, z) to o + x*u + y*v + z*n.  Axis-aligned frames
    (signed axis permutations, dyadic origin) map exactly."""

    def __init__(self, o, u, v, n):
        self.o, self.u, self.v, self.n = o, u, v, n

    def at(self, x, y, z=0.0):
        o, u, v, n = self.o, self.u, self.v, self.n
        return tuple(o[i] + x * u[i] + y * v[i] + z * n[i] for i in range(3))


def signed_perm(rng):
    perm = rng.sample([0, 1, 2], 3)
    rows = []
    for k in range(3):
        e = [0.0, 0.0, 0.0]
        e[perm[k]] = sgn(rng)
        rows.append(tuple(e))
    return rows


def plane_frame(rng, p_exact=0.5):
    if rng.random() < p_exact:
        u, v, n = signed_perm(rng)
        o = (0.0, 0.0, 0.0) if rng.random() < 0.5 else \
            tuple(dyadic(rng, -2, 2) for _ in range(3))
        return Frame(o, u, v, n)
    u = rand_unit(rng)
    v = perp_unit(rng, u)
    n = cross(u, v)
    o = tuple(rng.uniform(-1, 1) for _ in range(3)) if rng.random() < 0.7 \
        else (0.0, 0.0, 0.0)
    return Frame(o, u, v, n)


# --------------------------------------------------------------------------
# 2D building blocks


def convex_polygon(rng, n):
    """Convex polygon (counter-clockwise) with n vertices around the origin."""
    style = rng.random()
    if n == 4 and style < 0.35:
        w = 1.0
        h = rng.choice([1.0, 0.5, 2.0, logu(rng, -1, 1)])
        return [(0.0, 0.0), (w, 0.0), (w, h), (0.0, h)]
    if style < 0.6:
        ph = rng.uniform(0, 2 * math.pi) if rng.random() < 0.5 else 0.0
        return [(math.cos(ph + 2 * math.pi * k / n),
                 math.sin(ph + 2 * math.pi * k / n)) for k in range(n)]
    angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    return [(math.cos(a), math.sin(a)) for a in angs]


def tri_fan(idx, start=0):
    idx = idx[start:] + idx[:start]
    return [(idx[0], idx[k], idx[k + 1]) for k in range(1, len(idx) - 1)]


def tri_strip(idx, start=0):
    idx = idx[start:] + idx[:start]
    l, r, left, out = 0, len(idx) - 1, True, []
    while r - l >= 2:
        if left:
            out.append((idx[l], idx[l + 1], idx[r]))
            l += 1
        else:
            out.append((idx[l], idx[r - 1], idx[r]))
            r -= 1
        left = not left
    return out


def tri_random(rng, idx):
    if len(idx) < 3:
        return []
    k = rng.randrange(1, len(idx) - 1)
    return [(idx[0], idx[k], idx[-1])] + tri_random(rng, idx[:k + 1]) + \
        tri_random(rng, idx[k:])


def triangulate_convex(rng, idx, mode=None):
    mode = mode or rng.choice(['fan', 'strip', 'random'])
    if mode == 'fan':
        return tri_fan(idx, rng.randrange(len(idx)))
    if mode == 'strip':
        return tri_strip(idx, rng.randrange(len(idx)))
    return tri_random(rng, idx)


def canon(faces):
    return sorted(tuple(sorted(f)) for f in faces)


def orient2(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def insert_point(tris, pts, k):
    """Split the triangle of tris (indices into dict pts) containing pts[k]."""
    p = pts[k]
    for ti, (a, b, c) in enumerate(tris):
        o1 = orient2(pts[a], pts[b], p)
        o2 = orient2(pts[b], pts[c], p)
        o3 = orient2(pts[c], pts[a], p)
        if (o1 >= 0 and o2 >= 0 and o3 >= 0) or (o1 <= 0 and o2 <= 0 and o3 <= 0):
            tris[ti:ti + 1] = [(a, b, k), (b, c, k), (c, a, k)]
            return True
    return False


def grid(P, place, nx, ny, x0, y0, x1, y1, diag, rng):
    """(nx x ny)-cell grid over [x0,x1]x[y0,y1]; place(x, y) -> 3D point.
    diag: 'main', 'anti', 'alt', 'random'."""
    idx = [[P.v(place(x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny))
            for j in range(ny + 1)] for i in range(nx + 1)]
    faces = []
    for i in range(nx):
        for j in range(ny):
            a, b = idx[i][j], idx[i + 1][j]
            c, d = idx[i + 1][j + 1], idx[i][j + 1]
            if diag == 'main':
                m = True
            elif diag == 'anti':
                m = False
            elif diag == 'alt':
                m = (i + j) % 2 == 0
            else:
                m = rng.random() < 0.5
            faces += [(a, b, c), (a, c, d)] if m else [(a, b, d), (b, c, d)]
    return faces, idx


def grid_dims(rng, max_cells):
    nx = rng.randint(1, max(1, min(5, max_cells)))
    ny = rng.randint(1, max(1, min(5, max_cells // nx)))
    return nx, ny


DIAGS = ['main', 'anti', 'alt', 'random']


def bary_point(rng, a, b, c):
    """Random point strictly inside triangle abc (works in 2D or 3D)."""
    r1, r2 = rng.uniform(0.05, 0.95), rng.uniform(0.05, 0.95)
    if r1 + r2 > 1:
        r1, r2 = 1 - r1, 1 - r2
    return tuple(a[i] + (b[i] - a[i]) * r1 + (c[i] - a[i]) * r2
                 for i in range(len(a)))


# --------------------------------------------------------------------------
# generic small meshes


def base_mesh(rng, P, max_tris=20, style=None):
    """Append a small ordinary mesh to P.V and return its faces."""
    style = style or rng.choice(['grid', 'grid', 'polygon', 'cone', 'soup',
                                 'closed'])
    if style == 'grid':
        fr = plane_frame(rng)
        nx, ny = grid_dims(rng, max(1, max_tris // 2))
        amp = 0.0 if rng.random() < 0.5 else logu(rng, -3, 0)
        h = rng.choice([1.0, logu(rng, -1, 1)])
        f, _ = grid(P, lambda x, y: fr.at(x, y, amp * rng.uniform(-1, 1)),
                    nx, ny, 0.0, 0.0, 1.0, h, rng.choice(DIAGS), rng)
        return f
    if style == 'polygon':
        fr = plane_frame(rng)
        n = rng.randint(3, max(3, min(12, max_tris + 2)))
        idx = P.vs([fr.at(x, y) for x, y in convex_polygon(rng, n)])
        return triangulate_convex(rng, idx)
    if style == 'cone':
        fr = plane_frame(rng)
        n = rng.randint(3, max(3, min(14, max_tris)))
        hz = rng.choice([0.0, logu(rng, -6, 0), -logu(rng, -6, 0)])
        c = P.v(fr.at(0.0, 0.0, hz))
        ring = P.vs([fr.at(x, y) for x, y in convex_polygon(rng, n)])
        closed = rng.random() < 0.7
        return [(c, ring[k], ring[(k + 1) % n])
                for k in range(n if closed else n - 1)]
    if style == 'soup':
        k = rng.randint(1, max(1, min(8, max_tris)))
        faces = []
        for _ in range(k):
            if faces and rng.random() < 0.3:   # share an edge with a previous one
                a, b, _c = rng.choice(faces)
                faces.append((a, b, P.v(tuple(rng.uniform(0, 1) for _ in range(3)))))
            else:
                faces.append(P.tri(*[tuple(rng.uniform(0, 1) for _ in range(3))
                                     for _ in range(3)]))
        return faces
    # closed polyhedra
    which = rng.choice(['tet', 'oct', 'cube'] if max_tris >= 12 else ['tet', 'oct'])
    if which == 'tet':
        pts = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
        faces = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
    elif which == 'oct':
        pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
        faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4),
                 (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    else:
        pts = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
        quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6),
                 (0, 2, 6, 4), (1, 5, 7, 3)]
        faces = []
        for a, b, c, d in quads:
            faces += [(a, b, c), (a, c, d)] if rng.random() < 0.5 else \
                [(a, b, d), (b, c, d)]
    sc = rng.choice([1.0, 0.5, logu(rng, -1, 1)])
    idx = P.vs([scl(p, sc) for p in pts])
    return [(idx[a], idx[b], idx[c]) for a, b, c in faces]


def jitter_copy(rng, P, faces, sigma, mode='3d', frac=1.0):
    """Copy of the faces on new vertices, each moved by ~sigma."""
    used = sorted({i for f in faces for i in f})
    m = {}
    for i in used:
        p = P.V[i]
        if rng.random() < frac:
            d = rand_unit(rng)
            p = add(p, scl(d, sigma * rng.uniform(0.1, 1.0)))
        m[i] = P.v(p)
    return [(m[a], m[b], m[c]) for a, b, c in faces]


def copy_faces(P, faces):
    used = sorted({i for f in faces for i in f})
    m = {i: P.dup(i) for i in used}
    return [(m[a], m[b], m[c]) for a, b, c in faces]


# --------------------------------------------------------------------------
# kind 1: coplanar overlapping triangulations


def kind_coplanar(rng, P):
    fr = plane_frame(rng)
    var = rng.choice(['polygon', 'polygon', 'subpoly', 'grid', 'points'])
    if var in ('polygon', 'subpoly'):
        n = rng.choice([4, 4, 4, 5, 6, 7, 8, 10, 12])
        pts = convex_polygon(rng, n)
        ia = P.vs([fr.at(x, y) for x, y in pts])

        def tri_with_center(idx, pts2):
            if rng.random() < 0.2:
                cx = sum(p[0] for p in pts2) / len(pts2)
                cy = sum(p[1] for p in pts2) / len(pts2)
                c = P.v(fr.at(cx, cy))
                k = len(idx)
                return [(c, idx[j], idx[(j + 1) % k]) for j in range(k)]
            return triangulate_convex(rng, idx)

        P.A = tri_with_center(ia, pts)
        r = rng.random()
        if var == 'subpoly':
            # B: polygon on a subset of A's vertices (inside A, shares them)
            k = rng.randint(3, n)
            sel = sorted(rng.sample(range(n), k))
            P.B = tri_with_center([ia[j] for j in sel], [pts[j] for j in sel])
        elif r < 0.6:
            # same polygon, another triangulation
            for _ in range(10):
                P.B = tri_with_center(ia, pts)
                if canon(P.B) != canon(P.A):
                    break
        else:
            # overlapping polygon moved in the plane
            dx, dy = dyadic(rng, -0.8, 0.8), dyadic(rng, -0.8, 0.8)
            ang = 0.0 if rng.random() < 0.5 else rng.uniform(0, 2 * math.pi)
            s = 1.0 if rng.random() < 0.5 else rng.uniform(0.4, 1.6)
            ca, sa = math.cos(ang), math.sin(ang)
            nb = n if rng.random() < 0.5 else rng.choice([3, 4, 5, 6, 8])
            pb = pts if nb == n else convex_polygon(rng, nb)
            ib = P.vs([fr.at(s * (ca * x - sa * y) + dx, s * (sa * x + ca * y) + dy)
                       for x, y in pb])
            P.B = tri_with_center(ib, pb)
    elif var == 'grid':
        h = rng.choice([1.0, 1.0, logu(rng, -1, 1)])
        nx, ny = grid_dims(rng, 10)
        da = rng.choice(DIAGS)
        P.A, _ = grid(P, fr.at, nx, ny, 0.0, 0.0, 1.0, h, da, rng)
        if rng.random() < 0.4:      # same rectangle
            x0, y0, x1, y1 = 0.0, 0.0, 1.0, h
        else:
            x0, y0 = dyadic(rng, -0.5, 0.7), dyadic(rng, -0.5, 0.7) * h
            x1, y1 = x0 + dyadic(rng, 0.25, 1.5), y0 + dyadic(rng, 0.25, 1.5) * h
        for _ in range(10):
            mx, my = grid_dims(rng, 10)
            db = rng.choice(DIAGS)
            if (mx, my, db) != (nx, ny, da) or (x0, y0, x1, y1) != (0.0, 0.0, 1.0, h):
                break
        P.B, _ = grid(P, fr.at, mx, my, x0, y0, x1, y1, db, rng)
    else:
        # random interior points inserted in different orders / subsets
        n = rng.randint(3, 8)
        hull = convex_polygon(rng, n)
        m = rng.randint(1, 8)
        inner = []
        for _ in range(m):
            if rng.random() < 0.15:      # exactly-ish on a hull edge
                j = rng.randrange(n)
                inner.append(lerp(hull[j], hull[(j + 1) % n], 0.5))
            else:
                j = rng.randrange(1, n - 1)
                inner.append(bary_point(rng, hull[0], hull[j], hull[j + 1]))
        allp = hull + inner
        idx = P.vs([fr.at(x, y) for x, y in allp])
        pts = {idx[j]: allp[j] for j in range(len(allp))}
        for target in ('A', 'B'):
            tris = triangulate_convex(rng, idx[:n])
            order = list(range(n, n + m))
            rng.shuffle(order)
            if target == 'B' and m > 1 and rng.random() < 0.5:
                order = order[:rng.randint(0, m - 1)]
            for j in order:
                insert_point(tris, pts, idx[j])
            setattr(P, target, tris)


# --------------------------------------------------------------------------
# kind 2: nearly coplanar tilted grids


def kind_tiltgrid(rng, P):
    fr = plane_frame(rng)
    h = rng.choice([1.0, logu(rng, -1, 1)])
    nx, ny = grid_dims(rng, 10)
    P.A, _ = grid(P, fr.at, nx, ny, 0.0, 0.0, 1.0, h, rng.choice(DIAGS), rng)
    region = rng.choice(['same', 'same', 'shift', 'inner', 'outer'])
    if region == 'same':
        x0, y0, x1, y1 = 0.0, 0.0, 1.0, h
    elif region == 'shift':
        x0, y0 = rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5) * h
        x1, y1 = x0 + 1.0, y0 + h
    elif region == 'inner':
        x0, y0 = rng.uniform(0, 0.4), rng.uniform(0, 0.4) * h
        x1, y1 = rng.uniform(0.6, 1.0), rng.uniform(0.6, 1.0) * h
    else:
        x0, y0 = -rng.uniform(0, 0.5), -rng.uniform(0, 0.5) * h
        x1, y1 = 1 + rng.uniform(0, 0.5), (1 + rng.uniform(0, 0.5)) * h
    mx, my = (nx, ny) if rng.random() < 0.5 else grid_dims(rng, 10)
    what = rng.choice(['tilt', 'tilt', 'offset', 'both'])
    theta = sgn(rng) * logu(rng, -10, -2) if what != 'offset' else 0.0
    d = sgn(rng) * logu(rng, -12, -2) if what != 'tilt' else 0.0
    alpha = rng.choice([0.0, math.pi / 2, rng.uniform(0, math.pi)])
    axis = (math.cos(alpha), math.sin(alpha), 0.0)
    pivot = rng.choice([(0.5, 0.5 * h, 0.0), (0.0, 0.0, 0.0),
                        (rng.uniform(0, 1), rng.uniform(0, h), 0.0),
                        (rng.uniform(1, 3), rng.uniform(1, 3), 0.0)])

    def place(x, y):
        p = add(rotate(sub((x, y, 0.0), pivot), axis, theta), pivot)
        return fr.at(p[0], p[1], p[2] + d)

    P.B, _ = grid(P, place, mx, my, x0, y0, x1, y1, rng.choice(DIAGS), rng)


# --------------------------------------------------------------------------
# kind 3: slivers


def sliver(rng, o, u, w, L, eps, style=None):
    """Sliver with long direction u, in the plane of (u, w), aspect ~eps."""
    style = style or rng.choice(['needle', 'cap', 'cap', 'needle2'])
    p1 = add(o, scl(u, L))
    if style == 'needle':            # one tiny edge at the far end
        a = rng.uniform(0, 2 * math.pi)
        p2 = add(p1, scl(add(scl(w, math.cos(a)), scl(u, math.sin(a))), eps * L))
    elif style == 'needle2':         # two long edges eps*L apart at the tip
        p2 = add(o, scl(add(u, scl(w, eps)), L))
    else:                            # cap: apex eps*L from the long edge
        t = rng.choice([0.5, rng.uniform(0, 1), rng.uniform(-0.5, 1.5)])
        p2 = add(add(o, scl(u, t * L)), scl(w, eps * L))
    return (o, p1, p2)


def kind_sliver(rng, P):
    planar = rng.random() < 0.5
    eps = lambda: logu(rng, -12, -3)

    def dirs():
        if planar:
            a = rng.uniform(0, 2 * math.pi)
            return (math.cos(a), math.sin(a), 0.0), (-math.sin(a), math.cos(a), 0.0)
        u = rand_unit(rng)
        return u, perp_unit(rng, u)

    def rand_origin():
        return (rng.uniform(0, 1), rng.uniform(0, 1),
                0.0 if planar else rng.uniform(-0.2, 0.2))

    layout = rng.choice(['random', 'strip', 'fan', 'onedge'])
    slivers = []                     # list of (o, p1, p2, u, w, L)
    if layout == 'onedge':
        # ordinary triangle in B, caps on (parts of) its edges in A
        T = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.uniform(0, 1), rng.uniform(0.3, 1), 0.0)]
        P.B = [tuple(P.vs(T))]
        for _ in range(rng.randint(1, 6)):
            j = rng.randrange(3)
            p, q = T[j], T[(j + 1) % 3]
            t0, t1 = (0.0, 1.0) if rng.random() < 0.4 else \
                sorted([rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3)])
            a, b = lerp(p, q, t0), lerp(p, q, t1)
            if norm(sub(b, a)) == 0:
                b = q
            u = unit(sub(b, a))
            inward = unit(sub(T[(j + 2) % 3], lerp(p, q, 0.5)))
            w = rng.choice([inward, scl(inward, -1.0), (0.0, 0.0, 1.0)])
            t = rng.uniform(0, 1)
            apex = add(lerp(a, b, t), scl(w, eps() * norm(sub(b, a))))
            P.A.append(P.tri(a, b, apex))
        if rng.random() < 0.3:
            P.A.append(tuple(P.vs(T)))   # and the ordinary triangle itself
        return
    if layout == 'random':
        for _ in range(rng.randint(1, 6)):
            u, w = dirs()
            L = rng.uniform(0.3, 1.0)
            slivers.append(sliver(rng, rand_origin(), u, w, L, eps()) + (u, w, L))
    elif layout == 'fan':
        o = rand_origin()
        for _ in range(rng.randint(2, 8)):
            u, w = dirs()
            L = rng.uniform(0.3, 1.0)
            slivers.append(sliver(rng, o, u, w, L, eps(),
                                  rng.choice(['needle', 'needle2'])) + (u, w, L))
    else:  # strip: thin rectangle cut into k pieces along its length
        u, w = dirs()
        o = rand_origin()
        e = eps()
        k = rng.randint(1, 8)
        bot = [add(o, scl(u, j / k)) for j in range(k + 1)]
        top = [add(b, scl(w, e)) for b in bot]
        ib, it = P.vs(bot), P.vs(top)
        for j in range(k):
            if rng.random() < 0.5:
                P.A += [(ib[j], ib[j + 1], it[j + 1]), (ib[j], it[j + 1], it[j])]
            else:
                P.A += [(ib[j], ib[j + 1], it[j]), (ib[j + 1], it[j + 1], it[j])]
            slivers.append((bot[j], bot[j + 1], top[j + 1], u, w, 1.0 / k))
    if layout != 'strip':
        o0 = None
        for (o, p1, p2, u, w, L) in slivers:
            if layout == 'fan':
                if o0 is None:
                    o0 = P.v(o)
                P.A.append((o0, P.v(p1), P.v(p2)))
            else:
                P.A.append(P.tri(o, p1, p2))
    if rng.random() < 0.25:          # some ordinary triangles in A as well
        P.A += base_mesh(rng, P, 4, rng.choice(['soup', 'polygon']))

    bvar = rng.choice(['ordinary', 'perturb', 'flip', 'cross', 'other', 'mixed'])
    if bvar in ('ordinary', 'mixed'):
        z = 0.0 if rng.random() < 0.5 else sgn(rng) * logu(rng, -12, -2)
        q = P.vs([(-0.5, -0.5, z), (1.5, -0.5, z), (1.5, 1.5, z), (-0.5, 1.5, z)])
        P.B += [(q[0], q[1], q[2]), (q[0], q[2], q[3])] if rng.random() < 0.5 \
            else [(q[0], q[1], q[3]), (q[1], q[2], q[3])]
    if bvar in ('perturb', 'mixed'):
        for (o, p1, p2, u, w, L) in slivers:
            s = L * logu(rng, -14, -3)
            P.B.append(P.tri(*[add(p, scl(rand_unit(rng), s)) for p in (o, p1, p2)]))
    if bvar == 'flip':               # apex mirrored across the long edge
        for (o, p1, p2, u, w, L) in slivers:
            d = sub(p2, o)
            along = scl(u, dot(d, u))
            P.B.append(P.tri(o, p1, add(o, sub(scl(along, 2.0), d))))
    if bvar == 'cross':              # shifted in opposite directions -> crossing
        for (o, p1, p2, u, w, L) in slivers:
            a = L * logu(rng, -12, -3)
            P.B.append(P.tri(add(o, scl(w, a)), sub(p1, scl(w, a)), sub(p2, scl(w, a))))
    if bvar == 'other':
        for _ in range(rng.randint(1, 6)):
            u, w = dirs()
            L = rng.uniform(0.3, 1.0)
            P.B.append(P.tri(*sliver(rng, rand_origin(), u, w, L, eps())))


# --------------------------------------------------------------------------
# kind 4: perpendicular fins


def kind_perp(rng, P):
    fr = plane_frame(rng)
    bstyle = rng.choice(['tri', 'square', 'grid', 'polygon'])
    pts2 = {}
    if bstyle == 'tri':
        pl = [(0.0, 0.0), (1.0, 0.0), (rng.uniform(0, 1), rng.uniform(0.3, 1))]
        idx = P.vs([fr.at(x, y) for x, y in pl])
        pts2 = dict(zip(idx, pl))
        P.A = [tuple(idx)]
    elif bstyle == 'polygon':
        pl = convex_polygon(rng, rng.randint(4, 8))
        idx = P.vs([fr.at(x, y) for x, y in pl])
        pts2 = dict(zip(idx, pl))
        P.A = triangulate_convex(rng, idx)
    else:
        nx, ny = (1, 1) if bstyle == 'square' else grid_dims(rng, 9)
        store = {}

        def place(x, y):
            store[len(P.V)] = (x, y)
            return fr.at(x, y)
        P.A, _ = grid(P, place, nx, ny, 0.0, 0.0, 1.0, 1.0, rng.choice(DIAGS), rng)
        pts2 = store
    edges = [(f[k], f[(k + 1) % 3]) for f in P.A for k in range(3)]

    def fin_up(p, q):
        """'Up' direction of a fin on the 2D segment pq: the plane normal,
        exactly, or tilted by 1e-9..1e-3 rad across the segment."""
        tilt = 0.0 if rng.random() < 0.4 else sgn(rng) * logu(rng, -9, -3)
        e = (q[0] - p[0], q[1] - p[1])
        le = math.hypot(*e) or 1.0
        m = (-e[1] / le, e[0] / le)
        st, ct = math.sin(tilt), math.cos(tilt)
        return (st * m[0], st * m[1], ct)

    for _ in range(rng.randint(1, 4)):
        mode = rng.choice(['edge', 'subedge', 'vertex', 'interior_seg',
                           'interior_pt', 'through', 'edge_through'])
        h = logu(rng, -2, 0.5) * sgn(rng)
        f = rng.choice(P.A)
        a2, b2, c2 = pts2[f[0]], pts2[f[1]], pts2[f[2]]
        if mode in ('edge', 'subedge', 'edge_through'):
            i, j = rng.choice(edges)
            p, q = pts2[i], pts2[j]
            if mode == 'subedge':
                t0, t1 = sorted([rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3)])
                p, q = lerp(p, q, t0), lerp(p, q, t1)
        elif mode in ('interior_seg', 'through'):
            p, q = bary_point(rng, a2, b2, c2), bary_point(rng, a2, b2, c2)
        else:
            p = pts2[rng.choice(f)] if mode == 'vertex' else bary_point(rng, a2, b2, c2)
            ang = rng.uniform(0, 2 * math.pi)
            q = (p[0] + math.cos(ang), p[1] + math.sin(ang))
        up = fin_up(p, q)
        P3 = lambda xy, k: fr.at(xy[0] + k * up[0], xy[1] + k * up[1], k * up[2])
        if mode in ('edge', 'subedge', 'interior_seg'):
            t = rng.uniform(-0.2, 1.2)
            P.B.append(P.tri(P3(p, 0.0), P3(q, 0.0), P3(lerp(p, q, t), h)))
        elif mode in ('vertex', 'interior_pt'):
            a, b = rng.uniform(0.1, 1), rng.uniform(0.1, 1)
            e1 = (math.cos(ang) * a, math.sin(ang) * a)
            pa = (p[0] + e1[0], p[1] + e1[1])
            pb = (p[0] - e1[0] * b / a, p[1] - e1[1] * b / a)
            P.B.append(P.tri(P3(p, 0.0), P3(pa, h), P3(pb, h)))
        elif mode == 'through':
            k = rng.uniform(0.05, 0.95)
            P.B.append(P.tri(P3(p, -k * h), P3(q, -k * h), P3(lerp(p, q, 0.5), (1 - k) * h)))
        else:  # edge_through: quad whose middle line is the base edge
            v = [P3(p, -h), P3(q, -h), P3(q, h), P3(p, h)]
            iv = P.vs(v)
            P.B += [(iv[0], iv[1], iv[2]), (iv[0], iv[2], iv[3])]


# --------------------------------------------------------------------------
# kind 5: shared edges / vertices (hinges)


def hinge_dir(rng):
    """Direction of the B half-plane; A's is (0, 1, 0).  Returns unit vector
    (0, cos phi, sin phi), exact for phi = 0, pi/2, pi."""
    c = rng.choice(['flat', 'folded', 'right', 'nearflat', 'nearfold', 'random'])
    if c == 'flat':
        return (0.0, -1.0, 0.0)
    if c == 'folded':
        return (0.0, 1.0, 0.0)
    if c == 'right':
        return (0.0, 0.0, sgn(rng))
    if c == 'nearflat':
        phi = math.pi - logu(rng, -10, -1)
    elif c == 'nearfold':
        phi = logu(rng, -10, -1)
    else:
        phi = rng.uniform(0, math.pi)
    return (0.0, math.cos(phi), math.sin(phi) * sgn(rng))


def kind_hinge(rng, P):
    var = rng.choice(['edge', 'edge', 'strip', 'vertex'])
    dB = hinge_dir(rng)
    dA = (0.0, 1.0, 0.0)
    if var in ('edge', 'strip'):
        k = rng.randint(1, 4)
        xs = [j / k for j in range(k + 1)] if rng.random() < 0.5 else \
            [0.0] + sorted(rng.uniform(0, 1) for _ in range(k - 1)) + [1.0]
        H = P.vs([(x, 0.0, 0.0) for x in xs])

        def side(d, use):
            hs = [H[j] for j in use]
            xx = [xs[j] for j in use]
            w = rng.choice([1.0, logu(rng, -2, 0.5)])
            faces = []
            if var == 'strip':
                row = P.vs([add((x, 0.0, 0.0), scl(d, w)) for x in xx])
                for j in range(len(hs) - 1):
                    faces += [(hs[j], hs[j + 1], row[j + 1]), (hs[j], row[j + 1], row[j])]
            else:
                for j in range(len(hs) - 1):
                    ax = rng.uniform(xx[j] - 0.3, xx[j + 1] + 0.3)
                    faces.append((hs[j], hs[j + 1], P.v(add((ax, 0.0, 0.0), scl(d, w)))))
            return faces

        def subset():
            r = rng.random()
            if r < 0.5 or k == 1:
                return list(range(k + 1))
            if r < 0.75:
                return [0, k]                       # one long edge (T-junctions)
            a = rng.randint(0, k - 1)
            b = rng.randint(a + 1, k)
            return list(range(a, b + 1))

        P.A = side(dA, subset())
        P.B = side(dB, subset())
        if rng.random() < 0.3:       # the B side continues on A's side too
            P.B += side(scl(dB, -1.0), subset())
    else:
        # share only one vertex (the origin); fans of sectors in two planes
        O = P.v((0.0, 0.0, 0.0))
        rot = lambda d: (d[0], d[1] * dB[1], d[1] * dB[2])  # y-axis -> dB

        def sector(a0, a1, n, plane):
            angs = [a0 + (a1 - a0) * j / n for j in range(n + 1)]
            r = [rng.choice([1.0, rng.uniform(0.3, 1.5)]) for _ in angs]
            ring = P.vs([plane((r[j] * math.cos(a), r[j] * math.sin(a), 0.0))
                         for j, a in enumerate(angs)])
            return [(O, ring[j], ring[j + 1]) for j in range(n)]

        a0 = rng.uniform(0, math.pi)
        P.A = sector(a0, a0 + rng.uniform(0.2, 2.5), rng.randint(1, 3), lambda d: d)
        b0 = rng.choice([a0 + rng.uniform(2.5, 3.5), rng.uniform(0, 2 * math.pi), a0])
        P.B = sector(b0, b0 + rng.uniform(0.2, 2.5), rng.randint(1, 3), rot)


# --------------------------------------------------------------------------
# kind 6: zero-area triangles


def degenerate_faces(rng, P, anchors, n):
    """n zero-area (or almost) triangles, partly on anchor vertices."""
    out = []
    for _ in range(n):
        t = rng.choice(['mid', 'mid', 'beyond', 'end', 'repeat_idx', 'point_idx',
                        'point_coords', 'collinear_free', 'collinear_exact'])
        if len(anchors) >= 2:
            p, q = rng.sample(anchors, 2)
        else:
            p, q = P.v((rng.uniform(0, 1), 0.5, 0.5)), P.v((0.5, rng.uniform(0, 1), 0.5))
        if t == 'mid':
            r = P.v(lerp(P.V[p], P.V[q], rng.choice([0.5, 0.25, rng.uniform(0, 1)])))
            f = (p, r, q)
        elif t == 'beyond':
            r = P.v(lerp(P.V[p], P.V[q], rng.choice([rng.uniform(1, 2), rng.uniform(-1, 0), 2.0])))
            f = (p, q, r)
        elif t == 'end':
            f = (p, q, P.dup(p))
        elif t == 'repeat_idx':
            f = (p, p, q)
        elif t == 'point_idx':
            f = (p, p, p)
        elif t == 'point_coords':
            c = P.V[p] if rng.random() < 0.5 else lerp(P.V[p], P.V[q], rng.uniform(0, 1))
            f = (P.v(c), P.v(c), P.v(c))
        elif t == 'collinear_free':
            a = tuple(rng.uniform(0, 1) for _ in range(3))
            d = rand_unit(rng)
            f = P.tri(a, add(a, scl(d, rng.uniform(0.1, 1))), add(a, scl(d, rng.uniform(-1, 1))))
        else:  # exactly collinear: axis-aligned line, dyadic coordinates
            ax = rng.randrange(3)
            base = [dyadic(rng, 0, 1) for _ in range(3)]
            pts = []
            for _k in range(3):
                c = list(base)
                c[ax] = dyadic(rng, -0.5, 1.5)
                pts.append(tuple(c))
            f = P.tri(*pts)
        out.append(tuple(f[j] for j in rng.choice([(0, 1, 2), (1, 2, 0), (2, 1, 0)])))
    return out


def kind_zeroarea(rng, P):
    P.A = base_mesh(rng, P, 20)
    bsel = rng.choice(['same', 'jitter', 'other', 'copy'])
    if bsel == 'same':
        P.B = list(P.A)
    elif bsel == 'copy':
        P.B = copy_faces(P, P.A)
    elif bsel == 'jitter':
        P.B = jitter_copy(rng, P, P.A, logu(rng, -12, -2))
    else:
        P.B = base_mesh(rng, P, 20)
    anchors_a = sorted({i for f in P.A for i in f})
    anchors_b = sorted({i for f in P.B for i in f})
    if rng.random() < 0.06:
        # rare: a mesh made of zero-area triangles only
        P.B = degenerate_faces(rng, P, anchors_a, rng.randint(1, 4))
    else:
        P.B += degenerate_faces(rng, P, anchors_b, rng.randint(0, 5))
    P.A += degenerate_faces(rng, P, anchors_a, rng.randint(1, 6))
    rng.shuffle(P.A)


# --------------------------------------------------------------------------
# kind 7: duplicated faces


def with_duplicates(rng, P, faces, count):
    out = list(faces)
    for _ in range(count):
        a, b, c = rng.choice(faces)
        t = rng.choice(['same', 'cycled', 'reversed', 'newverts', 'newverts_rev'])
        if t == 'same':
            f = (a, b, c)
        elif t == 'cycled':
            f = (b, c, a)
        elif t == 'reversed':
            f = (a, c, b)
        elif t == 'newverts':
            f = (P.dup(a), P.dup(b), P.dup(c))
        else:
            f = (P.dup(a), P.dup(c), P.dup(b))
        out.insert(rng.randint(0, len(out)), f)
    return out


def kind_dupfaces(rng, P):
    base = base_mesh(rng, P, 16)
    n = len(base)
    cnt = lambda: rng.choice([1, 1, 2, 3, n])
    P.A = with_duplicates(rng, P, base, cnt())
    bsel = rng.choice(['base', 'dups', 'twice', 'jitter', 'single', 'other'])
    if bsel == 'base':
        P.B = list(base)
    elif bsel == 'dups':
        P.B = with_duplicates(rng, P, base, cnt())
    elif bsel == 'twice':
        P.B = base + copy_faces(P, base)
    elif bsel == 'jitter':
        jb = jitter_copy(rng, P, base, logu(rng, -12, -3))
        P.B = with_duplicates(rng, P, jb, cnt()) if rng.random() < 0.5 else jb
    elif bsel == 'single':
        f = rng.choice(base)
        P.B = [f, (f[0], f[2], f[1])]
    else:
        P.B = base_mesh(rng, P, 10)


# --------------------------------------------------------------------------
# kind 8: near-coincident far from the origin (handles its own placement)


def kind_nearcoinc_far(rng, P):
    s = logu(rng, -6, 6)
    style = rng.choice(['flat', 'flat', 'height', 'polygon', 'closed'])
    planar = style in ('flat', 'polygon')
    Q = Pair()                        # built at unit size, scaled below
    if style in ('flat', 'height'):
        nx, ny = grid_dims(rng, 10)
        amp = 0.0 if style == 'flat' else logu(rng, -3, -0.3)
        faces, _ = grid(Q, lambda x, y: (x, y, amp * rng.uniform(-1, 1)),
                        nx, ny, 0.0, 0.0, 1.0, rng.choice([1.0, logu(rng, -1, 1)]),
                        rng.choice(DIAGS), rng)
    elif style == 'polygon':
        pts = convex_polygon(rng, rng.randint(3, 12))
        idx = Q.vs([(x, y, 0.0) for x, y in pts])
        faces = triangulate_convex(rng, idx)
    else:
        faces = base_mesh(rng, Q, 16, 'closed')
    # B's faces: a copy; sometimes a few duplicated faces (new vertex entries
    # are appended to Q.V) or, for flat grids, the other diagonals
    fb = list(faces)
    r = rng.random()
    if r < 0.2:
        fb = with_duplicates(rng, Q, fb, rng.randint(1, 3))
    elif r < 0.4 and style == 'flat':
        fb = retriangulate_grid(faces)
    R = random_rotation(rng) if rng.random() < 0.6 else None
    local = [scl(matvec(R, p) if R else p, s) for p in Q.V]
    nrm = matvec(R, (0.0, 0.0, 1.0)) if R else (0.0, 0.0, 1.0)
    delta = s * logu(rng, -12, -4)
    d = scl(nrm if (planar and rng.random() < 0.6) else rand_unit(rng), delta)
    moved = [add(p, d) for p in local]
    if rng.random() < 0.5:
        local, moved = moved, local          # either side carries the offset
    T = tuple(sgn(rng) * s * logu(rng, 2, 8) for _ in range(3))
    if rng.random() < 0.5:                   # same magnitude on every axis
        m = s * logu(rng, 2, 8)
        T = tuple(sgn(rng) * m for _ in range(3))
    ia = P.vs([add(p, T) for p in local])
    ib = P.vs([add(p, T) for p in moved])
    P.A = [(ia[a], ia[b], ia[c]) for a, b, c in faces]
    P.B = [(ib[a], ib[b], ib[c]) for a, b, c in fb]


def retriangulate_grid(faces):
    """Flip the diagonal of every quad made of two consecutive faces sharing
    an edge (grid() emits cells as consecutive face pairs)."""
    out = []
    for j in range(0, len(faces) - 1, 2):
        f, g = faces[j], faces[j + 1]
        shared = set(f) & set(g)
        if len(shared) != 2:
            out += [f, g]
            continue
        a = [v for v in f if v not in shared][0]
        b = [v for v in g if v not in shared][0]
        s0, s1 = [v for v in f if v in shared]
        out += [(a, s0, b), (a, b, s1)]
    if len(faces) % 2:
        out.append(faces[-1])
    return out


# --------------------------------------------------------------------------
# kind 9: miscellaneous degeneracies


def kind_tjunction(rng, P):
    fr = plane_frame(rng)
    L = [(0.0, 0.0), (1.0, 0.0)]

    def splits(k):
        if rng.random() < 0.5:
            return [j / k for j in range(k + 1)]
        return [0.0] + sorted(rng.uniform(0.02, 0.98) for _ in range(k - 1)) + [1.0]

    def side(k, up, height, bump):
        ts = splits(k)
        line = []
        for t in ts:
            x = lerp(L[0], L[1], t)
            off = 0.0
            if bump and 0 < t < 1 and rng.random() < 0.5:
                off = sgn(rng) * logu(rng, -12, -4)   # near T-junction (crack/overlap)
            line.append(P.v(fr.at(x[0], x[1] + off)))
        apex = P.v(fr.at(rng.uniform(0.2, 0.8), up * rng.uniform(0.3, 1),
                         height))
        return [(line[j], line[j + 1], apex) for j in range(k)], line

    bump = rng.random() < 0.3
    hz = 0.0 if rng.random() < 0.6 else sgn(rng) * logu(rng, -3, 0)
    ka, kb = rng.randint(1, 6), rng.randint(1, 6)
    top, _ = side(1 if rng.random() < 0.5 else ka, 1.0, 0.0, False)
    bot, _ = side(rng.randint(1, 6), -1.0, hz, bump)
    P.A = top + bot                               # T-junctions inside A
    var = rng.choice(['conform', 'other_split', 'only_line'])
    if var == 'conform':
        top2, _ = side(kb, 1.0, 0.0, False)
        bot2, _ = side(kb, -1.0, hz, False)
        P.B = top2 + bot2
    elif var == 'other_split':
        top2, _ = side(kb, 1.0, 0.0, bump)
        P.B = top2 + side(1, -1.0, hz, False)[0]
    else:  # B: triangles having vertices on A's edges interior
        for _ in range(rng.randint(1, 4)):
            t = rng.choice([0.5, rng.uniform(0, 1)])
            x = lerp(L[0], L[1], t)
            P.B.append(P.tri(fr.at(x[0], x[1]),
                             fr.at(x[0] + rng.uniform(-1, 1), rng.uniform(-1, 1)),
                             fr.at(x[0] + rng.uniform(-1, 1), rng.uniform(-1, 1),
                                   rng.uniform(-1, 1))))


def kind_fan(rng, P):
    fr = plane_frame(rng)

    def fan(center, n, full, phase, cone):
        style = rng.choice(['regular', 'random', 'dupangle', 'tinygap'])
        span = 2 * math.pi if full else rng.uniform(0.3, 2 * math.pi)
        if style == 'regular':
            angs = [phase + span * j / n for j in range(n)]
        else:
            angs = sorted(phase + rng.uniform(0, span) for _ in range(n))
            if style == 'dupangle' and n > 2:
                j = rng.randrange(n - 1)
                angs[j + 1] = angs[j]                  # zero-area spoke triangle
            if style == 'tinygap' and n > 2:
                j = rng.randrange(n - 1)
                angs[j + 1] = angs[j] + logu(rng, -10, -2)
        r = [rng.choice([1.0, rng.uniform(0.3, 1.5)]) for _ in angs]
        ring = P.vs([fr.at(r[j] * math.cos(a), r[j] * math.sin(a), 0.0)
                     for j, a in enumerate(angs)])
        m = n if full else n - 1
        return [(center, ring[j], ring[(j + 1) % n]) for j in range(m)], ring

    cone = 0.0 if rng.random() < 0.5 else sgn(rng) * logu(rng, -8, 0)
    C = P.v(fr.at(0.0, 0.0, cone))
    full = rng.random() < 0.6
    P.A, ring = fan(C, rng.randint(3, 30), full, 0.0, cone)
    var = rng.choice(['same_center', 'same_center', 'tiny_cone', 'rim_poly', 'moved'])
    if var == 'same_center':
        P.B, _ = fan(C, rng.randint(3, 30), full, rng.uniform(0, 1), cone)
    elif var == 'tiny_cone':
        C2 = P.v(fr.at(0.0, 0.0, cone + sgn(rng) * logu(rng, -12, -3)))
        P.B = [(C2, b, c) for (_a, b, c) in P.A]
    elif var == 'rim_poly' and full and len(ring) >= 3:
        P.B = triangulate_convex(rng, ring)      # centre not a vertex of B
    else:
        eps = logu(rng, -12, -1)
        C2 = P.v(fr.at(eps * rng.uniform(-1, 1), eps * rng.uniform(-1, 1), cone))
        P.B, _ = fan(C2, rng.randint(3, 30), full, rng.uniform(0, 1), cone)


def kind_mirror(rng, P):
    P.A = base_mesh(rng, P, 20)
    used = sorted({i for f in P.A for i in f})
    pts = [P.V[i] for i in used]
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    var = rng.choice(['axis0', 'axis_through', 'axis_beside', 'random_plane'])
    if var.startswith('axis'):
        ax = rng.randrange(3)
        if var == 'axis0':
            c = 0.0
        elif var == 'axis_through':
            c = rng.choice([(lo[ax] + hi[ax]) / 2, rng.uniform(lo[ax], hi[ax])])
        else:
            c = hi[ax] + rng.choice([0.0, logu(rng, -12, -1)])
        def refl(p):
            q = list(p)
            q[ax] = 2 * c - p[ax]
            return tuple(q)
    else:
        n = rand_unit(rng)
        o = tuple(rng.uniform(lo[k], hi[k]) for k in range(3))
        def refl(p):
            return sub(p, scl(n, 2 * dot(sub(p, o), n)))
    m = {i: P.v(refl(P.V[i])) for i in used}
    keep = rng.random() < 0.5
    P.B = [(m[a], m[b], m[c]) if keep else (m[a], m[c], m[b]) for a, b, c in P.A]


def kind_crossing(rng, P):
    var = rng.choice(['x_edge', 'edge_in_face', 'general'])
    if var == 'x_edge':
        # both meshes have the edge (0,0,0)-(1,0,0) and cross through it
        E = P.vs([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)])

        def hinge(d1, d2):
            a = P.v(add((rng.uniform(0, 1), 0.0, 0.0), d1))
            b = P.v(add((rng.uniform(0, 1), 0.0, 0.0), d2))
            return [(E[0], E[1], a), (E[1], E[0], b)]
        dA = (0.0, rng.uniform(0.3, 1), 0.0)
        P.A = hinge(dA, scl(dA, -rng.uniform(0.3, 1.5)))       # flat sheet
        ang = rng.choice([math.pi / 2, rng.uniform(0.05, 3.1), logu(rng, -9, -2)])
        dB = (0.0, math.cos(ang), math.sin(ang))
        P.B = hinge(dB, scl(dB, -rng.uniform(0.3, 1.5)))
    elif var == 'edge_in_face':
        # A's edge lies inside B's faces (B = sheet containing the line)
        P.A = [P.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 0.0, 1.0)),
               P.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 0.0, -1.0))]
        if rng.random() < 0.5:
            P.A = [(P.A[0][0], P.A[0][1], P.A[0][2]), (P.A[0][0], P.A[0][1], P.A[1][2])]
        ang = rng.choice([0.0, rng.uniform(0, math.pi)])
        d = (0.0, math.cos(ang), math.sin(ang))
        e0, e1 = (-0.5, 0.0, 0.0), (1.5, 0.0, 0.0)
        iq = P.vs([sub(e0, d), sub(e1, d), add(e1, d), add(e0, d)])
        P.B = [(iq[0], iq[1], iq[2]), (iq[0], iq[2], iq[3])]
    else:
        fr1, fr2 = plane_frame(rng), plane_frame(rng)
        n1, m1 = grid_dims(rng, 8)
        n2, m2 = grid_dims(rng, 8)
        P.A, _ = grid(P, fr1.at, n1, m1, -1.0, -1.0, 1.0, 1.0, rng.choice(DIAGS), rng)
        P.B, _ = grid(P, fr2.at, n2, m2, -1.0, -1.0, 1.0, 1.0, rng.choice(DIAGS), rng)


def kind_identical(rng, P):
    P.A = base_mesh(rng, P, 36)
    r = rng.random()
    if r < 0.4:
        P.B = list(P.A)
    elif r < 0.7:
        P.B = copy_faces(P, P.A)
    else:
        P.B = [rng.choice([(a, b, c), (b, c, a), (a, c, b)]) for a, b, c in P.A]
        rng.shuffle(P.B)


def kind_subset(rng, P):
    P.A = base_mesh(rng, P, 30)
    n = len(P.A)
    k = rng.randint(1, max(1, n - 1))
    P.B = rng.sample(P.A, k)
    if rng.random() < 0.3:           # plus a nearly coincident extra face
        P.B += jitter_copy(rng, P, [rng.choice(P.A)], logu(rng, -12, -3))


def kind_jitter(rng, P):
    fr = plane_frame(rng)
    nx, ny = grid_dims(rng, 12)
    amp = 0.0 if rng.random() < 0.6 else logu(rng, -3, 0)
    heights = {}

    def z(i, j):
        if (i, j) not in heights:
            heights[(i, j)] = amp * rng.uniform(-1, 1)
        return heights[(i, j)]

    sigma = logu(rng, -13, -1) / max(nx, ny)
    mode = rng.choice(['inplane', 'normal', '3d'])
    frac = rng.choice([1.0, 0.5, 0.2])

    def place(jit):
        def f(x, y):
            key = (round(x * nx * 1024), round(y * ny * 1024))
            zz = z(*key)
            if jit and rng.random() < frac:
                dx, dy, dz = (rng.uniform(-1, 1) * sigma for _ in range(3))
                if mode == 'inplane':
                    dz = 0.0
                elif mode == 'normal':
                    dx = dy = 0.0
                return fr.at(x + dx, y + dy, zz + dz)
            return fr.at(x, y, zz)
        return f

    da = rng.choice(DIAGS)
    P.A, _ = grid(P, place(rng.random() < 0.3), nx, ny, 0.0, 0.0, 1.0, 1.0, da, rng)
    db = da if rng.random() < 0.6 else rng.choice(DIAGS)
    P.B, _ = grid(P, place(True), nx, ny, 0.0, 0.0, 1.0, 1.0, db, rng)


def kind_touch(rng, P):
    var = rng.choice(['vv', 've', 'vf', 'ee', 'planar_vv', 'planar_ve'])
    gap = 0.0 if rng.random() < 0.6 else logu(rng, -12, -3)
    z = (0.0, 0.0, 1.0)

    def cone_pts(sign, k):
        """Points in the half-space sign*z > 0 (strictly)."""
        out = []
        for _ in range(k):
            d = rand_unit(rng)
            d = (d[0], d[1], sign * (abs(d[2]) + 0.2))
            out.append(scl(d, rng.uniform(0.3, 1.0)))
        return out

    O = (0.0, 0.0, 0.0)
    if var == 'vv':
        a = cone_pts(-1, 2)
        b = cone_pts(1, 2)
        P.A = [P.tri(O, a[0], a[1])]
        P.B = [P.tri((0.0, 0.0, gap), add(b[0], (0, 0, gap)), add(b[1], (0, 0, gap)))]
    elif var in ('ve', 'vf'):
        # A: triangle in z=0 plane; B: apex touching an edge / interior
        T = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.uniform(0, 1), rng.uniform(0.3, 1), 0.0)]
        if var == 'vf':
            P.A = [P.tri(*T)]
            c = bary_point(rng, *T)
            b = cone_pts(1, 2)
        else:
            # B apex on edge T0-T1, B on the other side (y < 0) and above/below
            P.A = [P.tri(*T)]
            c = lerp(T[0], T[1], rng.choice([0.5, rng.uniform(0.05, 0.95)]))
            b = [(rng.uniform(-1, 1), -rng.uniform(0.1, 1), rng.uniform(-1, 1))
                 for _ in range(2)]
        c = add(c, (0.0, 0.0, gap) if var == 'vf' else (0.0, -gap, 0.0))
        P.B = [P.tri(c, add(c, b[0]), add(c, b[1]))]
    elif var == 'ee':
        # A in half-space z <= 0 with an edge along x; B in z >= 0 along y
        P.A = [P.tri((-rng.uniform(0.2, 1), 0.0, 0.0), (rng.uniform(0.2, 1), 0.0, 0.0),
                     (rng.uniform(-1, 1), rng.uniform(-1, 1), -rng.uniform(0.2, 1)))]
        P.B = [P.tri((0.0, -rng.uniform(0.2, 1), gap), (0.0, rng.uniform(0.2, 1), gap),
                     (rng.uniform(-1, 1), rng.uniform(-1, 1), gap + rng.uniform(0.2, 1)))]
    else:
        # coplanar: two triangles in z=0 touching at a vertex / vertex-on-edge
        a0 = rng.uniform(0, 2 * math.pi)
        w = rng.uniform(0.2, 2.5)
        P.A = [P.tri(O, (math.cos(a0), math.sin(a0), 0.0),
                     (math.cos(a0 + w), math.sin(a0 + w), 0.0))]
        if var == 'planar_vv':
            b0 = a0 + w + rng.uniform(0, 2 * math.pi - w - 0.3) + rng.choice([0.0, 0.1])
            b1 = b0 + rng.uniform(0.05, 0.3)
            s = (-gap, 0.0, 0.0)
            P.B = [P.tri(s, add(s, (math.cos(b0), math.sin(b0), 0.0)),
                         add(s, (math.cos(b1), math.sin(b1), 0.0)))]
        else:
            p, q = P.V[P.A[0][1]], P.V[P.A[0][2]]
            c = lerp(p, q, rng.uniform(0.1, 0.9))
            out = unit(sub(c, O))
            c = add(c, scl(out, gap))
            tang = unit(sub(q, p))
            P.B = [P.tri(c, add(c, add(scl(out, 0.7), scl(tang, 0.4))),
                         add(c, add(scl(out, 0.7), scl(tang, -0.4))))]
    # sometimes more separated clutter in both
    if rng.random() < 0.3:
        for F in (P.A, P.B):
            for _ in range(rng.randint(1, 3)):
                off = (rng.choice([-3.0, 3.0]), rng.uniform(-1, 1), rng.uniform(-1, 1))
                F.append(P.tri(*[add(off, tuple(rng.uniform(0, 1) for _ in range(3)))
                                 for _ in range(3)]))


KINDS = [
    ('coplanar', kind_coplanar),
    ('tiltgrid', kind_tiltgrid),
    ('sliver', kind_sliver),
    ('perp', kind_perp),
    ('hinge', kind_hinge),
    ('zeroarea', kind_zeroarea),
    ('dupfaces', kind_dupfaces),
    ('nearcoinc_far', kind_nearcoinc_far),
    ('tjunction', kind_tjunction),
    ('fan', kind_fan),
    ('mirror', kind_mirror),
    ('crossing', kind_crossing),
    ('identical', kind_identical),
    ('subset', kind_subset),
    ('jitter', kind_jitter),
    ('touch', kind_touch),
]

# --------------------------------------------------------------------------
# global similarity transform


def random_rotation(rng):
    if rng.random() < 0.25:
        return signed_perm(rng)        # exact
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(c * c for c in q))
    w, x, y, z = (c / n for c in q)
    return [(1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y))]


def matvec(M, p):
    return (dot(M[0], p), dot(M[1], p), dot(M[2], p))


def bbox_size(pts):
    if not pts:
        return 1.0
    e = max(max(p[k] for p in pts) - min(p[k] for p in pts) for k in range(3))
    return e if e > 0 else 1.0


def random_similarity(rng, size):
    R = random_rotation(rng) if rng.random() < 0.8 else [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
    sc = logu(rng, -6, 6)
    if rng.random() < 0.25:
        sc = 2.0 ** round(math.log2(sc))   # exact scale
    r = rng.random()
    if r < 0.4:
        t = (0.0, 0.0, 0.0)
    elif r < 0.7:
        t = tuple(rng.uniform(-1, 1) * sc * size for _ in range(3))
    else:
        t = tuple(sgn(rng) * logu(rng, 0, 8) * sc * size for _ in range(3))
    return R, sc, t


def xform_a(T, p):                      # R (s p) + t
    R, sc, t = T
    return add(matvec(R, scl(p, sc)), t)


def xform_b(T, p):                      # (s R) p + t, other rounding
    R, sc, t = T
    SR = [scl(row, sc) for row in R]
    return tuple(t[i] + (SR[i][0] * p[0] + SR[i][1] * p[1] + SR[i][2] * p[2])
                 for i in range(3))


# --------------------------------------------------------------------------
# pipeline


MAX_FACES = 48


def make_pair(seed):
    rng = random.Random(seed)
    name, fn = KINDS[seed % len(KINDS)]
    P = Pair()
    fn(rng, P)
    if not P.A or not P.B:
        raise RuntimeError('kind %s produced an empty mesh (seed %d)' % (name, seed))
    for F in ('A', 'B'):             # safety cap on the face count
        faces = getattr(P, F)
        if len(faces) > MAX_FACES:
            setattr(P, F, rng.sample(faces, MAX_FACES - rng.randint(0, 10)))
    if rng.random() < 0.5:
        P.A, P.B = P.B, P.A

    used_all = sorted({i for f in P.A + P.B for i in f})
    size = bbox_size([P.V[i] for i in used_all])
    # unused vertices, sometimes
    extra = {'A': [], 'B': []}
    for F in ('A', 'B'):
        if rng.random() < 0.1:
            for _ in range(rng.randint(1, 4)):
                c = P.V[rng.choice(used_all)]
                far = rng.random() < 0.3
                d = scl(rand_unit(rng), size * (logu(rng, 1, 4) if far else rng.uniform(0, 1)))
                extra[F].append(P.v(add(c, d)))
        elif rng.random() < 0.05:    # whole common list (other mesh's vertices unused)
            extra[F] = list(range(len(P.V)))

    meshes = {}
    if name.endswith('_far'):
        mode = 'none'
    else:
        r = rng.random()
        mode = 'none' if r < 0.35 else ('shared' if r < 0.75 else 'separate')
    if mode != 'none':
        T = random_similarity(rng, size)
    if mode == 'shared':
        P.V = [xform_a(T, p) for p in P.V]
    for F in ('A', 'B'):
        faces = getattr(P, F)
        used = sorted({i for f in faces for i in f} | set(extra[F]))
        if rng.random() < 0.3:
            rng.shuffle(used)
        m = {i: k for k, i in enumerate(used)}
        if mode == 'separate':
            xf = xform_a if F == 'A' else xform_b
            verts = [xf(T, P.V[i]) for i in used]
        else:
            verts = [P.V[i] for i in used]
        out = []
        perm = rng.random() < 0.2
        for (a, b, c) in faces:
            f = (m[a], m[b], m[c])
            if perm:
                f = rng.choice([f, (f[1], f[2], f[0]), (f[0], f[2], f[1])])
            out.append(f)
        if rng.random() < 0.2:
            rng.shuffle(out)
        meshes[F] = (verts, out)
    return '%d_%s' % (seed, name), meshes


def check_mesh(name, verts, faces):
    if not faces:
        raise RuntimeError('%s: no faces' % name)
    for p in verts:
        for c in p:
            if not math.isfinite(c):
                raise RuntimeError('%s: non-finite coordinate' % name)
    n = len(verts)
    for f in faces:
        for i in f:
            if not 0 <= i < n:
                raise RuntimeError('%s: bad index' % name)


def write_obj(path, verts, faces):
    lines = ['v %.17g %.17g %.17g' % (p[0] + 0.0, p[1] + 0.0, p[2] + 0.0) for p in verts]
    lines += ['f %d %d %d' % (a + 1, b + 1, c + 1) for a, b, c in faces]
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: %s OUTDIR SEED_FROM SEED_TO\n' % argv[0])
        return 2
    outdir, s0, s1 = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    status = 0
    for seed in range(s0, s1):
        try:
            base, meshes = make_pair(seed)
            for F, suf in (('A', 'a'), ('B', 'b')):
                verts, faces = meshes[F]
                check_mesh(base + '_' + suf, verts, faces)
            for F, suf in (('A', 'a'), ('B', 'b')):
                verts, faces = meshes[F]
                write_obj(os.path.join(outdir, '%s_%s.obj' % (base, suf)), verts, faces)
        except Exception as e:   # report and go on with the other seeds
            sys.stderr.write('seed %d: %s: %s\n' % (seed, type(e).__name__, e))
            status = 1
    return status


if __name__ == '__main__':
    sys.exit(main(sys.argv))
