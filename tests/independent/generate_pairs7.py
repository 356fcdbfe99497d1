#!/usr/bin/env python3
"""Seventh independent generator of degenerate mesh pairs for Hausdorff Lens (issue 8).

Written BLIND by a helper: I did not read tests/independent/generate_pairs*.py,
tests/degenerate_pairs.h nor the generator part of tests/independent/check_pairs.cpp. What I read:
main(), run_pair() and the failure messages of check_pairs.cpp (the --pairs interface: DIR/NAME_a.obj
and DIR/NAME_b.obj; a NAME ending in "_far" is held to a certified interval no wider than 1e-9 of
the diagonal), the README (formats, welding of identical vertices, zero-area triangles kept,
tolerances, the lists of what the first six generators cover) and docs/degenerate-input-history.md
(the failure classes already found).

Aim: configurations the earlier generators' descriptions do not name, mostly combinations:
- many source triangles equidistant from one target point: cones, prisms and regular solids with a
  target on their axis or at their centre, points on a circle round a disc, a regular polygonal
  hole in a coplanar annulus, pyramids of tiny height over a flat polygon;
- concentric and nested shapes: solids inside rotated / scaled copies, coaxial cones, boxes in
  boxes (near-coincident ones far from the origin);
- non-manifold edges shared by 3..9 faces (books of pages round a spine), non-manifold vertices
  (bow-ties of fans sharing an apex);
- zero-area triangles inside otherwise good meshes (T-junctions filled by collinear triangles,
  collapsed edges in closed solids), a surface against its own wire frame of zero-area triangles;
- triangle soups with duplicated vertices jittered by 1e-15..1e-11 (or a few ulps far away);
- anisotropic scaling (1e3..1e6 along one axis, 1e-4..1e-1 along another);
- sheets and slivers crossing at tiny angles (1e-12..1e-2 rad), twisted strips, hinges nearly
  shut or nearly flat, mirror images in tilted mirrors, sliver fans nearly coplanar with a tilted
  grid;
- targets touching the source at one point only (apex on a vertex, an edge or a face; inverted
  cones grazing a plane at slopes down to 1e-12);
- huge triangles against clusters 1e-7..1e-5 of their size, tall spikes on grids;
- exactly representable (dyadic) coordinates against decimal ones off by an ulp, exact
  (permutation) rotations against computed ones (cos(pi/2) != 0), ulp noise far from the origin.
Every pair is placed by a similarity at scales 1e-6..1e6 (exact ones for the dyadic kinds), and
often far from the origin; the 17 kinds ending in "_far" (of 43, list KINDS at the end) are
near-coincident pairs 1e3..3e7 sizes away.

Usage: python3 generate_pairs7.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/<seed:06d>_<kind>_a.obj and _b.obj for each seed in [SEED_FROM, SEED_TO),
kind = KINDS[seed % len(KINDS)], deterministic per seed (random.Random(seed)); every mesh has
1..80 triangles and finite coordinates written with repr(). Python 3 standard library only.
"""
import math
import os
import random
import sys

# ---------------------------------------------------------------------------------------------
# vectors
# ---------------------------------------------------------------------------------------------


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
    return mul(a, 1.0 / n) if n > 0 else (1.0, 0.0, 0.0)


def lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def rand_dir(r):
    while True:
        v = (r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1))
        n = norm(v)
        if 0.1 < n <= 1:
            return mul(v, 1 / n)


def loguni(r, lo, hi):
    """10 ** uniform(lo, hi)."""
    return 10.0 ** r.uniform(lo, hi)


def sgn(r):
    return 1 if r.random() < 0.5 else -1


# 3x3 matrices as tuples of rows
IDENT = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def mat_apply(m, p):
    return (dot(m[0], p), dot(m[1], p), dot(m[2], p))


def mat_mul(a, b):
    bt = tuple(zip(*b))
    return tuple(tuple(dot(a[i], bt[j]) for j in range(3)) for i in range(3))


def rot_axis(axis, ang):
    """Rodrigues: rotation by ang about the unit vector axis."""
    x, y, z = unit(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def rand_rot(r):
    """Uniform random rotation (Shoemake)."""
    u1, u2, u3 = r.random(), r.random(), r.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    w, x = a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2)
    y, z = b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def signed_perm(r):
    """An exact rotation or reflection: a signed permutation matrix."""
    p = [0, 1, 2]
    r.shuffle(p)
    m = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        m[i][p[i]] = float(sgn(r))
    return tuple(tuple(row) for row in m)


# ---------------------------------------------------------------------------------------------
# meshes
# ---------------------------------------------------------------------------------------------


class Mesh:
    def __init__(self):
        self.v = []
        self.f = []

    def vert(self, p):
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.v) - 1

    def tri(self, a, b, c):
        self.f.append((a, b, c))

    def tri_pts(self, a, b, c):
        self.tri(self.vert(a), self.vert(b), self.vert(c))

    def extend(self, other):
        base = len(self.v)
        self.v.extend(other.v)
        self.f.extend((a + base, b + base, c + base) for a, b, c in other.f)
        return self

    def copy(self):
        m = Mesh()
        m.v = list(self.v)
        m.f = list(self.f)
        return m

    def mapped(self, fn):
        m = Mesh()
        m.v = [tuple(float(c) for c in fn(p)) for p in self.v]
        m.f = list(self.f)
        return m

    def flipped(self):
        m = self.copy()
        m.f = [(a, c, b) for a, b, c in self.f]
        return m

    def shuffled(self, r):
        m = self.copy()
        r.shuffle(m.f)
        return m

    def bbox(self):
        used = sorted({i for t in self.f for i in t})
        lo = [min(self.v[i][k] for i in used) for k in range(3)]
        hi = [max(self.v[i][k] for i in used) for k in range(3)]
        return lo, hi


def tri_area_sum(m):
    return sum(norm(cross(sub(m.v[b], m.v[a]), sub(m.v[c], m.v[a]))) / 2 for a, b, c in m.f)


def edges_of(m):
    es = set()
    for a, b, c in m.f:
        for u, w in ((a, b), (b, c), (c, a)):
            if u != w:
                es.add((min(u, w), max(u, w)))
    return sorted(es)


def grid(nx, ny, x0=0.0, y0=0.0, w=1.0, h=1.0, zf=None, diag="random", r=None):
    """nx x ny cells over [x0, x0+w] x [y0, y0+h], z = zf(x, y); diag: same, alt, random, other."""
    m = Mesh()
    idx = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = x0 + w * i / nx
            y = y0 + h * j / ny
            idx[i, j] = m.vert((x, y, zf(x, y) if zf else 0.0))
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            if diag == "same":
                flip = False
            elif diag == "other":
                flip = True
            elif diag == "alt":
                flip = (i + j) % 2 == 1
            else:
                flip = r.random() < 0.5
            if flip:
                m.tri(a, b, d)
                m.tri(b, c, d)
            else:
                m.tri(a, b, c)
                m.tri(a, c, d)
    return m


def bump(r, amp):
    fx, fy = r.uniform(1, 6), r.uniform(1, 6)
    px, py = r.uniform(0, 6.3), r.uniform(0, 6.3)
    return lambda x, y: amp * math.sin(fx * x + px) * math.cos(fy * y + py)


def ngon(n, radius=1.0, z=0.0, phase=0.0, center=(0.0, 0.0)):
    return [(center[0] + radius * math.cos(phase + 2 * math.pi * i / n),
             center[1] + radius * math.sin(phase + 2 * math.pi * i / n), z) for i in range(n)]


def fan(hub, ring, closed=True):
    m = Mesh()
    h = m.vert(hub)
    ids = [m.vert(p) for p in ring]
    n = len(ids)
    for i in range(n if closed else n - 1):
        m.tri(h, ids[i], ids[(i + 1) % n])
    return m


def strip_poly(ring):
    """A convex polygon triangulated as a zig-zag strip."""
    m = Mesh()
    ids = [m.vert(p) for p in ring]
    lo, hi = 0, len(ids) - 1
    toggle = True
    while hi - lo >= 2:
        if toggle:
            m.tri(ids[lo], ids[lo + 1], ids[hi])
            lo += 1
        else:
            m.tri(ids[lo], ids[hi - 1], ids[hi])
            hi -= 1
        toggle = not toggle
    return m


def fan_from_vertex(ring, k=0):
    m = Mesh()
    ids = [m.vert(p) for p in ring]
    n = len(ids)
    for i in range(1, n - 1):
        m.tri(ids[k], ids[(k + i) % n], ids[(k + i + 1) % n])
    return m


def ring_band(inner, outer):
    """Triangulate the band between two concentric closed rings (ordered by angle, any counts)."""
    m = Mesh()
    I = [m.vert(p) for p in inner]
    O = [m.vert(p) for p in outer]
    ni, no = len(I), len(O)

    def ang(p):
        a = math.atan2(p[1], p[0])
        return a if a >= 0 else a + 2 * math.pi

    ai = [ang(p) for p in inner]
    ao = [ang(p) for p in outer]
    # start both rings at their smallest angle
    si = min(range(ni), key=lambda k: ai[k])
    so = min(range(no), key=lambda k: ao[k])
    i = j = 0
    while i < ni or j < no:
        ci, co = I[(si + i) % ni], O[(so + j) % no]
        ni_a = ai[(si + i + 1) % ni] + (2 * math.pi if (si + i + 1) % ni == si else 0) if i < ni else 1e9
        no_a = ao[(so + j + 1) % no] + (2 * math.pi if (so + j + 1) % no == so else 0) if j < no else 1e9
        if i < ni and (j >= no or ni_a <= no_a):
            m.tri(ci, co, I[(si + i + 1) % ni])
            i += 1
        else:
            m.tri(ci, co, O[(so + j + 1) % no])
            j += 1
    return m


PHI = (1 + math.sqrt(5)) / 2


def solid(name):
    """Closed convex solids centred at the origin, outward orientation."""
    if name == "tetra":
        V = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
        F = [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]
    elif name == "octa":
        V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
        F = [(a, b, c) for a in (0, 1) for b in (2, 3) for c in (4, 5)]
    elif name == "cube":
        V = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
        quads = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5)]
        F = []
        for a, b, c, d in quads:
            F += [(a, b, c), (a, c, d)]
    elif name == "icosa":
        V = []
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                V += [(0, s1, s2 * PHI), (s1, s2 * PHI, 0), (s2 * PHI, 0, s1)]
        F = []
        n = len(V)
        for a in range(n):
            for b in range(a + 1, n):
                for c in range(b + 1, n):
                    if all(abs(norm(sub(V[p], V[q])) - 2) < 1e-9 for p, q in ((a, b), (b, c), (a, c))):
                        F.append((a, b, c))
    else:
        raise ValueError(name)
    m = Mesh()
    for p in V:
        m.vert(p)
    for a, b, c in F:
        n = cross(sub(m.v[b], m.v[a]), sub(m.v[c], m.v[a]))
        cen = mul(add(add(m.v[a], m.v[b]), m.v[c]), 1 / 3)
        m.tri(a, b, c) if dot(n, cen) > 0 else m.tri(a, c, b)
    return m


def subdivide(m, sphere=False):
    out = Mesh()
    out.v = list(m.v)
    mid = {}

    def midpoint(a, b):
        key = (min(a, b), max(a, b))
        if key not in mid:
            p = lerp(out.v[a], out.v[b], 0.5)
            mid[key] = out.vert(p)
        return mid[key]

    for a, b, c in m.f:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        out.f += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    if sphere:
        rad = norm(m.v[m.f[0][0]])
        out.v = [mul(unit(p), rad) for p in out.v]
    return out


def cube_surface(k, r, size=(1.0, 1.0, 1.0)):
    """Box [-sx,sx]x[-sy,sy]x[-sz,sz], each face k x k cells, random diagonals, outward."""
    m = Mesh()
    sx, sy, sz = size
    for axis in range(3):
        for side in (-1, 1):
            u_ax, v_ax = [a for a in range(3) if a != axis]
            ids = {}
            for i in range(k + 1):
                for j in range(k + 1):
                    p = [0.0, 0.0, 0.0]
                    p[axis] = side * 1.0
                    p[u_ax] = -1 + 2 * i / k
                    p[v_ax] = -1 + 2 * j / k
                    ids[i, j] = m.vert((p[0] * sx, p[1] * sy, p[2] * sz))
            for i in range(k):
                for j in range(k):
                    a, b, c, d = ids[i, j], ids[i + 1, j], ids[i + 1, j + 1], ids[i, j + 1]
                    tris = [(a, b, c), (a, c, d)] if r.random() < 0.5 else [(a, b, d), (b, c, d)]
                    for t in tris:
                        n = cross(sub(m.v[t[1]], m.v[t[0]]), sub(m.v[t[2]], m.v[t[0]]))
                        cen = m.v[t[0]]
                        m.tri(*t) if dot(n, cen) > 0 else m.tri(t[0], t[2], t[1])
    return m


def cone(n, half_angle, height=1.0, phase=0.0, apex_z=0.0, closed=False):
    """Apex at (0,0,apex_z), opening towards +z, base ring at height."""
    rad = height * math.tan(half_angle)
    ring = ngon(n, rad, apex_z + height, phase)
    m = fan((0.0, 0.0, apex_z), ring)
    if closed:
        m.extend(fan((0.0, 0.0, apex_z + height), ring).flipped())
    return m


# ---------------------------------------------------------------------------------------------
# placement: similarity transforms at scales 1e-6..1e6, often far from the origin
# ---------------------------------------------------------------------------------------------


def union_box(meshes):
    lo = [float("inf")] * 3
    hi = [-float("inf")] * 3
    for m in meshes:
        l, h = m.bbox()
        lo = [min(lo[k], l[k]) for k in range(3)]
        hi = [max(hi[k], h[k]) for k in range(3)]
    return lo, hi


def place(meshes, r, far=False, exact=False, offset_mode=None):
    """The same similarity on every mesh: p -> off + s R p.

    exact: R a signed permutation, s a power of two, off a dyadic vector (no rounding when the
    coordinates are dyadic and fit). far: 1e3..3e7 sizes from the origin."""
    lo, hi = union_box(meshes)
    size = max(norm(sub(tuple(hi), tuple(lo))), 1e-300)
    if exact:
        s = 2.0 ** r.randint(-20, 20)
        R = signed_perm(r)
    else:
        s = loguni(r, -6, 6)
        R = r.choice([IDENT, signed_perm(r), rand_rot(r), rand_rot(r)])
    if offset_mode is None:
        offset_mode = "far" if far else r.choice(["zero", "zero", "near", "far"])
    if offset_mode == "zero":
        off = (0.0, 0.0, 0.0)
    else:
        dist = s * size * (loguni(r, 3, 7.5) if offset_mode == "far" else loguni(r, 0, 3))
        if exact:
            k = math.floor(math.log2(dist))
            off = tuple(float(r.randint(-3, 3) * 2.0 ** k) for _ in range(3))
            if off == (0.0, 0.0, 0.0):
                off = (2.0 ** k, 0.0, 0.0)
        else:
            off = mul(rand_dir(r), dist)
            if r.random() < 0.3:  # an offset with one round component
                off = (round(off[0]), off[1], off[2])
    out = [m.mapped(lambda p: add(off, mul(mat_apply(R, p), s))) for m in meshes]
    return out


# ---------------------------------------------------------------------------------------------
# the kinds
# ---------------------------------------------------------------------------------------------


def k_cone_axis_point(r):
    """A cone of 3..40 triangles; the target on its axis is equidistant from every face."""
    n = r.randint(3, 40)
    h = loguni(r, -4, 3)
    A = cone(n, math.atan(1.0 / h), height=h, phase=r.uniform(0, 1) if r.random() < 0.5 else 0.0,
             closed=(n <= 40 and r.random() < 0.4))
    # the apex at the origin, the base at z = h
    c = h * r.choice([0.5, r.random(), 1e-9, 1 - 1e-9, 1.0, 1.5, -0.5])
    size = loguni(r, -12, -1) * max(1.0, h)
    mode = r.choice(["tri", "point", "needle", "tilted"])
    B = Mesh()
    if mode == "tri":
        B.extend(fan((0.0, 0.0, c), ngon(3, size, c, r.uniform(0, 7)))) if r.random() < 0.5 else \
            B.tri_pts(*ngon(3, size, c, r.uniform(0, 7)))
    elif mode == "point":
        p = (0.0, 0.0, c)
        B.tri_pts(p, p, p)
    elif mode == "needle":
        w = r.choice([0.0, size * 1e-6, size])
        B.tri_pts((0.0, 0.0, c - size), (0.0, 0.0, c + size), (w, 0.0, c))
    else:
        R = rot_axis(rand_dir(r), r.uniform(0, 3))
        pts = [add((0.0, 0.0, c), mat_apply(R, p)) for p in ngon(3, size)]
        B.tri_pts(*pts)
    return A, B, {}


def k_prism_axis_needle(r):
    """A prism (polygonal cylinder); a sliver or a book of needles along its axis."""
    n = r.randint(3, 16)
    m = r.randint(1, max(1, min(4, 40 // n)))
    H = loguni(r, -3, 3)
    A = Mesh()
    rings = []
    for j in range(m + 1):
        rings.append([A.vert(p) for p in ngon(n, 1.0, H * j / m)])
    for j in range(m):
        for i in range(n):
            a, b = rings[j][i], rings[j][(i + 1) % n]
            c, d = rings[j + 1][(i + 1) % n], rings[j + 1][i]
            if r.random() < 0.5:
                A.tri(a, b, c), A.tri(a, c, d)
            else:
                A.tri(a, b, d), A.tri(b, c, d)
    if len(A.f) + 2 * n <= 80 and r.random() < 0.4:
        A.extend(fan((0.0, 0.0, 0.0), ngon(n, 1.0, 0.0)).flipped())
        A.extend(fan((0.0, 0.0, H), ngon(n, 1.0, H)))
    B = Mesh()
    z0, z1 = H * r.choice([0.0, 0.25, -0.5]), H * r.choice([1.0, 0.75, 1.5])
    mode = r.choice(["sliver", "book", "offaxis"])
    if mode == "sliver":
        w = r.choice([0.0, loguni(r, -12, -3)])
        B.tri_pts((0.0, 0.0, z0), (0.0, 0.0, z1), (w, 0.0, (z0 + z1) / 2))
    elif mode == "book":
        k = r.randint(2, 8)
        a, b = B.vert((0.0, 0.0, z0)), B.vert((0.0, 0.0, z1))
        w = loguni(r, -10, -1)
        for p in ngon(k, w, (z0 + z1) / 2, r.uniform(0, 7)):
            B.tri(a, b, B.vert(p))
    else:
        e = loguni(r, -13, -6)
        B.tri_pts((e, 0.0, z0), (e, 0.0, z1), (e, loguni(r, -12, -4), (z0 + z1) / 2))
    return A, B, {}


def k_regular_solid_center(r):
    """A regular solid (faces equidistant from its centre) against a tiny target at the centre."""
    name = r.choice(["tetra", "octa", "cube", "icosa", "octa_sub", "icosa_sub"])
    if name == "octa_sub":
        A = subdivide(solid("octa"), sphere=r.random() < 0.5)
    elif name == "icosa_sub":
        A = subdivide(solid("icosa"), sphere=True)
    else:
        A = solid(name)
    if r.random() < 0.5:
        R = rand_rot(r)
        A = A.mapped(lambda p: mat_apply(R, p))
    size = loguni(r, -12, -1)
    ctr = (0.0, 0.0, 0.0) if r.random() < 0.6 else mul(rand_dir(r), loguni(r, -14, -6))
    B = Mesh()
    mode = r.choice(["tri", "point", "fan"])
    if mode == "point":
        B.tri_pts(ctr, ctr, ctr)
    elif mode == "tri":
        R2 = rand_rot(r)
        B.tri_pts(*[add(ctr, mat_apply(R2, p)) for p in ngon(3, size)])
    else:
        R2 = rand_rot(r)
        B = fan(ctr, [add(ctr, mat_apply(R2, p)) for p in ngon(r.randint(3, 12), size)])
    return A, B, {}


def _nested(r, lo_eps, hi_eps, rot_lo, rot_hi, allow_other):
    names = ["tetra", "octa", "cube", "icosa"]
    na = r.choice(names)
    A = solid(na)
    if allow_other and r.random() < 0.3:
        nb = r.choice(names)
    else:
        nb = na
    B = solid(nb)
    if nb == na and r.random() < 0.5:
        B = subdivide(B, sphere=False)  # coplanar refinement of the same faces
    if na == "icosa" and len(B.f) > 80:
        B = solid(nb)
    if nb != na:  # the same circumradius
        ra, rb = norm(A.v[0]), norm(B.v[0])
        B = B.mapped(lambda p: mul(p, ra / rb))
    eps = sgn(r) * loguni(r, lo_eps, hi_eps) if r.random() < 0.85 else 0.0
    ang = loguni(r, rot_lo, rot_hi) if r.random() < 0.7 else 0.0
    R = rot_axis(rand_dir(r), ang)
    B = B.mapped(lambda p: mul(mat_apply(R, p), 1 + eps))
    if r.random() < 0.5:
        B = B.shuffled(r)
    return A, B


def k_nested_solids(r):
    """Concentric solids: a solid inside a rotated, scaled copy (or another solid)."""
    A, B = _nested(r, -12, -1, -12, -1, True)
    if r.random() < 0.2:
        R = rand_rot(r)
        B = B.mapped(lambda p: mat_apply(R, p))
    return A, B, {}


def k_nested_solids_far(r):
    """Near-coincident concentric solids (scaled by 1 +- 1e-13..1e-8, rotated 1e-13..1e-8 rad)."""
    A, B = _nested(r, -13, -8, -13, -8, False)
    return A, B, {"far": True}


def _book(r, k, angles, s, widths, L=1.0):
    m = Mesh()
    spine = [m.vert((0.0, 0.0, L * j / s)) for j in range(s + 1)]
    for th, w in zip(angles, widths):
        o = m.vert((w * math.cos(th), w * math.sin(th), L * r.uniform(0.2, 0.8)))
        for j in range(s):
            m.tri(spine[j], spine[j + 1], o)
    return m


def k_book_spine(r):
    """Non-manifold edges: 3..9 pages sharing a spine; a second book, a cutting plane, a target."""
    k = r.randint(3, 9)
    mode_a = r.choice(["random", "near_equal", "opposite"])
    if mode_a == "random":
        ang = [r.uniform(0, 2 * math.pi) for _ in range(k)]
    elif mode_a == "near_equal":
        base = r.uniform(0, 6.3)
        ang = [base + i * loguni(r, -12, -4) for i in range(k)]
    else:
        base = r.uniform(0, 6.3)
        ang = [base + math.pi * (i % 2) + (i // 2) * r.uniform(0.1, 0.5) for i in range(k)]
    widths = [r.uniform(0.3, 1.0) for _ in range(k)]
    A = _book(r, k, ang, r.randint(1, 3), widths)
    mode = r.choice(["book", "plane", "target", "bisector"])
    if mode == "book":
        d = loguni(r, -12, -3)
        B = _book(r, k, [a + sgn(r) * d for a in ang], r.randint(1, 3), widths)
    elif mode == "plane":
        z = r.choice([0.5, r.uniform(0.1, 0.9), 0.0])
        B = grid(r.randint(1, 4), r.randint(1, 4), -1, -1, 2, 2, lambda x, y: z, r=r)
    elif mode == "target":
        zc = r.uniform(0, 1)
        size = loguni(r, -10, -2)
        B = Mesh()
        B.tri_pts(*ngon(3, size, zc, r.uniform(0, 7)))
    else:
        th = (ang[0] + ang[1]) / 2
        B = Mesh()
        B.tri_pts((0.0, 0.0, -0.2), (0.0, 0.0, 1.2), (math.cos(th), math.sin(th), 0.5))
    return A, B, {}


def k_book_spine_far(r):
    """Near-coincident books of pages (non-manifold spine), far from the origin."""
    k = r.randint(3, 9)
    ang = [r.uniform(0, 2 * math.pi) for _ in range(k)]
    widths = [r.uniform(0.3, 1.0) for _ in range(k)]
    st = r.getstate()
    A = _book(r, k, ang, r.randint(1, 3), widths)
    r.setstate(st)
    B = _book(r, k, ang, r.randint(1, 3), widths)
    # move B's page tips by 1e-13..1e-9 and possibly re-split the spine
    eps = loguni(r, -13, -9)
    B = B.mapped(lambda p: add(p, mul(rand_dir(r), eps)) if p[0] != 0.0 or p[1] != 0.0 else p)
    if r.random() < 0.5:
        B2 = Mesh()
        B2.v = list(B.v)
        for a, b, c in B.f:  # split each page triangle at its spine edge's midpoint
            mpt = B2.vert(lerp(B.v[a], B.v[b], 0.5))
            B2.tri(a, mpt, c)
            B2.tri(mpt, b, c)
        if len(B2.f) <= 80:
            B = B2
    return A, B, {"far": True}


def _tjunction(r, far):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    amp = r.choice([0.0, loguni(r, -13, -9) if far else loguni(r, -6, -1)])
    zf = bump(r, amp) if amp else None
    A = Mesh()
    idx = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = i / nx, j / ny
            idx[i, j] = A.vert((x, y, zf(x, y) if zf else 0.0))
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            if r.random() < 0.4:
                # a point on edge ab (bottom) or da (left): fan from it; the neighbour does not have it
                t = r.choice([0.5, r.random(), 1e-9, 1 - 1e-7])
                if r.random() < 0.5:
                    mpt = A.vert(lerp(A.v[a], A.v[b], t))
                    A.tri(mpt, b, c), A.tri(mpt, c, d), A.tri(mpt, d, a)
                    if r.random() < 0.6:
                        A.tri(a, mpt, b) if r.random() < 0.5 else A.tri(a, b, mpt)
                else:
                    mpt = A.vert(lerp(A.v[d], A.v[a], t))
                    A.tri(mpt, a, b), A.tri(mpt, b, c), A.tri(mpt, c, d)
                    if r.random() < 0.6:
                        A.tri(d, mpt, a)
            elif r.random() < 0.5:
                A.tri(a, b, c), A.tri(a, c, d)
            else:
                A.tri(a, b, d), A.tri(b, c, d)
    mode = r.choice(["tilt", "lift", "coarse", "clean"])
    if mode == "coarse":
        B = grid(1, 1, zf=zf, r=r)
    else:
        B = grid(nx, ny, zf=zf, r=r)
        if mode == "tilt":
            R = rot_axis((r.uniform(-1, 1), r.uniform(-1, 1), 0.0), loguni(r, -13, -9) if far else loguni(r, -12, -4))
            B = B.mapped(lambda p: add(mat_apply(R, sub(p, (0.5, 0.5, 0.0))), (0.5, 0.5, 0.0)))
        elif mode == "lift":
            dz = sgn(r) * (loguni(r, -14, -9) if far else loguni(r, -13, -5))
            B = B.mapped(lambda p: (p[0], p[1], p[2] + dz))
    return A, B


def k_tjunction_zero_area(r):
    """A grid with T-junctions filled by collinear (zero-area) triangles, against a copy without
    them tilted by 1e-12..1e-4 rad, lifted by 1e-13..1e-5, coarse or the same."""
    A, B = _tjunction(r, False)
    return A, B, {}


def k_tjunction_zero_area_far(r):
    """As tjunction_zero_area, near-coincident (bumps, tilts and lifts below 1e-9), far away."""
    A, B = _tjunction(r, True)
    return A, B, {"far": True}


def _soup(r, nx, ny, zf, jit, diag_r):
    clean = grid(nx, ny, zf=zf, r=diag_r)
    A = Mesh()
    for a, b, c in clean.f:
        ids = []
        for v in (a, b, c):
            p = clean.v[v]
            if r.random() < 0.6:
                p = add(p, mul(rand_dir(r), jit * r.choice([1.0, 0.5, 2.0])))
            ids.append(A.vert(p))
        A.tri(*ids)
    return clean, A


def k_soup_crack_jitter(r):
    """A triangle soup whose duplicated vertices differ by 1e-15..1e-11 (hairline cracks and
    overlaps; identical copies are welded by the loader) against the welded surface."""
    nx, ny = r.randint(1, 5), r.randint(1, 5)
    zf = bump(r, loguni(r, -4, -0.5)) if r.random() < 0.7 else None
    jit = loguni(r, -15, -11)
    diag_r = random.Random(r.random())
    clean, A = _soup(r, nx, ny, zf, jit, diag_r)
    mode = r.choice(["clean", "retri", "fine"])
    if mode == "clean":
        B = clean
    elif mode == "retri":
        B = grid(nx, ny, zf=zf, diag="other" if r.random() < 0.5 else "alt", r=r)
    else:
        B = grid(min(2 * nx, 6), min(2 * ny, 6), zf=zf, r=r)
    return A, B, {}


def k_soup_crack_jitter_far(r):
    """A soup of a grid, far from the origin, its duplicated vertices moved by 1e-14..1e-11 of the
    size or 1..4 ulps of the world coordinates, against the welded grid (near-coincident)."""
    nx, ny = r.randint(1, 5), r.randint(1, 5)
    zf = bump(r, loguni(r, -4, -1)) if r.random() < 0.6 else None
    diag_r = random.Random(r.random())
    clean, A = _soup(r, nx, ny, zf, 0.0, diag_r)
    A, B = place([A, clean], r, far=True)
    rel = loguni(r, -14, -11)
    lo, hi = union_box([B])
    size = norm(sub(tuple(hi), tuple(lo)))

    def jitter(p):
        if r.random() < 0.4:
            return p
        if r.random() < 0.5:
            return tuple(c + r.randint(-4, 4) * math.ulp(c) for c in p)
        return add(p, mul(rand_dir(r), rel * size))
    A = A.mapped(jitter)
    return A, B, {"far": True, "placed": True}


def k_aniso_grid(r):
    """A bumpy grid scaled 1e3..1e6 along one axis and 1e-4..1e-1 along another (aspect up to
    1e10), against another resolution of the same surface."""
    nx, ny = r.randint(2, 8), r.randint(2, 5)
    zf = bump(r, r.uniform(0.1, 1.0))
    A = grid(nx, ny, zf=zf, r=r)
    mode = r.choice(["res", "retri", "offset"])
    if mode == "res":
        B = grid(r.randint(1, 8), r.randint(1, 5), zf=zf, r=r)
    elif mode == "retri":
        B = grid(nx, ny, zf=zf, diag="other", r=r)
    else:
        dz = loguni(r, -9, -2)
        B = grid(nx, ny, zf=lambda x, y: zf(x, y) + dz, r=r)
    scales = [loguni(r, 3, 6), 1.0, loguni(r, -4, -1)]
    r.shuffle(scales)
    A = A.mapped(lambda p: (p[0] * scales[0], p[1] * scales[1], p[2] * scales[2]))
    B = B.mapped(lambda p: (p[0] * scales[0], p[1] * scales[1], p[2] * scales[2]))
    return A, B, {}


def k_aniso_retri_far(r):
    """Near-coincident anisotropic grids (the same vertices, other diagonals), far away."""
    nx, ny = r.randint(1, 6), r.randint(1, 5)
    scales = [loguni(r, 2, 5), 1.0, loguni(r, -3, -1)]
    r.shuffle(scales)
    # heights 1e-9..1e-4 of the larger extent in the plane, whatever the axis scales
    zf = bump(r, loguni(r, -9, -4) * max(scales[0], scales[1]) / scales[2])
    A = grid(nx, ny, zf=zf, r=r)
    B = grid(nx, ny, zf=zf, diag=r.choice(["other", "alt", "random"]), r=r)
    A = A.mapped(lambda p: (p[0] * scales[0], p[1] * scales[1], p[2] * scales[2]))
    B = B.mapped(lambda p: (p[0] * scales[0], p[1] * scales[1], p[2] * scales[2]))
    return A, B, {"far": True}


def _crossing_grid(r, alo, ahi, same_region=False):
    A = grid(r.randint(1, 6), r.randint(1, 6), r=r)
    if same_region:
        B = grid(r.randint(1, 6), r.randint(1, 6), r=r)
    else:
        x0, y0 = r.uniform(-0.3, 0.5), r.uniform(-0.3, 0.5)
        B = grid(r.randint(1, 6), r.randint(1, 6), x0, y0, r.uniform(0.3, 1.0), r.uniform(0.3, 1.0), r=r)
    # the hinge: through a point of A (maybe a vertex of A), along x, y, a diagonal or at random
    piv = r.choice([(0.5, 0.5, 0.0), (r.random(), r.random(), 0.0), (0.0, 0.0, 0.0)])
    th = r.choice([0.0, math.pi / 2, math.pi / 4, r.uniform(0, math.pi)])
    ax = (math.cos(th), math.sin(th), 0.0)
    R = rot_axis(ax, sgn(r) * loguni(r, alo, ahi))
    B = B.mapped(lambda p: add(piv, mat_apply(R, sub(p, piv))))
    return A, B


def k_cross_tiny_angle(r):
    """Two flat grids crossing along a line at 1e-12..1e-2 rad."""
    A, B = _crossing_grid(r, -12, -2)
    return A, B, {}


def k_cross_tiny_angle_far(r):
    """Two flat grids over one square crossing at 1e-13..1e-8 rad, far from the origin
    (near-coincident)."""
    A, B = _crossing_grid(r, -13, -8, same_region=True)
    return A, B, {"far": True}


def _mirror(r, far):
    nx, ny = r.randint(1, 6), r.randint(1, 6)
    amp = loguni(r, -13, -9) if far else loguni(r, -6, -1)
    zf = bump(r, amp)
    c = r.choice([0.0, 0.0, amp * 0.5, loguni(r, -14, -10) if far else loguni(r, -12, -7)])
    A = grid(nx, ny, zf=lambda x, y: zf(x, y) + c, r=r)
    beta = r.choice([0.0, loguni(r, -13, -9) if far else loguni(r, -12, -3)])
    gam = r.uniform(0, 6.3)
    n = (math.sin(beta) * math.cos(gam), math.sin(beta) * math.sin(gam), math.cos(beta))
    q = (0.5, 0.5, 0.0)
    B = A.mapped(lambda p: sub(p, mul(n, 2 * dot(sub(p, q), n))))
    if r.random() < 0.5:
        B = B.flipped()
    if r.random() < 0.3:  # a mirror across a vertical plane instead: a chiral shape's image
        B = A.mapped(lambda p: (1.0 - p[0], p[1], p[2]))
    return A, B


def k_mirror_tilted(r):
    """A bumpy surface against its mirror image in a mirror tilted by 0 or 1e-12..1e-3 rad
    through the surface (the two cross)."""
    A, B = _mirror(r, False)
    return A, B, {}


def k_mirror_tilted_far(r):
    """A surface with bumps of 1e-13..1e-9 against its image in a mirror tilted by 0 or
    1e-13..1e-9 rad (near-coincident, crossing everywhere), far from the origin."""
    A, B = _mirror(r, True)
    return A, B, {"far": True}


def k_point_touch(r):
    """Meshes touching at exactly one point: an apex on a vertex, an edge or inside a face of a
    grid, or two tetrahedra apex to apex; dyadic coordinates, often placed exactly."""
    n = r.choice([2, 4])
    A = grid(n, n, -1.0, -1.0, 2.0, 2.0, r=r)
    where = r.choice(["vertex", "edge", "face", "corner", "apex"])
    h = 2.0 ** r.randint(-8, 4)
    rad = 2.0 ** r.randint(-6, 1)
    if where == "vertex":
        P = (0.0, 0.0, 0.0)
    elif where == "edge":
        P = (0.25, 0.0, 0.0) if n == 4 else (0.5, 0.0, 0.0)
    elif where == "face":
        P = (0.125, 0.375, 0.0) if n == 4 else (0.25, 0.625, 0.0)
    elif where == "corner":
        P = (-1.0, -1.0, 0.0)
    else:
        P = None
    if P is None:
        A = fan((0.0, 0.0, 0.0), [(x * rad, y * rad, -h) for x, y in ((1, 0), (0, 1), (-1, 0), (0, -1))])
        A.extend(fan((0.0, 0.0, -h), [(x * rad, y * rad, -h) for x, y in ((1, 0), (0, 1), (-1, 0), (0, -1))]).flipped())
        B = A.mapped(lambda p: (p[1], p[0], -p[2]))
    else:
        nn = r.choice([3, 4, 8])
        if nn == 4:
            ring = [(P[0] + x * rad, P[1] + y * rad, h) for x, y in ((1, 0), (0, 1), (-1, 0), (0, -1))]
        elif nn == 8:
            ring = [(P[0] + x * rad, P[1] + y * rad, h) for x, y in
                    ((1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1))]
        else:
            ring = [(P[0] + x * rad, P[1] + y * rad, h) for x, y in ((1, 0), (-0.5, 1), (-0.5, -1))]
        B = fan(P, ring)
        if r.random() < 0.5:
            B.extend(fan((P[0], P[1], h), ring).flipped())
        if r.random() < 0.3:  # lying beside the plane, the apex on the plane's rim
            B = B.mapped(lambda p: (p[0], p[1], -p[2]))
    exact = r.random() < 0.6
    A, B = place([A, B], r, exact=exact)
    if r.random() < 0.5:
        A, B = B, A
    return A, B, {"placed": True}


def k_huge_tiny_scatter(r):
    """Two huge triangles against clusters 1e-7..1e-5 of their size at a corner, an edge's
    middle, inside the face, just above it and beyond an edge."""
    A = Mesh()
    a, b, c, d = (A.vert(p) for p in ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)))
    A.tri(a, b, c)
    if r.random() < 0.7:
        A.tri(a, c, d)
    eps = loguni(r, -7, -5)
    spots = [(0.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.3, 0.2, 0.0), (0.6, 0.3, eps * r.choice([1e-3, 1, 10])),
             (1.0 + eps, 0.5, 0.0), (0.5, 0.5, 0.0), (1.0, 1.0, 0.0), (0.2, 0.7, -eps)]
    r.shuffle(spots)
    B = Mesh()
    for P in spots[:r.randint(1, 8)]:
        kind = r.choice(["tetra", "fan", "sliver", "flat"])
        if kind == "tetra":
            R = rand_rot(r)
            t = solid("tetra").mapped(lambda p: add(P, mul(mat_apply(R, p), eps)))
            B.extend(t)
        elif kind == "fan":
            B.extend(fan(P, [add(P, mul(q, eps)) for q in ngon(r.randint(3, 6), 1.0, r.uniform(-1, 1), r.uniform(0, 7))]))
        elif kind == "sliver":
            B.tri_pts(P, add(P, (eps, eps * 0.3, 0.0)), add(P, (eps * 0.5, eps * 0.15, eps * 1e-7)))
        else:
            B.tri_pts(P, add(P, (eps, 0.0, 0.0)), add(P, (0.0, eps, 0.0)))
    if r.random() < 0.5:
        A, B = B, A
    return A, B, {}


def k_sliver_fan_tilted_grid(r):
    """A fan of slivers (1e-9..1e-3 rad wide) round a hub, nearly coplanar with a grid tilted by
    1e-12..1e-5 rad about a line through the hub."""
    hub = (r.uniform(0.3, 0.7), r.uniform(0.3, 0.7), 0.0)
    K = r.randint(5, 30)
    A = Mesh()
    h = A.vert(hub)
    detached = r.random() < 0.3
    for i in range(K):
        th = 2 * math.pi * (i + r.uniform(-0.3, 0.3)) / K
        w = loguni(r, -9, -3)
        rho = r.uniform(0.2, 0.5)
        p = (hub[0] + rho * math.cos(th), hub[1] + rho * math.sin(th), 0.0)
        q = (hub[0] + rho * math.cos(th + w), hub[1] + rho * math.sin(th + w), 0.0)
        if detached:
            s0 = r.uniform(0.01, 0.1)
            A.tri(A.vert(lerp(hub, p, s0)), A.vert(p), A.vert(q))
        else:
            A.tri(h, A.vert(p), A.vert(q))
    B = grid(r.randint(1, 5), r.randint(1, 5), r=r)
    tilt = loguni(r, -12, -5)
    R = rot_axis((r.uniform(-1, 1), r.uniform(-1, 1), 0.0), tilt)
    dz = r.choice([0.0, 0.0, sgn(r) * loguni(r, -13, -7)])
    B = B.mapped(lambda p: add(add(hub, mat_apply(R, sub(p, hub))), (0.0, 0.0, dz)))
    if r.random() < 0.5:
        A, B = B, A
    return A, B, {}


def _slivers(r, K, center):
    m = Mesh()
    for _ in range(K):
        th = r.uniform(0, math.pi)
        L = r.uniform(0.3, 1.0)
        d = (math.cos(th), math.sin(th), 0.0)
        c = add(center, (r.uniform(-0.1, 0.1), r.uniform(-0.1, 0.1), 0.0))
        p, q = sub(c, mul(d, L / 2)), add(c, mul(d, L / 2))
        t = r.random()
        hgt = L * loguni(r, -10, -3)
        apex = add(lerp(p, q, t), mul((-d[1], d[0], 0.0), hgt * sgn(r)))
        m.tri_pts(p, q, apex)
    return m


def k_crossing_slivers(r):
    """Slivers crossing each other in X's, in one plane or planes 1e-12..1e-4 rad apart."""
    c = (0.5, 0.5, 0.0)
    A = _slivers(r, r.randint(3, 20), c)
    B = _slivers(r, r.randint(1, 20), c)
    mode = r.choice(["coplanar", "tilt", "lift"])
    if mode == "tilt":
        R = rot_axis((r.uniform(-1, 1), r.uniform(-1, 1), 0.0), loguni(r, -12, -4))
        B = B.mapped(lambda p: add(c, mat_apply(R, sub(p, c))))
    elif mode == "lift":
        dz = sgn(r) * loguni(r, -14, -6)
        B = B.mapped(lambda p: (p[0], p[1], p[2] + dz))
    return A, B, {}


def _dyadic_grid(r):
    nx, ny = r.randint(1, 6), r.randint(1, 6)
    H = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            H[i, j] = float(r.choice([0, 0, 1, 2, 3, -1]))
    A = Mesh()
    idx = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            idx[i, j] = A.vert((float(i), float(j), H[i, j]))
    diags = {}
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            diags[i, j] = r.random() < 0.5
            if diags[i, j]:
                A.tri(a, b, c), A.tri(a, c, d)
            else:
                A.tri(a, b, d), A.tri(b, c, d)
    return A


def k_pow2_decimal(r):
    """Integer lattice surface scaled by a power of two (exact) against the same surface computed
    through decimal factors (i * 0.1 * 10 * 2^-k: off by ulps), maybe other diagonals."""
    A = _dyadic_grid(r)
    k = r.randint(-30, 30)
    sA = 2.0 ** k
    fac = r.choice([0.1, 0.2, 0.3, 0.7, 1.1])
    B = A.copy()
    if r.random() < 0.4:  # the other diagonal in some cells: re-triangulate B at random
        B = Mesh()
        B.v = list(A.v)
        for t in range(0, len(A.f), 2):
            a1, b1, c1 = A.f[t]
            a2, b2, c2 = A.f[t + 1]
            quad = sorted(set((a1, b1, c1, a2, b2, c2)))
            if r.random() < 0.5 or len(quad) != 4:
                B.f += [A.f[t], A.f[t + 1]]
            else:
                # quad vertices in lattice order: (i,j),(i+1,j),(i+1,j+1),(i,j+1)
                pts = sorted(quad, key=lambda v: (A.v[v][1], A.v[v][0]))
                a, b, d, c = pts
                if (a1, b1, c1) == (a, b, c):
                    B.f += [(a, b, d), (b, c, d)]
                else:
                    B.f += [(a, b, c), (a, c, d)]
    A = A.mapped(lambda p: mul(p, sA))
    B = B.mapped(lambda p: tuple(c * fac * (sA / fac) for c in p))
    A, B = place([A, B], r, exact=True, offset_mode=r.choice(["zero", "near", "zero"]))
    return A, B, {"placed": True}


def k_pow2_decimal_far(r):
    """As pow2_decimal, far from the origin: A offset by a dyadic vector exactly, B by the same
    vector plus and minus a decimal (off by ulps of the far coordinate)."""
    A = _dyadic_grid(r)
    k = r.randint(-20, 20)
    A = A.mapped(lambda p: mul(p, 2.0 ** k))
    lo, hi = A.bbox()
    size = norm(sub(tuple(hi), tuple(lo)))
    e = math.floor(math.log2(size * loguni(r, 3, 7.5)))
    off = tuple(float(r.randint(1, 7) * 2.0 ** e) * sgn(r) for _ in range(3))
    dec = r.choice([0.1, 0.3, 1e-3, 7.7])
    Am = A.mapped(lambda p: add(p, off))
    B = A.mapped(lambda p: tuple((c + (o + dec * 2.0 ** e)) - dec * 2.0 ** e for c, o in zip(p, off)))
    R = signed_perm(r)
    Am = Am.mapped(lambda p: mat_apply(R, p))
    B = B.mapped(lambda p: mat_apply(R, p))
    return Am, B, {"far": True, "placed": True}


def k_wire_vs_surface(r):
    """A surface against its own wire frame: every edge a zero-area triangle (a, b, a) or
    (a, mid, b), maybe its vertices as point triangles; the farthest points are equidistant from
    several edges."""
    choice = r.choice(["grid", "tetra", "octa", "cube", "icosa", "fan"])
    if choice == "grid":
        S = grid(r.randint(1, 4), r.randint(1, 4), zf=bump(r, r.choice([0.0, 0.1])) if r.random() < 0.5 else None, r=r)
    elif choice == "fan":
        S = fan((0.0, 0.0, r.choice([0.0, 0.3])), ngon(r.randint(3, 20)))
    else:
        S = solid(choice)
    W = Mesh()
    W.v = list(S.v)
    style = r.choice(["aba", "mid", "mixed"])
    for a, b in edges_of(S):
        s = style if style != "mixed" else r.choice(["aba", "mid", "abb"])
        if s == "aba":
            W.tri(a, b, a)
        elif s == "abb":
            W.tri(a, b, b)
        else:
            W.tri(a, W.vert(lerp(S.v[a], S.v[b], 0.5)), b)
    if r.random() < 0.3:
        for v in sorted({i for t in S.f for i in t}):
            if len(W.f) < 80:
                W.tri(v, v, v)
    if len(W.f) > 80:
        W.f = W.f[:80]
    if r.random() < 0.3:
        dz = loguni(r, -12, -3)
        W = W.mapped(lambda p: add(p, (0.0, 0.0, dz)))
    return S, W, {}


def k_points_on_circle(r):
    """Point triangles on a circle (or sphere) against a disc (or a tiny target) at the centre:
    the disc's centre is equidistant from every point."""
    N = r.randint(3, 60)
    jit = r.choice([0.0, 0.0, loguni(r, -13, -6)])
    sphere = r.random() < 0.25
    A = Mesh()
    pts = []
    if sphere:
        ga = math.pi * (3 - math.sqrt(5))
        for i in range(N):
            z = 1 - 2 * (i + 0.5) / N
            rr = math.sqrt(max(0.0, 1 - z * z))
            pts.append((rr * math.cos(ga * i), rr * math.sin(ga * i), z))
    else:
        pts = ngon(N, 1.0, 0.0, r.choice([0.0, r.uniform(0, 7)]))
    tiny = r.choice([0.0, 0.0, loguni(r, -15, -9)])
    for p in pts:
        p = add(p, mul(rand_dir(r), jit)) if jit else p
        if tiny:
            A.tri_pts(p, add(p, (tiny, 0.0, 0.0)), add(p, (0.0, tiny, 0.0)))
        else:
            i = A.vert(p)
            A.tri(i, i, i)
    if sphere or r.random() < 0.25:
        B = Mesh()
        s = loguni(r, -12, -2)
        B.tri_pts(*ngon(3, s, 0.0, r.uniform(0, 7)))
    else:
        M = r.randint(3, 40)
        Rd = r.choice([1.0, 1 - 1e-9, 0.5, 1.5, 1 + 1e-12])
        z0 = r.choice([0.0, 0.0, loguni(r, -9, 0)])
        ring = ngon(M, Rd, z0, r.uniform(0, 7))
        B = fan((0.0, 0.0, z0), ring) if r.random() < 0.6 else strip_poly(ring)
    return A, B, {}


def _coax(r, lo, hi, allow_n):
    n1 = r.randint(3, 40)
    th = r.uniform(0.05, 1.45)
    phase = r.uniform(0, 1)
    closed = n1 <= 40 and r.random() < 0.3
    A = cone(n1, th, phase=phase, closed=closed)
    delta = sgn(r) * loguni(r, lo, hi) if r.random() < 0.85 else 0.0
    apex = r.choice([0.0, sgn(r) * loguni(r, lo - 1, hi - 1)])
    if allow_n and r.random() < 0.5:
        n2 = r.randint(3, 40)
        B = cone(n2, th * (1 + delta), phase=r.uniform(0, 1), apex_z=apex, closed=closed and n2 <= 40)
    else:
        B = cone(n1, th * (1 + delta), phase=phase, apex_z=apex, closed=False)
        if closed:
            B.extend(fan((0.0, 0.0, apex + 1.0), ngon(n1, math.tan(th * (1 + delta)), apex + 1.0, phase)).flipped())
        if r.random() < 0.5 and 2 * n1 <= 80:  # split every side at its base edge's middle (coplanar)
            B2 = Mesh()
            B2.v = list(B.v)
            for a, b, c in B.f[:n1]:
                mpt = B2.vert(lerp(B.v[b], B.v[c], 0.5))
                B2.tri(a, b, mpt)
                B2.tri(a, mpt, c)
            if len(B2.f) + len(B.f) - n1 <= 80:
                B2.f += B.f[n1:]
                B = B2
    return A, B


def k_coaxial_cones(r):
    """Cones on one axis: half-angles 1e-12..1e-2 relative apart, other segment counts, apices
    shifted along the axis."""
    A, B = _coax(r, -12, -2, True)
    return A, B, {}


def k_coaxial_cones_far(r):
    """Near-coincident coaxial cones (same facets, maybe split; half-angles 1e-13..1e-8 apart),
    far from the origin."""
    A, B = _coax(r, -13, -8, False)
    return A, B, {"far": True}


def _twisted(r, far):
    M = r.randint(2, 20)
    w = loguni(r, -3, 0)
    tau = loguni(r, -13, -9) if far else loguni(r, -12, -3)

    def strip(M, twist, diag):
        m = Mesh()
        top, bot = [], []
        for i in range(M + 1):
            x = i / M
            a = twist * x
            top.append(m.vert((x, w / 2 * math.cos(a), w / 2 * math.sin(a))))
            bot.append(m.vert((x, -w / 2 * math.cos(a), -w / 2 * math.sin(a))))
        for i in range(M):
            a, b, c, d = bot[i], bot[i + 1], top[i + 1], top[i]
            flip = diag == "other" or (diag == "random" and r.random() < 0.5)
            if flip:
                m.tri(a, b, d), m.tri(b, c, d)
            else:
                m.tri(a, b, c), m.tri(a, c, d)
        return m
    A = strip(M, tau, "same")
    mode = r.choice(["flat", "other", "res"])
    if mode == "flat":
        B = strip(r.randint(1, 20), 0.0, "random")
    elif mode == "other":
        B = strip(M, tau, "other")
    else:
        B = strip(r.randint(1, 20), tau * r.choice([1.0, -1.0, 2.0]), "random")
    return A, B


def k_twisted_strip(r):
    """A strip twisted by 1e-12..1e-3 rad per length, against a flat or oppositely split strip."""
    A, B = _twisted(r, False)
    return A, B, {}


def k_twisted_strip_far(r):
    """A strip twisted by 1e-13..1e-9 rad against a flat, oppositely split or otherwise twisted
    strip, far from the origin (near-coincident)."""
    A, B = _twisted(r, True)
    return A, B, {"far": True}


def k_hinge_near_closed_far(r):
    """Two sheets on a hinge nearly shut (1e-13..1e-9 rad) against the bisecting sheet or one of
    them, or nearly flat (pi less that) against the flat sheet, far from the origin."""
    e = loguni(r, -13, -9)
    shut = r.random() < 0.5
    phi = e if shut else math.pi - e

    def sheet(ang, nx, ny, y0=0.0, h=1.0):
        g = grid(nx, ny, 0.0, y0, 1.0, h, r=r)
        R = rot_axis((1.0, 0.0, 0.0), ang)
        return g.mapped(lambda p: mat_apply(R, p) if ang else p)
    nx = r.randint(1, 4)
    A = sheet(0.0, nx, r.randint(1, 3))
    A.extend(sheet(phi, nx if r.random() < 0.7 else r.randint(1, 4), r.randint(1, 3)))
    if shut:
        B = sheet(r.choice([phi / 2, 0.0, phi]), r.randint(1, 4), r.randint(1, 3))
    else:
        B = sheet(0.0, r.randint(1, 4), r.randint(1, 6), -1.0, 2.0)
    if r.random() < 0.5:
        A, B = B, A
    return A, B, {"far": True}


def k_hinge_near_closed(r):
    """Two sheets on a hinge with a dihedral of 1e-12..1e-3 rad (nearly shut) or pi less that
    (nearly flat) or pi/2 +- tiny, against the bisecting sheet, one sheet or a fin on the hinge."""
    mode = r.choice(["shut", "flat", "right"])
    e = loguni(r, -12, -3)
    phi = {"shut": e, "flat": math.pi - e, "right": math.pi / 2 + sgn(r) * e * 1e-3}[mode]

    def sheet(ang, nx, ny):
        g = grid(nx, ny, r=r)  # x along the hinge, y away from it
        R = rot_axis((1.0, 0.0, 0.0), ang)
        return g.mapped(lambda p: mat_apply(R, p) if ang else p)
    nx = r.randint(1, 4)
    A = sheet(0.0, nx, r.randint(1, 3))
    A.extend(sheet(phi, nx if r.random() < 0.7 else r.randint(1, 4), r.randint(1, 3)))
    bmode = r.choice(["bisect", "one", "fin"])
    if bmode == "bisect":
        B = sheet(phi / 2, r.randint(1, 4), r.randint(1, 3))
    elif bmode == "one":
        B = sheet(r.choice([0.0, phi]), r.randint(1, 4), r.randint(1, 3))
    else:
        B = Mesh()
        B.tri_pts((0.2, 0.0, 0.0), (0.8, 0.0, 0.0), (0.5, -math.sin(phi / 2) * 0.5, -math.cos(phi / 2) * 0.5))
    if r.random() < 0.5:
        A, B = B, A
    return A, B, {}


def k_bowtie_vertex(r):
    """Non-manifold vertices: 2..4 open cones sharing their apex, against a plane through the
    apex, a slightly rotated copy or a tiny triangle at the apex."""
    k = r.randint(2, 4)
    axes = [(0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]
    if r.random() < 0.4:
        axes[1] = unit((loguni(r, -12, -4), 0.0, -1.0))
    while len(axes) < k:
        axes.append(rand_dir(r))
    A = Mesh()
    for ax in axes[:k]:
        n = r.randint(3, 10)
        th = r.uniform(0.1, 1.2)
        c = cone(n, th, height=r.uniform(0.5, 1.0), phase=r.uniform(0, 7))
        # rotate (0,0,1) to ax
        z = (0.0, 0.0, 1.0)
        v = cross(z, ax)
        if norm(v) < 1e-300:
            R = IDENT if ax[2] > 0 else ((1.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, -1.0))
        else:
            R = rot_axis(v, math.atan2(norm(v), dot(z, ax)))
        A.extend(c.mapped(lambda p: mat_apply(R, p)))
    mode = r.choice(["plane", "rotated", "target"])
    if mode == "plane":
        B = grid(r.randint(1, 4), r.randint(1, 4), -1.0, -1.0, 2.0, 2.0, r=r)
        if r.random() < 0.5:
            dz = sgn(r) * loguni(r, -13, -5)
            B = B.mapped(lambda p: (p[0], p[1], dz))
    elif mode == "rotated":
        R = rot_axis(rand_dir(r), loguni(r, -12, -3))
        B = A.mapped(lambda p: mat_apply(R, p))
        B = B.shuffled(r)
    else:
        B = Mesh()
        B.tri_pts(*[mat_apply(rand_rot(r), p) for p in ngon(3, loguni(r, -12, -3))])
    return A, B, {}


def k_fan_hub_shift_far(r):
    """A regular fan against the same ring with its hub moved 1e-13..1e-8 in the plane and
    1e-14..1e-9 out of it (or another count of spokes), far from the origin."""
    N = r.randint(3, 40)
    ring = ngon(N, 1.0, 0.0, r.uniform(0, 7))
    A = fan((0.0, 0.0, 0.0), ring)
    d = loguni(r, -13, -8)
    th = r.uniform(0, 7)
    hz = r.choice([0.0, sgn(r) * loguni(r, -14, -9)])
    B = fan((d * math.cos(th), d * math.sin(th), hz), ring)
    if r.random() < 0.3:
        B = B.flipped().shuffled(r)
    return A, B, {"far": True}


def k_nested_box_far(r):
    """A box against the box scaled by 1 +- 1e-13..1e-8 with another subdivision (1x1 or 2x2 cells
    a face, random diagonals), far from the origin."""
    size = (1.0, r.choice([1.0, r.uniform(0.1, 1.0)]), r.choice([1.0, loguni(r, -3, 0)]))
    A = cube_surface(r.choice([1, 2]), r, size)
    B = cube_surface(r.choice([1, 2]), r, size)
    eps = sgn(r) * loguni(r, -13, -8) if r.random() < 0.85 else 0.0
    B = B.mapped(lambda p: mul(p, 1 + eps))
    return A, B, {"far": True}


def k_ulp_noise_far(r):
    """A flat grid placed far away, every world coordinate then moved by -3..3 ulps, against the
    same grid or a coarse square over it, unmoved."""
    n1, n2 = r.randint(1, 6), r.randint(1, 6)
    A = grid(n1, n2, r=r)
    B = grid(1, 1, r=r) if r.random() < 0.5 else grid(n1, n2, r=r)
    A, B = place([A, B], r, far=True)
    A = A.mapped(lambda p: tuple(c + r.randint(-3, 3) * math.ulp(c) for c in p))
    return A, B, {"far": True, "placed": True}


def k_spike_grid(r):
    """A grid with 1..3 vertices pulled out 1..1e6 cells (steep slivers), against the flat grid,
    the spikes 1e-12..1e-6 relative longer, or a coarse square."""
    nx, ny = r.randint(2, 6), r.randint(2, 6)
    A = grid(nx, ny, r=r)
    inner = [v for v, p in enumerate(A.v) if 0 < p[0] < 1 and 0 < p[1] < 1]
    r.shuffle(inner)
    spikes = {v: sgn(r) * loguni(r, 0, 6) / max(nx, ny) for v in inner[:r.randint(1, 3)]}
    mode = r.choice(["flat", "longer", "coarse"])
    if mode == "flat":
        B = A.copy()
    elif mode == "coarse":
        B = grid(1, 1, r=r)
    else:
        rel = loguni(r, -12, -6)
        B = A.mapped(lambda p: p)
        for v, hgt in spikes.items():
            p = B.v[v]
            B.v[v] = (p[0], p[1], hgt * (1 + rel))
    for v, hgt in spikes.items():
        p = A.v[v]
        A.v[v] = (p[0], p[1], hgt)
    return A, B, {}


def k_pyramid_flat(r):
    """A regular N-gon fan with its hub raised by 1e-12..1e-1 against the flat N-gon split as a
    strip or a fan from a corner: the hub is equidistant from many of them."""
    A, B = _pyramid(r, -12, -1)
    return A, B, {}


def k_pyramid_flat_far(r):
    """As pyramid_flat with the hub raised by 1e-13..1e-9 (near-coincident), far away."""
    A, B = _pyramid(r, -13, -9)
    return A, B, {"far": True}


def _pyramid(r, lo, hi):
    N = r.randint(3, 40)
    ring = ngon(N, 1.0, 0.0, r.choice([0.0, r.uniform(0, 7)]))
    h = sgn(r) * loguni(r, lo, hi)
    A = fan((0.0, 0.0, h), ring)
    mode = r.choice(["strip", "corner", "hub"])
    if mode == "strip":
        B = strip_poly(ring)
    elif mode == "corner":
        B = fan_from_vertex(ring, r.randrange(N))
    else:
        B = fan((0.0, 0.0, 0.0), ring)
    if r.random() < 0.5:
        A, B = B, A
    return A, B


def k_zero_area_in_closed(r):
    """A closed solid with zero-area triangles mixed in (collapsed edges (i,i,j), collinear
    fillers at split edges, point triangles, nearly collinear faces), against the clean solid,
    scaled by 1 +- 1e-12..1e-2 or identical."""
    A, B = _zero_area_closed(r, -12, -2)
    return A, B, {}


def k_zero_area_in_closed_far(r):
    """As zero_area_in_closed, the clean solid scaled by 1 +- 1e-13..1e-9 or identical, far."""
    A, B = _zero_area_closed(r, -13, -9)
    return A, B, {"far": True}


def _zero_area_closed(r, lo, hi):
    name = r.choice(["octa_sub", "cube", "cube2", "icosa", "tetra_sub"])
    if name == "octa_sub":
        S = subdivide(solid("octa"), sphere=r.random() < 0.5)
    elif name == "cube2":
        S = cube_surface(2, r)
    elif name == "tetra_sub":
        S = subdivide(solid("tetra"))
    else:
        S = solid(name)
    A = Mesh()
    A.v = list(S.v)
    spare = 80 - len(S.f)  # triangles that may be added
    for a, b, c in S.f:
        u = r.random()
        if u < 0.15 and spare >= 2:
            spare -= 2
            mpt = A.vert(lerp(A.v[a], A.v[b], r.choice([0.5, 0.25, 1e-8])))
            A.tri(a, mpt, c), A.tri(mpt, b, c), A.tri(a, b, mpt)
        elif u < 0.25 and spare >= 1:
            spare -= 1
            A.tri(a, b, c), A.tri(a, a, b)
        elif u < 0.3 and spare >= 1:
            spare -= 1
            A.tri(a, b, c), A.tri(c, c, c)
        elif u < 0.38 and spare >= 1:
            spare -= 1
            A.tri(a, b, c)
            nrm = unit(cross(sub(A.v[b], A.v[a]), sub(A.v[c], A.v[a])))
            q = add(lerp(A.v[a], A.v[b], r.random()), mul(nrm, loguni(r, -15, -10)))
            A.tri(a, b, A.vert(q))
        else:
            A.tri(a, b, c)
    if r.random() < 0.5:
        A = A.shuffled(r)
    eps = r.choice([0.0, sgn(r) * loguni(r, lo, hi)])
    B = S.mapped(lambda p: mul(p, 1 + eps))
    return A, B


def k_grazing_vertex(r):
    """An inverted cone (or one triangle) touching a grid at one point with slopes of
    1e-12..1e-2: at a vertex, on an edge, inside a face, at the grid's corner or just off it."""
    n = r.randint(1, 5)
    A = grid(n, n, -1.0, -1.0, 2.0, 2.0, r=r)
    where = r.choice(["vertex", "edge", "face", "corner", "outside", "below"])
    cell = 2.0 / n
    if where == "vertex":
        P = (-1.0 + cell * r.randint(0, n), -1.0 + cell * r.randint(0, n), 0.0)
    elif where == "edge":
        P = (-1.0 + cell * (r.randint(0, n - 1) + r.random()), -1.0 + cell * r.randint(0, n), 0.0)
    elif where == "face":
        P = (r.uniform(-1, 1), r.uniform(-1, 1), 0.0)
    elif where == "corner":
        P = (-1.0, -1.0, 0.0)
    elif where == "outside":
        P = (1.0 + loguni(r, -12, -6), r.uniform(-1, 1), 0.0)
    else:
        P = (r.uniform(-1, 1), r.uniform(-1, 1), -loguni(r, -15, -10))
    slope = loguni(r, -12, -2)
    rho = r.uniform(0.1, 1.0)
    if r.random() < 0.7:
        N = r.randint(3, 30)
        ring = [(x, y, P[2] + rho * slope) for x, y, _ in ngon(N, rho, 0.0, r.uniform(0, 7), (P[0], P[1]))]
        B = fan(P, ring)
    else:
        th = r.uniform(0, 7)
        d = (math.cos(th), math.sin(th), 0.0)
        e = (-d[1], d[0], 0.0)
        q1 = add(add(P, mul(d, rho)), mul(e, rho * 0.5))
        q2 = add(add(P, mul(d, rho)), mul(e, -rho * 0.5))
        B = Mesh()
        B.tri_pts(P, (q1[0], q1[1], P[2] + rho * slope), (q2[0], q2[1], P[2] + rho * slope))
    if r.random() < 0.5:
        A, B = B, A
    return A, B, {}


def k_annulus_hole(r):
    """A coplanar annulus with a regular polygonal hole against a disc over the hole (or a tiny
    target at its centre): the hole's centre is equidistant from its edges."""
    N = r.randint(3, 24)
    M = r.choice([N, r.randint(3, 24)])
    rin = r.uniform(0.1, 0.9) * math.cos(math.pi / M)
    ph = r.choice([0.0, r.uniform(0, 7)])
    inner = ngon(N, rin, 0.0, ph)
    outer = ngon(M, 1.0, 0.0, ph if M == N else r.uniform(0, 7))
    A = ring_band(inner, outer)
    want = 0.5 * M * math.sin(2 * math.pi / M) - 0.5 * N * rin * rin * math.sin(2 * math.pi / N)
    if abs(tri_area_sum(A) - want) > 1e-9:  # the merge by angle overlapped: the same counts
        outer = ngon(N, 1.0, 0.0, ph)
        A = ring_band(inner, outer)
    mode = r.choice(["disc", "tiny", "fill"])
    z0 = r.choice([0.0, 0.0, sgn(r) * loguni(r, -13, -3)])
    if mode == "disc":
        K = r.randint(3, 30)
        Rd = r.choice([rin, rin * 0.5, 1.0, rin * (1 + 1e-9)])
        B = fan((0.0, 0.0, z0), ngon(K, Rd, z0, r.uniform(0, 7)))
    elif mode == "fill":
        B = fan((0.0, 0.0, z0), [(p[0], p[1], z0) for p in inner])
    else:
        B = Mesh()
        B.tri_pts(*ngon(3, loguni(r, -12, -3), z0, r.uniform(0, 7)))
    if r.random() < 0.4:
        A, B = B, A
    return A, B, {}


def k_rot90_inexact_far(r):
    """A shape symmetric under a rotation about z (a square grid, a square pyramid, a regular
    fan) against itself turned by that rotation computed with cos/sin (inexact: cos(pi/2) is
    6e-17), far from the origin; the triangulations differ where the shape's does not turn onto
    itself."""
    mode = r.choice(["grid", "pyramid", "fan"])
    if mode == "grid":
        n = r.randint(1, 6)
        A = grid(n, n, -1.0, -1.0, 2.0, 2.0, r=r)
        k = r.choice([1, 2, 3])
        ang = k * math.pi / 2
    elif mode == "pyramid":
        h = r.choice([1.0, loguni(r, -9, 0)])
        ring = [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0), (0.0, -1.0, 0.0)]
        A = fan((0.0, 0.0, h), ring)
        A.extend(fan_from_vertex(ring, r.randrange(4)).flipped())
        ang = r.choice([1, 2, 3]) * math.pi / 2
    else:
        N = r.randint(3, 40)
        h = r.choice([0.0, loguni(r, -9, -1)])
        A = fan((0.0, 0.0, h), ngon(N, 1.0))
        ang = r.randint(1, N - 1) * 2 * math.pi / N
    c, s = math.cos(ang), math.sin(ang)
    B = A.mapped(lambda p: (c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]))
    return A, B, {"far": True}


KINDS = [
    ("cone_axis_point", k_cone_axis_point),
    ("prism_axis_needle", k_prism_axis_needle),
    ("regular_solid_center", k_regular_solid_center),
    ("nested_solids", k_nested_solids),
    ("nested_solids_far", k_nested_solids_far),
    ("book_spine", k_book_spine),
    ("book_spine_far", k_book_spine_far),
    ("tjunction_zero_area", k_tjunction_zero_area),
    ("soup_crack_jitter", k_soup_crack_jitter),
    ("soup_crack_jitter_far", k_soup_crack_jitter_far),
    ("aniso_grid", k_aniso_grid),
    ("aniso_retri_far", k_aniso_retri_far),
    ("cross_tiny_angle", k_cross_tiny_angle),
    ("cross_tiny_angle_far", k_cross_tiny_angle_far),
    ("mirror_tilted", k_mirror_tilted),
    ("point_touch", k_point_touch),
    ("huge_tiny_scatter", k_huge_tiny_scatter),
    ("sliver_fan_tilted_grid", k_sliver_fan_tilted_grid),
    ("crossing_slivers", k_crossing_slivers),
    ("pow2_decimal", k_pow2_decimal),
    ("pow2_decimal_far", k_pow2_decimal_far),
    ("wire_vs_surface", k_wire_vs_surface),
    ("points_on_circle", k_points_on_circle),
    ("coaxial_cones", k_coaxial_cones),
    ("coaxial_cones_far", k_coaxial_cones_far),
    ("twisted_strip", k_twisted_strip),
    ("hinge_near_closed", k_hinge_near_closed),
    ("bowtie_vertex", k_bowtie_vertex),
    ("fan_hub_shift_far", k_fan_hub_shift_far),
    ("nested_box_far", k_nested_box_far),
    ("ulp_noise_far", k_ulp_noise_far),
    ("spike_grid", k_spike_grid),
    ("pyramid_flat", k_pyramid_flat),
    ("zero_area_in_closed", k_zero_area_in_closed),
    ("grazing_vertex", k_grazing_vertex),
    ("annulus_hole", k_annulus_hole),
    ("rot90_inexact_far", k_rot90_inexact_far),
    ("tjunction_zero_area_far", k_tjunction_zero_area_far),
    ("mirror_tilted_far", k_mirror_tilted_far),
    ("twisted_strip_far", k_twisted_strip_far),
    ("hinge_near_closed_far", k_hinge_near_closed_far),
    ("pyramid_flat_far", k_pyramid_flat_far),
    ("zero_area_in_closed_far", k_zero_area_in_closed_far),
]


def generate(seed):
    name, fn = KINDS[seed % len(KINDS)]
    r = random.Random(seed)
    A, B, info = fn(r)
    if not info.get("placed"):
        A, B = place([A, B], r, far=info.get("far", False))
    if r.random() < 0.5:
        A = A.shuffled(r)
    for m in (A, B):
        if not 1 <= len(m.f) <= 80:
            raise RuntimeError("seed %d (%s): %d triangles" % (seed, name, len(m.f)))
        for p in m.v:
            if not all(math.isfinite(c) for c in p):
                raise RuntimeError("seed %d (%s): a non-finite coordinate" % (seed, name))
    return name, A, B


def write_obj(path, m, comment):
    used = sorted({i for t in m.f for i in t})
    new = {old: k + 1 for k, old in enumerate(used)}
    lines = ["# " + comment]
    for i in used:
        p = m.v[i]
        lines.append("v %s %s %s" % (repr(p[0]), repr(p[1]), repr(p[2])))
    for a, b, c in m.f:
        lines.append("f %d %d %d" % (new[a], new[b], new[c]))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: %s OUTDIR SEED_FROM SEED_TO\n" % argv[0])
        return 2
    out, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for seed in range(lo, hi):
        name, A, B = generate(seed)
        stem = os.path.join(out, "%06d_%s" % (seed, name))
        write_obj(stem + "_a.obj", A, "generate_pairs7.py seed %d kind %s mesh A" % (seed, name))
        write_obj(stem + "_b.obj", B, "generate_pairs7.py seed %d kind %s mesh B" % (seed, name))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
