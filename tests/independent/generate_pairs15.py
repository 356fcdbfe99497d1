#!/usr/bin/env python3
"""
NAME
    generate_pairs15.py - adversarial triangle-mesh pairs (set 15) for an
    exact Hausdorff-distance tool

    Written BLIND: without reading the tool's code or any of its other test
    generators, only from a verbal description of its algorithm (per
    triangle of A, an exact planar subdivision of the squared distance to B
    into face-plane / edge-line / vertex domains bounded by lines and conics).

SYNOPSIS
    python3 generate_pairs15.py OUTDIR FROM TO

DESCRIPTION
    For every integer seed s in [FROM, TO) write OUTDIR/NNNNNN_KIND_a.obj and
    OUTDIR/NNNNNN_KIND_b.obj, NNNNNN = s zero-padded to 6 digits,
    KIND = KINDS[s % len(KINDS)].  OUTDIR is created if missing.  All
    randomness comes from random.Random(s): output depends only on s.
    Nothing is printed per pair; one summary line is printed at the end.
    Python 3 standard library only.

FORMAT
    One comment line ('# gen15 seed=.. kind=.. mesh=a|b <parameters>'), then
    'v x y z' lines written with repr(float) (exact double round trip), then
    'f i j k' lines (1-based).  Every mesh: 1..200 triangles (mostly <= 60),
    finite coordinates, valid indices, no unused vertices (checked before
    writing, ValueError otherwise), at most 40 triangles around one vertex
    (counted by index and by coordinates; a pair violating this is redrawn
    from the same random stream).  Zero-area faces (repeated index, repeated
    coordinates, collinear corners) occur on purpose in several kinds.

PLACEMENT (one map, applied to both meshes of a pair after construction)
    none        identity (construction coordinates, often dyadic)
    exact       axis permutation, sign flips, power-of-two scale, dyadic
                translation of a few sizes (keeps dyadic ties exact)
    rot         uniformly random rotation + random translation
    exact+tiny  exact, then a rotation by 1e-14..1e-4 rad about a random axis
    Kinds ending in _far then add an offset of 1e3..1e7 pair sizes
    (float32_far: 1e3..1e5), axis-aligned, diagonal or random direction,
    sometimes rounded to a dyadic value.

KINDS (one line each)
    lod_sphere       large-radius sphere patch (R 3..1e9): fine grid/subdivided triangle vs coarse, shared vertices exact
    lod_cylinder     large-radius cylinder strip (long, needle-like strips) fine vs coarse angular tessellation
    lod_saddle       paraboloid / saddle / monkey saddle / parabolic ridge (coeff 1e-9..1e-1), fine vs coarse
    sin_bump         sinusoidal bumps, amplitude 1e-9..1e-3, fine grid vs flat, vs LOD, vs tangentially jittered copy
    mtet_iso         marching-tetrahedra isosurface (slivers / zero-area near grid points) vs smooth heightfield
    float32_export   double mesh vs the same mesh rounded to float32 after placement (optionally welded)
    quad_diag        slightly non-planar quads (1e-12..1e-1) split along one diagonal in A, the other in B
    terrain_crack    two terrain tiles of different resolution (T-junction cracks, skirts, 1e-12 overlaps/gaps) vs continuous/stitched
    mirror_seam      dyadic mirrored model, duplicated seam vertices/faces, vs merged/offset/lifted mirror (exact ties)
    box_union        union of two boxes retriangulated on the cell grid (flush / 1e-12-near faces) vs the two whole boxes
    thin_wall        extruded polyline wall of thickness 1e-12..1e-4 (both sides, caps) vs its mid-surface
    vertex_nudge     mesh vs itself with vertices moved 1e-15..1e-6 (normal, tangent, onto vertex/edge)
    flat_apex        pyramid/cone with apex height 1e-12..1e-4 vs base polygon (fans, random or Steiner retriangulation)
    flat_fan         fan of up to 32 nearly coplanar triangles (normal angles 1e-12..1e-5) vs a flat fan
    twisted_strip    helicoidal strip (total twist 1e-12..1e-1 rad) vs flat / counter-twisted strip
    degenerate_only  only zero-area faces (points, segments, collinear, repeated coordinates) vs a surface, or vice versa
    needle_fan       needles / slivers of aspect 1e3..1e12: fans, strips, nearly parallel crossing needles and fins
    star_cross       flat triangles vs a star of up to 24 spokes whose region lines meet at (nearly) one point
    ridge_pair       flat triangles vs nearly flat folds with nearly parallel / coincident ridge lines, or skew fins
    coplanar_retri   exactly coplanar dyadic polygon, two triangulations with Steiner points / T-junctions
    sandwich_tie     flat grid exactly midway between two dyadic layers (planes, mirrored bumps/roofs, shifted grids)
    scaled_mix       one of the kinds above, the whole pair scaled to ~1e-6 or ~1e6
    float32_far      float32_export placed 1e3..1e5 sizes from the origin
    lod_sphere_far   lod_sphere placed 1e3..1e7 sizes from the origin
    quad_diag_far    quad_diag placed 1e3..1e7 sizes from the origin
    vertex_nudge_far vertex_nudge placed 1e3..1e7 sizes from the origin
    thin_wall_far    thin_wall placed 1e3..1e7 sizes from the origin
"""

import sys
import os
import math
import random
import struct

TAU = 2.0 * math.pi
MAX_TRIS = 200
SOFT_MAX_TRIS = 150
MAX_VALENCE = 40


# ----------------------------------------------------------------- helpers
def lu(rng, a, b):
    """log-uniform 10**U(a, b)"""
    return 10.0 ** rng.uniform(a, b)


def sgn(rng):
    return 1.0 if rng.random() < 0.5 else -1.0


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def lerp(a, b, t):
    if t == 0:
        return a
    if t == 1:
        return b
    return a + (b - a) * t


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vmul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def vlen(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = vlen(a)
    if n > 0:
        return (a[0] / n, a[1] / n, a[2] / n)
    return (0.0, 0.0, 1.0)


def rand_unit(rng):
    while True:
        v = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        if vlen(v) > 1e-3:
            return unit(v)


def bary(a, b, c, w0, w1, w2):
    return (w0 * a[0] + w1 * b[0] + w2 * c[0],
            w0 * a[1] + w1 * b[1] + w2 * c[1],
            w0 * a[2] + w1 * b[2] + w2 * c[2])


def fmt(x):
    return '%.3g' % x


class Mesh(object):
    """vertices (tuples of float) + triangles (0-based index triples)"""

    def __init__(self):
        self.v = []
        self.f = []
        self.keys = {}

    def add(self, p, key=None):
        if key is not None:
            i = self.keys.get(key)
            if i is not None:
                return i
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        i = len(self.v) - 1
        if key is not None:
            self.keys[key] = i
        return i

    def addw(self, p):
        """add, welding exactly equal coordinates"""
        p = (float(p[0]), float(p[1]), float(p[2]))
        return self.add(p, key=('w',) + p)

    def tri(self, a, b, c):
        self.f.append((a, b, c))

    def quad(self, a, b, c, d, diag):
        """quad a-b-c-d; diag 0 splits along a-c, 1 along b-d"""
        if diag:
            self.f.append((a, b, d))
            self.f.append((b, c, d))
        else:
            self.f.append((a, b, c))
            self.f.append((a, c, d))

    def extend(self, other):
        off = len(self.v)
        self.v.extend(other.v)
        self.f.extend((a + off, b + off, c + off) for a, b, c in other.f)
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

    def welded(self):
        m = Mesh()
        idx = [m.addw(p) for p in self.v]
        m.f = [(idx[a], idx[b], idx[c]) for a, b, c in self.f]
        return m

    def compact(self):
        used = sorted(set(i for f in self.f for i in f))
        remap = dict((o, n) for n, o in enumerate(used))
        m = Mesh()
        m.v = [self.v[i] for i in used]
        m.f = [(remap[a], remap[b], remap[c]) for a, b, c in self.f]
        return m

    def flipped(self):
        m = self.copy()
        m.f = [(a, c, b) for a, b, c in self.f]
        return m


def diag_fn(rng, mode=None):
    """quad split pattern (i, j) -> 0/1; f.mode names it"""
    if mode is None:
        mode = rng.choice(['a', 'b', 'alt', 'rand'])
    if mode == 'a':
        f = lambda i, j: 0
    elif mode == 'b':
        f = lambda i, j: 1
    elif mode == 'alt':
        f = lambda i, j: (i + j) % 2
    else:
        memo = {}

        def f(i, j):
            if (i, j) not in memo:
                memo[(i, j)] = rng.randrange(2)
            return memo[(i, j)]
    f.mode = mode
    return f


def grid_mesh(nu, nv, pos, diag, m=None, weld=False):
    """(nu x nv) quad grid; pos(u, v) with u = i/nu, v = j/nv"""
    if m is None:
        m = Mesh()
    ids = {}
    for i in range(nu + 1):
        for j in range(nv + 1):
            p = pos(i / nu, j / nv)
            ids[(i, j)] = m.addw(p) if weld else m.add(p)
    for i in range(nu):
        for j in range(nv):
            m.quad(ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)],
                   ids[(i, j + 1)], diag(i, j))
    return m


def tri_subdiv(k, c0, c1, c2, zf, m=None):
    """triangle (xy corners c0 c1 c2) split into k*k, lifted by zf"""
    if m is None:
        m = Mesh()
    ids = {}
    for i in range(k + 1):
        for j in range(k + 1 - i):
            w1 = i / k
            w2 = j / k
            w0 = (k - i - j) / k
            x = w0 * c0[0] + w1 * c1[0] + w2 * c2[0]
            y = w0 * c0[1] + w1 * c1[1] + w2 * c2[1]
            ids[(i, j)] = m.add((x, y, zf(x, y)))
    for i in range(k):
        for j in range(k - i):
            m.tri(ids[(i, j)], ids[(i + 1, j)], ids[(i, j + 1)])
            if i + j < k - 1:
                m.tri(ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)])
    return m


def box_mesh(lo, hi, rng, m=None):
    """12-triangle box"""
    if m is None:
        m = Mesh()
    ids = {}
    for a in range(2):
        for b in range(2):
            for c in range(2):
                ids[(a, b, c)] = m.add((hi[0] if a else lo[0],
                                        hi[1] if b else lo[1],
                                        hi[2] if c else lo[2]))
    quads = [((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)),
             ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)),
             ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)),
             ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),
             ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)),
             ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1))]
    for q in quads:
        m.quad(ids[q[0]], ids[q[1]], ids[q[2]], ids[q[3]], rng.randrange(2))
    return m


def random_convex_triangulation(rng, lst, out):
    """random triangulation of a convex polygon given as a ccw index list"""
    if len(lst) < 3:
        return
    if len(lst) == 3:
        out.append((lst[0], lst[1], lst[2]))
        return
    k = rng.randint(1, len(lst) - 2)
    out.append((lst[0], lst[k], lst[-1]))
    random_convex_triangulation(rng, lst[:k + 1], out)
    random_convex_triangulation(rng, lst[k:], out)


def sphere_sag(r2, R):
    """sagitta of a sphere of radius R at squared distance r2 (stable)"""
    return r2 / (R + math.sqrt(R * R - r2))


class Pair(object):
    def __init__(self, a, b, desc, place=None, post=None):
        self.a = a
        self.b = b
        self.desc = desc
        self.place = place
        self.post = post


def maybe_swap(rng, a, b, p=0.3):
    if rng.random() < p:
        return b, a, ' swapped'
    return a, b, ''


# ----------------------------------------------------- base mesh library
def base_heightfield(rng):
    nu = rng.randint(2, 5)
    nv = rng.randint(2, 5)
    amp = lu(rng, -3, 0)
    wy = rng.choice([1.0, rng.uniform(0.3, 2.0)])
    terms = [(rng.uniform(0.5, 5), rng.uniform(0.5, 5), rng.uniform(0, TAU))
             for _ in range(rng.randint(1, 2))]

    def pos(u, v):
        x = u
        y = lerp(0.0, wy, v)
        return (x, y, amp * sum(math.sin(a * x + b * y + c) for a, b, c in terms))
    d = diag_fn(rng)
    return grid_mesh(nu, nv, pos, d), 'heightfield %dx%d amp=%s' % (nu, nv, fmt(amp))


def base_ellipsoid(rng):
    r = (rng.uniform(0.2, 1), rng.uniform(0.2, 1), rng.uniform(0.2, 1))
    m = Mesh()
    pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4),
             (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    level = rng.choice([0, 1, 1])
    P = [tuple(float(c) for c in p) for p in pts]
    if level == 1:
        mid = {}

        def mp(a, b):
            k = (min(a, b), max(a, b))
            if k not in mid:
                P.append(unit(vmul(vadd(P[a], P[b]), 0.5)))
                mid[k] = len(P) - 1
            return mid[k]
        nf = []
        for a, b, c in faces:
            ab, bc, ca = mp(a, b), mp(b, c), mp(c, a)
            nf += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = nf
    for p in P:
        m.add((p[0] * r[0], p[1] * r[1], p[2] * r[2]))
    m.f = faces
    return m, 'ellipsoid level=%d' % level


def base_box(rng):
    lo = (0.0, 0.0, 0.0)
    hi = (rng.uniform(0.2, 1), rng.uniform(0.2, 1), rng.uniform(0.2, 1))
    k = rng.choice([1, 1, 2])
    m = Mesh()
    for d in range(3):
        d1, d2 = (d + 1) % 3, (d + 2) % 3
        for side in (lo[d], hi[d]):
            ids = {}
            for i in range(k + 1):
                for j in range(k + 1):
                    p = [0.0, 0.0, 0.0]
                    p[d] = side
                    p[d1] = lerp(lo[d1], hi[d1], i / k)
                    p[d2] = lerp(lo[d2], hi[d2], j / k)
                    ids[(i, j)] = m.addw(p)
            for i in range(k):
                for j in range(k):
                    m.quad(ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)],
                           ids[(i, j + 1)], rng.randrange(2))
    return m, 'box k=%d' % k


def base_torus(rng):
    nu = rng.randint(5, 8)
    nv = rng.randint(3, 4)
    R0 = 1.0
    r0 = rng.uniform(0.1, 0.5)
    m = Mesh()
    ids = {}
    for i in range(nu):
        for j in range(nv):
            a = TAU * i / nu
            b = TAU * j / nv
            ids[(i, j)] = m.add(((R0 + r0 * math.cos(b)) * math.cos(a),
                                 (R0 + r0 * math.cos(b)) * math.sin(a),
                                 r0 * math.sin(b)))
    for i in range(nu):
        for j in range(nv):
            m.quad(ids[(i, j)], ids[((i + 1) % nu, j)],
                   ids[((i + 1) % nu, (j + 1) % nv)], ids[(i, (j + 1) % nv)],
                   rng.randrange(2))
    return m, 'torus %dx%d r=%s' % (nu, nv, fmt(r0))


def base_cylinder(rng):
    k = rng.randint(5, 10)
    nr = rng.choice([1, 2])
    r = rng.uniform(0.2, 1)
    h = rng.uniform(0.2, 2)
    m = Mesh()
    ids = {}
    for i in range(k):
        a = TAU * i / k
        for j in range(nr + 1):
            ids[(i, j)] = m.add((r * math.cos(a), r * math.sin(a), lerp(0.0, h, j / nr)))
    for i in range(k):
        for j in range(nr):
            m.quad(ids[(i, j)], ids[((i + 1) % k, j)], ids[((i + 1) % k, j + 1)],
                   ids[(i, j + 1)], rng.randrange(2))
    cb = m.add((0.0, 0.0, 0.0))
    ct = m.add((0.0, 0.0, h))
    for i in range(k):
        m.tri(cb, ids[((i + 1) % k, 0)], ids[(i, 0)])
        m.tri(ct, ids[(i, nr)], ids[((i + 1) % k, nr)])
    return m, 'cylinder k=%d rings=%d' % (k, nr)


BASES = [base_heightfield, base_ellipsoid, base_box, base_torus, base_cylinder]


def base_mesh(rng):
    return rng.choice(BASES)(rng)


# ------------------------------------------------ fine/coarse LOD helper
def lod_pair(rng, zf, x0, x1, y0, y1):
    """fine and coarse tessellations of z = zf(x, y) over a box"""
    def pos(u, v):
        x = lerp(x0, x1, u)
        y = lerp(y0, y1, v)
        return (x, y, zf(x, y))
    r = rng.random()
    if r < 0.5:
        nc = rng.choice([1, 1, 2])
        nf = rng.randint(2, 5) if nc == 1 else 4
        df, dc = diag_fn(rng), diag_fn(rng)
        fine = grid_mesh(nf, nf, pos, df)
        coarse = grid_mesh(nc, nc, pos, dc)
        desc = 'grid nf=%d nc=%d shared diag=%s/%s' % (nf, nc, df.mode, dc.mode)
    elif r < 0.65:
        nc = 2
        nfu, nfv = rng.choice([3, 5]), rng.choice([3, 4, 5])
        df, dc = diag_fn(rng), diag_fn(rng)
        fine = grid_mesh(nfu, nfv, pos, df)
        coarse = grid_mesh(nc, nc, pos, dc)
        desc = 'grid nf=%dx%d nc=%d unshared' % (nfu, nfv, nc)
    elif r < 0.78:
        nf = rng.randint(3, 5)
        nc = rng.choice([1, 2]) if nf % 2 == 0 else 1
        jit = lu(rng, -12, -4) * (x1 - x0)
        jm = {}

        def posj(u, v):
            x = lerp(x0, x1, u)
            y = lerp(y0, y1, v)
            if 0 < u < 1 and 0 < v < 1:
                if (u, v) not in jm:
                    jm[(u, v)] = (rng.uniform(-1, 1) * jit, rng.uniform(-1, 1) * jit)
                x += jm[(u, v)][0]
                y += jm[(u, v)][1]
            return (x, y, zf(x, y))
        fine = grid_mesh(nf, nf, posj, diag_fn(rng))
        coarse = grid_mesh(nc, nc, pos, diag_fn(rng))
        desc = 'grid nf=%d nc=%d tangential-jitter=%s' % (nf, nc, fmt(jit))
    else:
        W = x1 - x0
        H = y1 - y0
        if rng.random() < 0.4:
            c0, c1, c2 = (x0, y0), (x1, y0), (x0, y1)
        else:
            c0 = (x0 + rng.uniform(0, 0.3) * W, y0 + rng.uniform(0, 0.3) * H)
            c1 = (x0 + rng.uniform(0.7, 1) * W, y0 + rng.uniform(0, 1) * H)
            c2 = (x0 + rng.uniform(0, 1) * W, y0 + rng.uniform(0.7, 1) * H)
        kf = rng.randint(2, 6)
        kc = rng.choice([d for d in (1, 2, 3) if kf % d == 0 and d < kf])
        fine = tri_subdiv(kf, c0, c1, c2, zf)
        coarse = tri_subdiv(kc, c0, c1, c2, zf)
        desc = 'trisubdiv kf=%d kc=%d' % (kf, kc)
    return fine, coarse, desc


# ------------------------------------------------------------------ kinds
def k_lod_sphere(rng):
    R = lu(rng, 0.5, 9)
    s = sgn(rng)
    if rng.random() < 0.5:
        cx = cy = 0.0
    else:
        cx, cy = rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)
    zf = lambda x, y: -s * sphere_sag((x - cx) ** 2 + (y - cy) ** 2, R)
    fine, coarse, d = lod_pair(rng, zf, -0.5, 0.5, -0.5, 0.5)
    extra = ''
    if rng.random() < 0.2:
        sh = 0.5 * sphere_sag(0.5, R) * -s
        coarse = coarse.mapped(lambda p: (p[0], p[1], p[2] + sh))
        extra = ' coarse-shift=%s' % fmt(sh)
    A, B, sw = maybe_swap(rng, fine, coarse)
    return Pair(A, B, 'R=%s convex=%d %s%s%s' % (fmt(R), s > 0, d, extra, sw))


def k_lod_cylinder(rng):
    R = lu(rng, 0, 8)
    Th = 1.0 / R
    Ly = lu(rng, -1, 3)
    s = sgn(rng)

    def pos(u, v):
        th = -0.5 * Th + Th * u
        return (R * math.sin(th), lerp(0.0, Ly, v), -s * 2.0 * R * math.sin(0.5 * th) ** 2)
    nf = rng.randint(2, 12)
    shared = rng.random() < 0.8
    if shared:
        nc = rng.choice([d for d in range(1, nf) if nf % d == 0])
    else:
        nc = rng.randint(1, nf - 1)
    nyf = rng.choice([1, 1, 2])
    nyc = 1
    df, dc = diag_fn(rng), diag_fn(rng)
    fine = grid_mesh(nf, nyf, pos, df)
    coarse = grid_mesh(nc, nyc, pos, dc)
    A, B, sw = maybe_swap(rng, fine, coarse)
    return Pair(A, B, 'R=%s L=%s nf=%dx%d nc=%d shared=%d%s' %
                (fmt(R), fmt(Ly), nf, nyf, nc, shared, sw))


def k_lod_saddle(rng):
    shape = rng.choice(['paraboloid', 'saddle', 'monkey', 'ridge', 'twist'])
    a = sgn(rng) * lu(rng, -9, -1)
    if rng.random() < 0.5:
        cx = cy = 0.0
    else:
        cx, cy = rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4)
    if shape == 'paraboloid':
        b = a * rng.choice([1.0, rng.uniform(0.2, 5)])
        zf = lambda x, y: a * (x - cx) ** 2 + b * (y - cy) ** 2
    elif shape == 'saddle':
        b = -a * rng.choice([1.0, rng.uniform(0.2, 5)])
        zf = lambda x, y: a * (x - cx) ** 2 + b * (y - cy) ** 2
    elif shape == 'monkey':
        zf = lambda x, y: a * ((x - cx) ** 3 - 3 * (x - cx) * (y - cy) ** 2)
    elif shape == 'ridge':
        zf = lambda x, y: a * (x - cx) ** 2
    else:
        zf = lambda x, y: a * (x - cx) * (y - cy)
    fine, coarse, d = lod_pair(rng, zf, -0.5, 0.5, -0.5, 0.5)
    A, B, sw = maybe_swap(rng, fine, coarse)
    return Pair(A, B, '%s a=%s centre=(%s,%s) %s%s' % (shape, fmt(a), fmt(cx), fmt(cy), d, sw))


def k_sin_bump(rng):
    amp = lu(rng, -9, -3)
    kx, ky = rng.uniform(0.5, 3) * TAU, rng.uniform(0.5, 3) * TAU
    px, py = rng.choice([0.0, rng.uniform(0, TAU)]), rng.choice([0.0, rng.uniform(0, TAU)])
    zf = lambda x, y: amp * math.sin(kx * x + px) * math.sin(ky * y + py)
    variant = rng.choice(['flat', 'lod', 'lod', 'jitter'])
    if variant == 'flat':
        n = rng.randint(3, 5)
        fine = grid_mesh(n, n, lambda u, v: (u, v, zf(u, v)), diag_fn(rng))
        nc = rng.choice([1, 2])
        coarse = grid_mesh(nc, nc, lambda u, v: (u, v, 0.0), diag_fn(rng))
        d = 'flat n=%d nc=%d' % (n, nc)
    elif variant == 'lod':
        fine, coarse, d = lod_pair(rng, zf, 0.0, 1.0, 0.0, 1.0)
    else:
        n = rng.randint(3, 5)
        dg = diag_fn(rng)
        fine = grid_mesh(n, n, lambda u, v: (u, v, zf(u, v)), dg)
        jit = lu(rng, -12, -5)
        jm = {}

        def pj(u, v):
            x, y = u, v
            if 0 < u < 1 and 0 < v < 1:
                if (u, v) not in jm:
                    jm[(u, v)] = (rng.uniform(-1, 1) * jit, rng.uniform(-1, 1) * jit)
                x += jm[(u, v)][0]
                y += jm[(u, v)][1]
            return (x, y, zf(x, y))
        coarse = grid_mesh(n, n, pj, dg if rng.random() < 0.5 else diag_fn(rng))
        d = 'jitter n=%d jit=%s' % (n, fmt(jit))
    A, B, sw = maybe_swap(rng, fine, coarse)
    return Pair(A, B, 'amp=%s %s%s' % (fmt(amp), d, sw))


KUHN = []
for _perm in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
    _cur = [0, 0, 0]
    _t = [tuple(_cur)]
    for _ax in _perm:
        _cur[_ax] += 1
        _t.append(tuple(_cur))
    KUHN.append(_t)


def marching_tets(nx, ny, nz, fz, weld):
    """isosurface f = z - H(x, y) = 0 of the Kuhn-triangulated integer grid"""
    F = {}
    for i in range(nx + 1):
        for j in range(ny + 1):
            for k in range(nz + 1):
                F[(i, j, k)] = fz(float(i), float(j), float(k))
    m = Mesh()

    def ep(gi, go):
        fi, fo = F[gi], F[go]
        t = fi / (fi - fo)
        p = tuple(gi[c] * (1.0 - t) + go[c] * t for c in range(3))
        if weld:
            return m.addw(p)
        return m.add(p, key=(min(gi, go), max(gi, go)))
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                for tet in KUHN:
                    g = [(i + a, j + b, k + c) for a, b, c in tet]
                    ins = [q for q in g if F[q] < 0]
                    out = [q for q in g if not F[q] < 0]
                    if len(ins) == 1:
                        m.tri(ep(ins[0], out[0]), ep(ins[0], out[1]), ep(ins[0], out[2]))
                    elif len(ins) == 3:
                        m.tri(ep(ins[0], out[0]), ep(ins[1], out[0]), ep(ins[2], out[0]))
                    elif len(ins) == 2:
                        a, b = ins
                        c, d = out
                        ac, ad, bd, bc = ep(a, c), ep(a, d), ep(b, d), ep(b, c)
                        m.tri(ac, ad, bd)
                        m.tri(ac, bd, bc)
    return m


def k_mtet_iso(rng):
    for _ in range(50):
        nx, ny = rng.choice([(1, 1), (2, 1), (1, 2), (2, 2), (3, 1)])
        nz = 2
        shape = rng.choice(['plane', 'level', 'sphere', 'saddle', 'wave'])
        delta = rng.choice([0.0, sgn(rng) * lu(rng, -15, -3), sgn(rng) * lu(rng, -15, -3)])
        cx, cy = rng.choice([(0.0, 0.0), (nx * 0.5, ny * 0.5),
                             (rng.uniform(0, nx), rng.uniform(0, ny))])
        if shape == 'plane':
            a = rng.choice([0.0, sgn(rng) * lu(rng, -12, -0.8)])
            b = sgn(rng) * lu(rng, -12, -0.8)
            H = lambda x, y: 1.0 + delta + a * (x - cx) + b * (y - cy)
            par = 'a=%s b=%s' % (fmt(a), fmt(b))
        elif shape == 'level':
            H = lambda x, y: 1.0 + delta
            par = ''
        elif shape == 'sphere':
            R = lu(rng, 1, 6)
            sg = sgn(rng)
            H = lambda x, y: 1.0 + delta - sg * sphere_sag((x - cx) ** 2 + (y - cy) ** 2, R)
            par = 'R=%s' % fmt(R)
        elif shape == 'saddle':
            c = sgn(rng) * lu(rng, -9, -1.3)
            H = lambda x, y: 1.0 + delta + c * ((x - cx) ** 2 - (y - cy) ** 2)
            par = 'c=%s' % fmt(c)
        else:
            A = lu(rng, -9, -1)
            kx = rng.uniform(0.3, 2) * TAU / max(nx, 1)
            H = lambda x, y: 1.0 + delta + A * math.sin(kx * (x - cx)) * math.cos(kx * (y - cy))
            par = 'A=%s' % fmt(A)
        ok = all(0.05 < H(float(i), float(j)) < 1.95
                 for i in range(nx + 1) for j in range(ny + 1))
        if not ok:
            continue
        weld = rng.random() < 0.4
        A_ = marching_tets(nx, ny, nz, lambda x, y, z: z - H(x, y), weld)
        if not (1 <= len(A_.f) <= 80):
            continue
        variant = rng.choice(['heightfield', 'heightfield', 'mtet_other'])
        if variant == 'heightfield':
            mx, my = rng.randint(1, 4), rng.randint(1, 4)
            B_ = grid_mesh(mx, my, lambda u, v: (lerp(0.0, float(nx), u), lerp(0.0, float(ny), v),
                                               H(lerp(0.0, float(nx), u), lerp(0.0, float(ny), v))),
                           diag_fn(rng))
            vd = 'heightfield %dx%d' % (mx, my)
        else:
            d2 = delta + sgn(rng) * lu(rng, -15, -5)
            B_ = marching_tets(nx, ny, nz, lambda x, y, z: z - (H(x, y) - delta + d2), not weld)
            vd = 'mtet delta2=%s' % fmt(d2)
            if not (1 <= len(B_.f) <= 80):
                continue
        A, B, sw = maybe_swap(rng, A_, B_, 0.25)
        return Pair(A, B, '%s %s delta=%s grid=%dx%dx%d weld=%d vs %s%s' %
                    (shape, par, fmt(delta), nx, ny, nz, weld, vd, sw))
    raise RuntimeError('mtet_iso: no valid configuration')


def k_float32(rng):
    base, bd = base_mesh(rng)
    variant = rng.choice(['b32', 'b32', 'b32_weld', 'both32_jitter', 'b32_perm'])
    A = base
    B = base.copy()
    if variant == 'both32_jitter':
        sz = bbox_size(base)
        j = lu(rng, -9, -6) * sz
        B = B.mapped(lambda p: (p[0] + rng.uniform(-j, j), p[1] + rng.uniform(-j, j),
                                p[2] + rng.uniform(-j, j)))
    if variant == 'b32_perm':
        order = list(range(len(B.v)))
        rng.shuffle(order)
        inv = [0] * len(order)
        for n, o in enumerate(order):
            inv[o] = n
        nb = Mesh()
        nb.v = [B.v[o] for o in order]
        nb.f = []
        for a, b, c in B.f:
            r = rng.randrange(3)
            t = (inv[a], inv[b], inv[c])
            nb.f.append(t[r:] + t[:r])
        rng.shuffle(nb.f)
        B = nb

    def post(rng_, A_, B_):
        r32 = lambda p: (f32(p[0]), f32(p[1]), f32(p[2]))
        B2 = B_.mapped(r32)
        if variant == 'b32_weld':
            B2 = B2.welded()
        if variant == 'both32_jitter':
            A_ = A_.mapped(r32)
        return A_, B2
    return Pair(A, B, '%s %s' % (bd, variant), post=post)


def k_quad_diag(rng):
    while True:
        nu, nv = rng.randint(1, 5), rng.randint(1, 5)
        if nu * nv <= 25:
            break
    dy = rng.choice([1.0, 1.0, lu(rng, -6, 0), lu(rng, 0, 3)])
    eps = lu(rng, -12, -3) if rng.random() < 0.85 else lu(rng, -3, -1)
    mode = rng.choice(['noise', 'checker', 'dyadic', 'bilinear', 'ridge'])
    Z = {}
    ez = rng.randint(10, 45)
    for i in range(nu + 1):
        for j in range(nv + 1):
            if mode == 'noise':
                z = eps * rng.uniform(-1, 1)
            elif mode == 'checker':
                z = eps * (1 if (i + j) % 2 else -1)
            elif mode == 'dyadic':
                z = rng.randint(-3, 3) * 2.0 ** -ez
            elif mode == 'bilinear':
                z = eps * (i - nu * 0.5) * (j - nv * 0.5)
            else:
                z = eps * (i % 2)
            Z[(i, j)] = z
    dA = diag_fn(rng)

    def posf(u, v):
        i, j = int(round(u * nu)), int(round(v * nv))
        return (float(i), j * dy, Z[(i, j)])
    A = grid_mesh(nu, nv, posf, dA)
    zoff = 0.0
    if rng.random() < 0.2:
        zoff = sgn(rng) * lu(rng, -15, -8)
    B = grid_mesh(nu, nv, lambda u, v: vadd(posf(u, v), (0.0, 0.0, zoff)),
                  lambda i, j: 1 - dA(i, j))
    return Pair(A, B, '%dx%d dy=%s %s eps=%s diagA=%s zoff=%s' %
                (nu, nv, fmt(dy), mode, fmt(eps if mode != 'dyadic' else 2.0 ** -ez),
                 dA.mode, fmt(zoff)))


def k_terrain_crack(rng):
    amp = lu(rng, -3, -0.5)
    terms = [(rng.uniform(0.5, 4), rng.uniform(0.5, 4), rng.uniform(0, TAU), rng.uniform(-1, 1))
             for _ in range(rng.randint(1, 3))]

    def hf(x, y):
        return amp * sum(w * math.sin(a * x + b * y + c) for a, b, c, w in terms)
    n1, n2 = rng.choice([(1, 2), (2, 1), (1, 3), (3, 1), (1, 4), (4, 1), (2, 4), (4, 2),
                         (2, 3), (3, 2), (3, 4)])
    ov = 0.0
    if rng.random() < 0.35:
        ov = sgn(rng) * lu(rng, -12, -4)
    weld = ov == 0.0 and rng.random() < 0.5
    skirts = rng.random() < 0.4
    depth = lu(rng, -3, -1)
    A = Mesh()

    def tile(m, xa, xb, n, bcol, dg):
        ids = {}
        for i in range(n + 1):
            for j in range(n + 1):
                x = lerp(xa, xb, i / n)
                y = j / n
                p = (x, y, hf(x, y))
                ids[(i, j)] = m.addw(p) if weld else m.add(p)
        for i in range(n):
            for j in range(n):
                m.quad(ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)],
                       dg(i, j))
        if skirts:
            sk = []
            for j in range(n + 1):
                p = m.v[ids[(bcol, j)]]
                sk.append(m.add((p[0], p[1], p[2] - depth)))
            for j in range(n):
                m.quad(ids[(bcol, j)], ids[(bcol, j + 1)], sk[j + 1], sk[j], 0)
    tile(A, 0.0, 1.0 + ov, n1, n1, diag_fn(rng))
    tile(A, 1.0 - ov, 2.0, n2, 0, diag_fn(rng))
    options = ['continuous', 'finest']
    if ov == 0.0 and max(n1, n2) % min(n1, n2) == 0:
        options += ['stitched', 'stitched']
    variant = rng.choice(options)
    B = Mesh()
    if variant == 'continuous':
        mm = rng.randint(1, 3)
        grid_mesh(2 * mm, mm, lambda u, v: (lerp(0.0, 2.0, u), v, hf(lerp(0.0, 2.0, u), v)),
                  diag_fn(rng), m=B)
        vd = 'continuous %dx%d' % (2 * mm, mm)
    elif variant == 'finest':
        nn = max(n1, n2)
        for xa, xb in ((0.0, 1.0), (1.0, 2.0)):
            grid_mesh(nn, nn, lambda u, v, xa=xa, xb=xb: (lerp(xa, xb, u), v, hf(lerp(xa, xb, u), v)),
                      diag_fn(rng), m=B, weld=True)
        vd = 'finest welded n=%d' % nn
    else:
        nc, nf = min(n1, n2), max(n1, n2)
        r = nf // nc
        coarse_left = n1 < n2
        fa, fb = (1.0, 2.0) if coarse_left else (0.0, 1.0)
        ca, cb = (0.0, 1.0) if coarse_left else (1.0, 2.0)
        grid_mesh(nf, nf, lambda u, v: (lerp(fa, fb, u), v, hf(lerp(fa, fb, u), v)),
                  diag_fn(rng), m=B, weld=True)

        def P(i, j):
            x = lerp(ca, cb, i / nc)
            y = j / nc
            return B.addw((x, y, hf(x, y)))
        ci = nc - 1 if coarse_left else 0
        ii = nc - 1 if coarse_left else 1
        dg = diag_fn(rng)
        for i in range(nc):
            for j in range(nc):
                if i != ci:
                    B.quad(P(i, j), P(i + 1, j), P(i + 1, j + 1), P(i, j + 1), dg(i, j))
                else:
                    L0, L1 = P(ii, j), P(ii, j + 1)
                    R = [B.addw((1.0, k / nf, hf(1.0, k / nf)))
                         for k in range(j * r, (j + 1) * r + 1)]
                    for k in range(len(R) - 1):
                        B.tri(L0, R[k], R[k + 1])
                    B.tri(L0, R[-1], L1)
        vd = 'stitched T-junction fans'
    A2, B2, sw = maybe_swap(rng, A, B, 0.25)
    return Pair(A2, B2, 'amp=%s n1=%d n2=%d overlap=%s weld=%d skirts=%d depth=%s vs %s%s' %
                (fmt(amp), n1, n2, fmt(ov), weld, skirts, fmt(depth), vd, sw))


def k_mirror_seam(rng):
    nx, ny = rng.randint(1, 3), rng.randint(1, 3)
    dx, dy = 2.0 ** -rng.randint(0, 4), 2.0 ** -rng.randint(0, 4)
    ez = rng.randint(2, 40)
    Z = dict(((i, j), rng.randint(-8, 8) * 2.0 ** -ez)
             for i in range(nx + 1) for j in range(ny + 1))
    dA = diag_fn(rng)

    def half(m, xmap, diag, weld, mirror):
        ids = {}
        for i in range(nx + 1):
            for j in range(ny + 1):
                p = (xmap(i * dx), j * dy, Z[(i, j)])
                ids[(i, j)] = m.addw(p) if weld else m.add(p)
        for i in range(nx):
            for j in range(ny):
                a, b, c, d = ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)]
                if mirror:
                    m.quad(a, d, c, b, diag(i, j))
                else:
                    m.quad(a, b, c, d, diag(i, j))
        return ids
    weldA = rng.random() < 0.3
    A = Mesh()
    ids1 = half(A, lambda x: x, dA, weldA, False)
    half(A, lambda x: -x, dA, weldA, True)
    dup = rng.random() < 0.4
    if dup:
        seam_faces = [f for f in A.f if any(A.v[i][0] == 0.0 for i in f)]
        for f in seam_faces[:rng.randint(1, len(seam_faces))]:
            A.f.append(f if rng.random() < 0.5 else (f[0], f[2], f[1]))
    variant = rng.choice(['same', 'full_other', 'offset', 'lift'])
    B = Mesh()
    if variant in ('same', 'full_other'):
        dB = dA if variant == 'same' else diag_fn(rng)
        half(B, lambda x: x, dB, True, False)
        half(B, lambda x: -x, dB if variant == 'same' else diag_fn(rng), True, True)
        vd = variant
    elif variant == 'offset':
        s = 2.0 ** -rng.randint(8, 50)
        half(B, lambda x: x, dA, False, False)
        half(B, lambda x: 2.0 * s - x, dA, False, True)
        vd = 'mirror plane x=%s' % fmt(s)
    else:
        e = 2.0 ** -rng.randint(8, 50)
        half(B, lambda x: x, dA, False, False)
        m2 = Mesh()
        half(m2, lambda x: -x, dA, False, True)
        m2 = m2.mapped(lambda p: (p[0], p[1], p[2] + e))
        B.extend(m2)
        vd = 'lift half by %s' % fmt(e)
    A2, B2, sw = maybe_swap(rng, A, B, 0.3)
    return Pair(A2, B2, '%dx%d dx=%s dy=%s z=k*2^-%d weldA=%d dupfaces=%d vs %s%s' %
                (nx, ny, fmt(dx), fmt(dy), ez, weldA, dup, vd, sw),
                place=[0.3, 0.45, 0.1, 0.15])


def union_surface(boxes, rng):
    xs = [sorted(set(b[0][d] for b in boxes) | set(b[1][d] for b in boxes)) for d in range(3)]
    n = [len(xs[d]) - 1 for d in range(3)]

    def inside(c):
        for i in range(3):
            if not 0 <= c[i] < n[i]:
                return False
        p = [(xs[d][c[d]] + xs[d][c[d] + 1]) * 0.5 for d in range(3)]
        return any(all(lo[d] < p[d] < hi[d] for d in range(3)) for lo, hi in boxes)
    m = Mesh()

    def V(g):
        return m.add((xs[0][g[0]], xs[1][g[1]], xs[2][g[2]]), key=g)
    for i in range(n[0]):
        for j in range(n[1]):
            for k in range(n[2]):
                c = (i, j, k)
                if not inside(c):
                    continue
                for d in range(3):
                    for s in (-1, 1):
                        nb = list(c)
                        nb[d] += s
                        if inside(nb):
                            continue
                        d1, d2 = (d + 1) % 3, (d + 2) % 3
                        base = list(c)
                        if s > 0:
                            base[d] += 1
                        g = []
                        for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                            q = list(base)
                            q[d1] += a
                            q[d2] += b
                            g.append(V(tuple(q)))
                        m.quad(g[0], g[1], g[2], g[3], rng.randrange(2))
    return m


def k_box_union(rng):
    q = 0.125
    for _ in range(200):
        A1 = [rng.randint(3, 8) for _ in range(3)]
        lo2, hi2, modes = [], [], []
        for d in range(3):
            a = A1[d]
            mode = rng.choice(['cross', 'cross', 'inside', 'contain', 'flush', 'near'])
            if mode == 'cross':
                if rng.random() < 0.5:
                    lo, hi = rng.randint(1, a - 1) * q, (a + rng.randint(1, 4)) * q
                else:
                    lo, hi = -rng.randint(1, 4) * q, rng.randint(1, a - 1) * q
            elif mode == 'inside':
                lo = rng.randint(1, a - 2)
                hi = rng.randint(lo + 1, a - 1)
                lo, hi = lo * q, hi * q
            elif mode == 'contain':
                lo, hi = -rng.randint(1, 3) * q, (a + rng.randint(1, 3)) * q
            elif mode == 'flush':
                lo = 0.0
                hi = rng.choice([rng.randint(1, a - 1), a + rng.randint(1, 3)]) * q
            else:
                eps = sgn(rng) * lu(rng, -12, -4)
                if rng.random() < 0.5:
                    lo, hi = rng.randint(1, a - 1) * q, a * q + eps
                else:
                    lo, hi = -eps, rng.randint(1, a - 1) * q
            lo2.append(lo)
            hi2.append(hi)
            modes.append(mode)
        b1 = ((0.0, 0.0, 0.0), tuple(a * q for a in A1))
        b2 = (tuple(lo2), tuple(hi2))
        if not any(lo2[d] < 0 or hi2[d] > b1[1][d] for d in range(3)):
            continue
        if all(lo2[d] <= 0 and hi2[d] >= b1[1][d] for d in range(3)):
            continue
        U = union_surface([b1, b2], rng)
        if len(U.f) > 64:
            continue
        W = Mesh()
        box_mesh(b1[0], b1[1], rng, W)
        box_mesh(b2[0], b2[1], rng, W)
        A, B, sw = maybe_swap(rng, U, W, 0.3)
        return Pair(A, B, 'union box1=%s box2=%s-%s modes=%s vs two boxes%s' %
                    (A1, [fmt(x) for x in lo2], [fmt(x) for x in hi2], ','.join(modes), sw),
                    place=[0.3, 0.4, 0.15, 0.15])
    raise RuntimeError('box_union failed')


def k_thin_wall(rng):
    m = rng.randint(1, 4)
    pts = [(0.0, 0.0)]
    ang = rng.uniform(0, TAU)
    for k in range(m):
        if k:
            ang += rng.uniform(-2.0, 2.0)
        ln = lu(rng, -0.7, 0.3)
        pts.append((pts[-1][0] + ln * math.cos(ang), pts[-1][1] + ln * math.sin(ang)))
    t = lu(rng, -12, -4)
    Hh = lu(rng, -0.5, 0.5)
    nrm = []
    for k in range(m):
        dx, dy = pts[k + 1][0] - pts[k][0], pts[k + 1][1] - pts[k][1]
        ln = math.hypot(dx, dy)
        nrm.append((-dy / ln, dx / ln))
    off = []
    for k in range(m + 1):
        if k == 0:
            off.append(nrm[0])
        elif k == m:
            off.append(nrm[-1])
        else:
            sx, sy = nrm[k - 1][0] + nrm[k][0], nrm[k - 1][1] + nrm[k][1]
            ln = math.hypot(sx, sy)
            mx, my = sx / ln, sy / ln
            sc = 1.0 / (mx * nrm[k][0] + my * nrm[k][1])
            off.append((mx * sc, my * sc))

    def side(sg, th):
        return [(pts[k][0] + sg * 0.5 * th * off[k][0], pts[k][1] + sg * 0.5 * th * off[k][1])
                for k in range(m + 1)]
    style = rng.choice(['closed', 'closed', 'open', 'single'])
    W = Mesh()
    Lp, Rp = side(1, t), side(-1, t)
    L0 = [W.add((x, y, 0.0)) for x, y in Lp]
    L1 = [W.add((x, y, Hh)) for x, y in Lp]
    if style != 'single':
        R0 = [W.add((x, y, 0.0)) for x, y in Rp]
        R1 = [W.add((x, y, Hh)) for x, y in Rp]
    dg = diag_fn(rng)
    for k in range(m):
        W.quad(L0[k], L0[k + 1], L1[k + 1], L1[k], dg(k, 0))
        if style != 'single':
            W.quad(R0[k + 1], R0[k], R1[k], R1[k + 1], dg(k, 1))
            if style == 'closed':
                W.quad(L1[k], L1[k + 1], R1[k + 1], R1[k], dg(k, 2))
                W.quad(L0[k + 1], L0[k], R0[k], R0[k + 1], dg(k, 3))
    if style == 'closed':
        W.quad(R0[0], L0[0], L1[0], R1[0], dg(-1, 0))
        W.quad(L0[m], R0[m], R1[m], L1[m], dg(-1, 1))
    variant = rng.choice(['mid', 'mid', 'mid2', 'other_wall'])
    M = Mesh()
    if variant in ('mid', 'mid2'):
        rows = 1 if variant == 'mid' else 2
        ids = [[M.add((pts[k][0], pts[k][1], lerp(0.0, Hh, r / rows))) for r in range(rows + 1)]
               for k in range(m + 1)]
        dm = diag_fn(rng)
        for k in range(m):
            for r in range(rows):
                M.quad(ids[k][r], ids[k + 1][r], ids[k + 1][r + 1], ids[k][r + 1], dm(k, r))
        vd = 'mid-surface rows=%d' % rows
    else:
        t2 = t * rng.choice([0.5, 2.0, rng.uniform(0.1, 10)])
        P2, Q2 = side(1, t2), side(-1, t2)
        for S in (P2, Q2):
            b0 = [M.add((x, y, 0.0)) for x, y in S]
            b1 = [M.add((x, y, Hh)) for x, y in S]
            for k in range(m):
                M.quad(b0[k], b0[k + 1], b1[k + 1], b1[k], rng.randrange(2))
        vd = 'open wall t2=%s' % fmt(t2)
    A, B, sw = maybe_swap(rng, W, M, 0.4)
    return Pair(A, B, 'segments=%d t=%s H=%s %s vs %s%s' % (m, fmt(t), fmt(Hh), style, vd, sw))


def nudge_vertices(rng, M, cnt):
    """move cnt vertices of a copy of M (modes: normal, tangent, onto/almost onto a
    neighbour vertex, onto an opposite edge, random); a move smaller than the
    coordinates' ulp is forced to one ulp along the largest direction component"""
    size = bbox_size(M)
    inc = [[] for _ in M.v]
    for fi, f in enumerate(M.f):
        for i in sorted(set(f)):
            inc[i].append(fi)
    B = M.copy()
    modes = []
    for _ in range(cnt):
        v = rng.randrange(len(M.v))
        p = B.v[v]
        nsum = (0.0, 0.0, 0.0)
        for fi in inc[v]:
            a, b, c = [B.v[i] for i in M.f[fi]]
            nsum = vadd(nsum, cross(vsub(b, a), vsub(c, a)))
        n = unit(nsum)
        d = size * lu(rng, -15, -6)
        mode = rng.choice(['normal', 'normal', 'tangent', 'to_vertex', 'almost_vertex',
                           'to_edge', 'random'])
        nbrs = sorted(set(i for fi in inc[v] for i in M.f[fi] if i != v))
        dirv = None
        if mode == 'normal':
            dirv = vmul(n, sgn(rng))
        elif mode == 'tangent':
            dirv = unit(cross(n, rand_unit(rng)))
        elif mode == 'to_vertex':
            q = B.v[rng.choice(nbrs)]
        elif mode == 'almost_vertex':
            w = B.v[rng.choice(nbrs)]
            q = vadd(p, vmul(vsub(w, p), 1.0 - lu(rng, -15, -6)))
        elif mode == 'to_edge':
            fa = M.f[rng.choice(inc[v])]
            a, b = [i for i in fa if i != v][:2]
            tt = rng.choice([0.5, rng.uniform(0, 1)])
            q = vadd(B.v[a], vmul(vsub(B.v[b], B.v[a]), tt))
        else:
            dirv = rand_unit(rng)
        if dirv is not None:
            q = vadd(p, vmul(dirv, d))
            if q == p:
                c = max(range(3), key=lambda k: abs(dirv[k]))
                q = list(p)
                q[c] = math.nextafter(p[c], math.inf if dirv[c] > 0 else -math.inf)
                q = tuple(q)
                mode += '-1ulp'
        B.v[v] = q
        modes.append('%s(v%d,%s)' % (mode, v, fmt(d)))
    return B, ' '.join(modes)


def k_vertex_nudge(rng):
    M, bd = base_mesh(rng)
    cnt = rng.choice([1, 1, 1, 2, 3])
    if rng.random() < 0.5:
        B, md = nudge_vertices(rng, M, cnt)
        A, B2, sw = maybe_swap(rng, M, B, 0.4)
        return Pair(A, B2, '%s %s%s' % (bd, md, sw))
    which = rng.randrange(2)
    info = {}

    def post(rng_, A_, B_):
        X, md = nudge_vertices(rng_, B_ if which else A_, cnt)
        info['md'] = md
        return (A_, X) if which else (X, B_)
    return Pair(M, M.copy(), '%s nudge %d vertices of mesh %s after placement' %
                (bd, cnt, 'ab'[which]), post=post)


def k_flat_apex(rng):
    n = rng.randint(3, 24)
    rx, ry = 1.0, rng.choice([1.0, rng.uniform(0.2, 1)])
    if n == 4 and rng.random() < 0.5:
        P = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
        pd = 'dyadic square'
    elif rng.random() < 0.4:
        ph = rng.uniform(0, TAU)
        P = [(rx * math.cos(ph + TAU * k / n), ry * math.sin(ph + TAU * k / n)) for k in range(n)]
        pd = 'regular'
    else:
        angs = sorted(rng.uniform(0, TAU) for _ in range(n))
        P = [(rx * math.cos(a), ry * math.sin(a)) for a in angs]
        pd = 'random-on-ellipse'
    if rng.random() < 0.3:
        q = 2.0 ** -20
        P = [(round(x / q) * q, round(y / q) * q) for x, y in P]
        pd += ' dyadic-rounded'
    am = rng.choice(['centroid', 'interior', 'near_edge', 'at_vertex'])
    cxy = (sum(p[0] for p in P) / n, sum(p[1] for p in P) / n)
    if am == 'centroid':
        ap = cxy
    elif am == 'interior':
        w = [rng.random() for _ in range(n)]
        s = sum(w)
        ap = (sum(w[k] * P[k][0] for k in range(n)) / s, sum(w[k] * P[k][1] for k in range(n)) / s)
    elif am == 'near_edge':
        k = rng.randrange(n)
        a, b = P[k], P[(k + 1) % n]
        tt = rng.uniform(0.1, 0.9)
        e = (a[0] + (b[0] - a[0]) * tt, a[1] + (b[1] - a[1]) * tt)
        f = lu(rng, -12, -3)
        ap = (e[0] + (cxy[0] - e[0]) * f, e[1] + (cxy[1] - e[1]) * f)
    else:
        ap = P[rng.randrange(n)]
    h = sgn(rng) * lu(rng, -12, -4)
    A = Mesh()
    bi = [A.add((x, y, 0.0)) for x, y in P]
    top = A.add((ap[0], ap[1], h))
    for k in range(n):
        A.tri(top, bi[k], bi[(k + 1) % n])
    closed = rng.random() < 0.3
    if closed:
        tl = []
        random_convex_triangulation(rng, list(range(n)), tl)
        for a, b, c in tl:
            A.tri(bi[a], bi[c], bi[b])
    variant = rng.choice(['fan_vertex', 'fan_center', 'random', 'fan_center_split'])
    B = Mesh()
    bb = [B.add((x, y, 0.0)) for x, y in P]
    if variant == 'fan_vertex':
        k0 = rng.randrange(n)
        for k in range(1, n - 1):
            B.tri(bb[k0], bb[(k0 + k) % n], bb[(k0 + k + 1) % n])
    elif variant == 'random':
        tl = []
        random_convex_triangulation(rng, list(range(n)), tl)
        for a, b, c in tl:
            B.tri(bb[a], bb[b], bb[c])
    else:
        c = B.add((ap[0], ap[1], 0.0))
        for k in range(n):
            a, b = P[k], P[(k + 1) % n]
            if variant == 'fan_center_split' and rng.random() < 0.4:
                mid = B.add(((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, 0.0))
                B.tri(c, bb[k], mid)
                B.tri(c, mid, bb[(k + 1) % n])
            else:
                B.tri(c, bb[k], bb[(k + 1) % n])
    A2, B2, sw = maybe_swap(rng, A, B, 0.3)
    return Pair(A2, B2, 'n=%d %s apex=%s h=%s closed=%d vs base %s%s' %
                (n, pd, am, fmt(h), closed, variant, sw))


def k_flat_fan(rng):
    k = rng.randint(3, 32)
    closed = rng.random() < 0.7
    if closed:
        if rng.random() < 0.4:
            ph = rng.uniform(0, TAU)
            angs = [ph + TAU * i / k for i in range(k)]
        else:
            angs = sorted(rng.uniform(0, TAU) for _ in range(k))
    else:
        span = rng.uniform(0.5, 5.5)
        angs = sorted(rng.uniform(0, span) for _ in range(k))
    rad = [1.0] * k if rng.random() < 0.5 else [rng.uniform(0.2, 1) for _ in range(k)]
    zm = rng.choice(['cone', 'alt', 'rand', 'one'])
    base = lu(rng, -12, -5)
    z = []
    for i in range(k):
        if zm == 'cone':
            z.append(rad[i] * base)
        elif zm == 'alt':
            z.append(rad[i] * base * (1 if i % 2 else -1))
        elif zm == 'rand':
            z.append(rad[i] * sgn(rng) * lu(rng, -12, -5))
        else:
            z.append(rad[i] * base if i == 0 else 0.0)
    cz = rng.choice([0.0, 0.0, sgn(rng) * lu(rng, -15, -9)])
    rim = [(rad[i] * math.cos(angs[i]), rad[i] * math.sin(angs[i])) for i in range(k)]
    A = Mesh()
    c = A.add((0.0, 0.0, cz))
    ri = [A.add((rim[i][0], rim[i][1], z[i])) for i in range(k)]
    nt = k if closed else k - 1
    for i in range(nt):
        A.tri(c, ri[i], ri[(i + 1) % k])
    variant = rng.choice(['flat', 'flat', 'flat_shift', 'poly', 'self_lift'])
    B = Mesh()
    if variant in ('flat', 'flat_shift', 'self_lift'):
        if variant == 'flat':
            cp = (0.0, 0.0, 0.0)
        elif variant == 'flat_shift':
            d = lu(rng, -12, -4)
            a = rng.uniform(0, TAU)
            cp = (d * math.cos(a), d * math.sin(a), 0.0)
        else:
            cp = (0.0, 0.0, cz + sgn(rng) * lu(rng, -15, -7))
        cb = B.add(cp)
        zz = z if variant == 'self_lift' else [0.0] * k
        rb = [B.add((rim[i][0], rim[i][1], zz[i])) for i in range(k)]
        for i in range(nt):
            B.tri(cb, rb[i], rb[(i + 1) % k])
    else:
        rb = [B.add((rim[i][0], rim[i][1], 0.0)) for i in range(k)]
        if closed:
            for i in range(1, k - 1):
                B.tri(rb[0], rb[i], rb[i + 1])
        else:
            cb = B.add((0.0, 0.0, 0.0))
            for i in range(k - 1):
                B.tri(cb, rb[i], rb[i + 1])
    A2, B2, sw = maybe_swap(rng, A, B, 0.3)
    return Pair(A2, B2, 'k=%d closed=%d z=%s base=%s cz=%s vs %s%s' %
                (k, closed, zm, fmt(base), fmt(cz), variant, sw))


def k_twisted_strip(rng):
    n = rng.randint(2, 20)
    L = lu(rng, 0, 2)
    w = rng.choice([1.0, lu(rng, -3, 0)])
    Th = lu(rng, -12, -3) if rng.random() < 0.8 else lu(rng, -3, -1)

    def strip(theta, nseg, dg, bend=0.0):
        m = Mesh()

        def pos(u, v):
            th = theta * u
            s = (v - 0.5) * w
            return (lerp(0.0, L, u), s * math.cos(th), s * math.sin(th) + bend * math.sin(math.pi * u))
        return grid_mesh(nseg, 1, pos, dg, m=m)
    dA = diag_fn(rng)
    A = strip(Th, n, dA)
    variant = rng.choice(['flat', 'flat_coarse', 'counter', 'same_other_diag'])
    if variant == 'flat':
        B = strip(0.0, n, diag_fn(rng))
    elif variant == 'flat_coarse':
        mm = rng.choice([d for d in range(1, n + 1) if n % d == 0])
        B = strip(0.0, mm, diag_fn(rng))
    elif variant == 'counter':
        B = strip(-Th, n, diag_fn(rng))
    else:
        B = strip(Th, n, lambda i, j: 1 - dA(i, j))
    A2, B2, sw = maybe_swap(rng, A, B, 0.3)
    return Pair(A2, B2, 'n=%d L=%s w=%s twist=%s diag=%s vs %s%s' %
                (n, fmt(L), fmt(w), fmt(Th), dA.mode, variant, sw))


def k_degenerate_only(rng):
    st = rng.choice(['tri', 'grid', 'base'])
    if st == 'tri':
        S = Mesh()
        a = (0.0, 0.0, 0.0)
        b = (1.0, rng.uniform(-0.2, 0.2), 0.0)
        c = (rng.uniform(-0.2, 1), rng.uniform(0.3, 1), rng.uniform(-0.1, 0.1))
        S.tri(S.add(a), S.add(b), S.add(c))
        sd = 'triangle'
    elif st == 'grid':
        amp = lu(rng, -6, -1)
        S = grid_mesh(2, 2, lambda u, v: (u, v, amp * math.sin(3 * u + 2 * v)), diag_fn(rng))
        sd = 'grid2x2 amp=%s' % fmt(amp)
    else:
        S, sd = base_mesh(rng)
    size = bbox_size(S)

    def surf_point():
        f = rng.choice(S.f)
        a, b, c = [S.v[i] for i in f]
        k = rng.randint(1, 10)
        N = 2 ** k
        i = rng.randint(0, N)
        j = rng.randint(0, N - i)
        return bary(a, b, c, (N - i - j) / N, i / N, j / N), unit(cross(vsub(b, a), vsub(c, a)))
    edges = sorted(set((min(a, b), max(a, b)) for f in S.f
                       for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])) if a != b))

    def degen(dtype):
        D = Mesh()
        cnt = rng.randint(1, 30) if dtype != 'wire' else 0
        kinds = []
        for _ in range(cnt):
            t = dtype if dtype != 'mixed' else rng.choice(
                ['points_on', 'points_near', 'points_vert', 'collinear', 'repeated'])
            kinds.append(t)
            if t == 'points_on':
                p, _n = surf_point()
                i = D.add(p)
                D.tri(i, i, i)
            elif t == 'points_near':
                p, nn = surf_point()
                i = D.add(vadd(p, vmul(nn, sgn(rng) * size * lu(rng, -15, -3))))
                D.tri(i, i, i)
            elif t == 'points_vert':
                if rng.random() < 0.5:
                    p = rng.choice(S.v)
                else:
                    a, b = rng.choice(edges)
                    p = vmul(vadd(S.v[a], S.v[b]), 0.5)
                i = D.add(p)
                D.tri(i, i, i)
            elif t == 'collinear':
                a, b = rng.choice(edges)
                ia, ib = D.add(S.v[a], key=('S', a)), D.add(S.v[b], key=('S', b))
                r = rng.random()
                if r < 0.4:
                    im = D.add(vmul(vadd(S.v[a], S.v[b]), 0.5))
                    D.tri(ia, ib, im)
                elif r < 0.7:
                    im = D.add(vsub(vmul(S.v[b], 2.0), S.v[a]))
                    D.tri(ia, im, ib)
                else:
                    D.tri(ia, ib, ib)
            elif t == 'repeated':
                p, nn = surf_point()
                if rng.random() < 0.5:
                    D.tri(D.add(p), D.add(p), D.add(p))
                else:
                    q, _n = surf_point()
                    D.tri(D.add(p), D.add(q), D.add(q))
        if dtype == 'wire':
            D = Mesh()
            sel = edges if len(edges) <= 40 else sorted(rng.sample(edges, 40))
            for a, b in sel:
                ia, ib = D.add(S.v[a], key=('S', a)), D.add(S.v[b], key=('S', b))
                D.tri(ia, ib, ib)
            kinds = ['wire']
        return D, '%s(%d)' % (dtype, len(D.f))
    dt = rng.choice(['points_on', 'points_near', 'points_vert', 'wire', 'collinear',
                     'repeated', 'mixed'])
    D, dd = degen(dt)
    if rng.random() < 0.15:
        dt2 = rng.choice(['points_on', 'wire', 'collinear', 'mixed'])
        D2, dd2 = degen(dt2)
        A, B, sw = maybe_swap(rng, D, D2, 0.5)
        return Pair(A, B, 'surface %s; degenerate %s vs degenerate %s%s' % (sd, dd, dd2, sw))
    A, B, sw = maybe_swap(rng, D, S, 0.5)
    return Pair(A, B, 'degenerate %s vs surface %s%s' % (dd, sd, sw))


def k_needle_fan(rng):
    w = lu(rng, -12, -3)
    variant = rng.choice(['fan', 'strip', 'cross'])
    if variant == 'fan':
        s = rng.choice([1.0, 0.5, rng.uniform(0.0, 1.2)])
        P0, P1, P2 = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (s, w, 0.0)
        k = rng.randint(2, 20)
        A = Mesh()
        a0 = A.add(P0)
        Q = [A.add(P1 if i == 0 else P2 if i == k else vadd(P1, vmul(vsub(P2, P1), i / k)))
             for i in range(k + 1)]
        for i in range(k):
            A.tri(a0, Q[i], Q[i + 1])
        bv = rng.choice(['single', 'otherfan', 'lifted'])
        B = Mesh()
        if bv == 'single':
            B.tri(B.add(P0), B.add(P1), B.add(P2))
        elif bv == 'otherfan':
            k2 = rng.randint(2, 20)
            b1 = B.add(P1)
            R = [B.add(P0 if i == 0 else P2 if i == k2 else vadd(P0, vmul(vsub(P2, P0), i / k2)))
                 for i in range(k2 + 1)]
            for i in range(k2):
                B.tri(b1, R[i], R[i + 1])
        else:
            d = lu(rng, -15, -4)
            B.tri(B.add((0.0, 0.0, d)), B.add((1.0, 0.0, d)), B.add((s, w, d)))
        desc = 'fan k=%d s=%s vs %s' % (k, fmt(s), bv)
    elif variant == 'strip':
        n = rng.randint(2, 20)
        bend = rng.choice([0.0, lu(rng, -15, -6)])
        dA = diag_fn(rng)
        A = grid_mesh(n, 1, lambda u, v: (u, v * w, bend * math.sin(math.pi * u)), dA)
        n2 = rng.choice([1, rng.randint(1, 20)])
        B = grid_mesh(n2, 1, lambda u, v: (u, v * w, 0.0), diag_fn(rng))
        desc = 'strip n=%d bend=%s vs n2=%d' % (n, fmt(bend), n2)
    else:
        cnt = rng.randint(1, 6)
        alpha = lu(rng, -12, -2)
        d = rng.choice([0.0, lu(rng, -15, -4)])
        orient = rng.choice(['flat', 'fin'])
        A, B = Mesh(), Mesh()
        for i in range(cnt):
            yc = i * 0.25
            for m, ang, dz in ((A, 0.0, 0.0), (B, alpha, d)):
                ca, sa = math.cos(ang), math.sin(ang)

                def rot(p):
                    x, y, z = p[0] - 0.5, p[1], p[2]
                    return (0.5 + ca * x - sa * y, yc + sa * x + ca * y, z + dz)
                tip = (0.5, w, 0.0) if orient == 'flat' else (0.5, 0.0, w)
                m.tri(m.add(rot((0.0, 0.0, 0.0))), m.add(rot((1.0, 0.0, 0.0))), m.add(rot(tip)))
        desc = 'crossing needles cnt=%d alpha=%s dz=%s %s' % (cnt, fmt(alpha), fmt(d), orient)
    A2, B2, sw = maybe_swap(rng, A, B, 0.4)
    return Pair(A2, B2, 'w=%s %s%s' % (fmt(w), desc, sw))


def k_star_cross(rng):
    A = Mesh()
    if rng.random() < 0.5:
        c = [A.add(p) for p in ((-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0))]
        A.quad(c[0], c[1], c[2], c[3], rng.randrange(2))
        ad = 'square'
    else:
        A.tri(A.add((-1.5, -1.0, 0.0)), A.add((1.5, -1.0, 0.0)), A.add((0.0, 1.5, 0.0)))
        ad = 'triangle'
    h = 0.0 if rng.random() < 0.15 else sgn(rng) * lu(rng, -12, -1)
    am = rng.choice(['origin', 'dyadic', 'tiny'])
    if am == 'origin':
        ax, ay = 0.0, 0.0
    elif am == 'dyadic':
        ax, ay = rng.randint(-8, 8) * 2.0 ** -10, rng.randint(-8, 8) * 2.0 ** -10
    else:
        ax, ay = sgn(rng) * lu(rng, -12, -3), sgn(rng) * lu(rng, -12, -3)
    sym = rng.random() < 0.3
    if sym:
        k = rng.choice([4, 8])
        pts4 = [(0.5, 0.0), (0.0, 0.5), (-0.5, 0.0), (0.0, -0.5)]
        if k == 4:
            rim = pts4
        else:
            rim = [(0.5, 0.0), (0.25, 0.25), (0.0, 0.5), (-0.25, 0.25), (-0.5, 0.0),
                   (-0.25, -0.25), (0.0, -0.5), (0.25, -0.25)]
    else:
        k = rng.randint(4, 24)
        angs = sorted(rng.uniform(0, TAU) for _ in range(k))
        rim = [(r * math.cos(a), r * math.sin(a)) for a, r in
               zip(angs, [rng.uniform(0.2, 0.9) for _ in range(k)])]
    rz = rng.choice(['flat', 'same', 'random'])
    if rz == 'flat':
        zr = [0.0] * k
    elif rz == 'same':
        zr = [h * rng.choice([0.5, 2.0, -1.0])] * k
    else:
        zr = [sgn(rng) * lu(rng, -12, -2) for _ in range(k)]
    variant = rng.choice(['fan', 'fan', 'soup', 'double', 'open'])
    B = Mesh()
    R = [B.add((rim[i][0], rim[i][1], zr[i])) for i in range(k)]
    if variant in ('fan', 'open'):
        c = B.add((ax, ay, h))
        skip = rng.randrange(k) if variant == 'open' else -1
        for i in range(k):
            if i != skip:
                B.tri(c, R[i], R[(i + 1) % k])
    elif variant == 'soup':
        dl = lu(rng, -15, -8)
        for i in range(k):
            if rng.random() < 0.3:
                c = B.add((ax, ay, h))
            else:
                c = B.add((ax + rng.uniform(-dl, dl), ay + rng.uniform(-dl, dl),
                           h + rng.uniform(-dl, dl)))
            B.tri(c, R[i], R[(i + 1) % k])
    else:
        dl = lu(rng, -15, -6)
        c1 = B.add((ax, ay, h))
        c2 = B.add((ax + dl, ay - dl * 0.5, h + rng.choice([0.0, dl])))
        for i in range(k):
            B.tri(c1 if i % 2 else c2, R[i], R[(i + 1) % k])
        # second, rotated rim on the other apex
        if k <= 12:
            R2 = [B.add((rim[i][0] * 0.5 - rim[i][1] * 0.5, rim[i][0] * 0.5 + rim[i][1] * 0.5, zr[i]))
                  for i in range(k)]
            for i in range(k):
                B.tri(c2 if i % 2 else c1, R2[i], R2[(i + 1) % k])
    A2, B2, sw = maybe_swap(rng, A, B, 0.2)
    return Pair(A2, B2, '%s vs star k=%d sym=%d h=%s apex=%s rimz=%s %s%s' %
                (ad, k, sym, fmt(h), am, rz, variant, sw))


def k_ridge_pair(rng):
    L = lu(rng, -0.5, 1)
    A = Mesh()
    na = rng.choice([1, 2])
    grid_mesh(na, na, lambda u, v: (u, lerp(0.0, L, v), 0.0), diag_fn(rng), m=A)
    variant = rng.choice(['fold', 'fold', 'skew'])
    B = Mesh()
    if variant == 'fold':
        xi1 = rng.uniform(0.2, 0.45)
        xi2 = rng.choice([rng.uniform(0.55, 0.8), xi1 + lu(rng, -9, -2)])
        a1 = rng.choice([0.0, sgn(rng) * lu(rng, -12, -3)])
        a2 = a1 + rng.choice([0.0, sgn(rng) * lu(rng, -12, -3)]) / L
        h = lu(rng, -6, -0.5)
        tie = rng.choice([0.0, sgn(rng) * lu(rng, -15, -6)])
        sl = [sgn(rng) * lu(rng, -9, -1) for _ in range(3)]
        ny = rng.choice([1, 2])
        rows = []
        for j in range(ny + 1):
            y = lerp(-0.1 * L, 1.1 * L, j / ny)
            r1 = xi1 + a1 * y
            r2 = xi2 + a2 * y
            xs = [-0.25, r1, 0.5 * (r1 + r2), r2, 1.25]
            zs = [h + sl[0] * (r1 + 0.25), h, h + sl[1] * 0.5 * abs(r2 - r1), h + tie,
                  h + tie + sl[2] * (1.25 - r2)]
            rows.append([B.add((xs[c], y, zs[c])) for c in range(5)])
        for j in range(ny):
            for c in range(4):
                B.quad(rows[j][c], rows[j][c + 1], rows[j + 1][c + 1], rows[j + 1][c],
                       rng.randrange(2))
        desc = 'fold xi=%s,%s slope-diff=%s h=%s tie=%s slopes=%s' % (
            fmt(xi1), fmt(xi2), fmt(a2 - a1), fmt(h), fmt(tie), ','.join(fmt(s) for s in sl))
    else:
        cnt = rng.randint(2, 4)
        h = lu(rng, -6, -0.5)
        alpha = lu(rng, -12, -2)
        dh = lu(rng, -15, -4)
        for i in range(cnt):
            ang = (i - (cnt - 1) * 0.5) * alpha
            ca, sa = math.cos(ang), math.sin(ang)
            z = h + i * dh * rng.choice([0.0, 1.0])
            xc = 0.5 + rng.choice([0.0, lu(rng, -12, -3)])
            p = (xc - 0.7 * sa * L, 0.5 * L - 0.7 * ca * L, z)
            q = (xc + 0.7 * sa * L, 0.5 * L + 0.7 * ca * L, z)
            lean = rng.uniform(-0.5, 0.5)
            r = (xc + lean, 0.5 * L, z + rng.uniform(0.3, 1.0))
            B.tri(B.add(p), B.add(q), B.add(r))
        desc = 'skew fins cnt=%d alpha=%s h=%s dh=%s' % (cnt, fmt(alpha), fmt(h), fmt(dh))
    A2, B2, sw = maybe_swap(rng, A, B, 0.3)
    return Pair(A2, B2, 'L=%s flat %dx%d vs %s%s' % (fmt(L), na, na, desc, sw))


def orient2(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def convex_hull_int(pts):
    pts = sorted(set(pts))
    if len(pts) < 3:
        return pts
    lower = []
    for p in pts:
        while len(lower) >= 2 and orient2(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper = []
    for p in reversed(pts):
        while len(upper) >= 2 and orient2(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


class Tri2(object):
    """exact integer planar triangulation with Steiner insertion"""

    def __init__(self, pts, tris):
        self.p = list(pts)
        self.t = list(tris)

    def insert(self, q):
        if q in self.p:
            return False
        for idx, (a, b, c) in enumerate(self.t):
            pa, pb, pc = self.p[a], self.p[b], self.p[c]
            o1, o2, o3 = orient2(pa, pb, q), orient2(pb, pc, q), orient2(pc, pa, q)
            if o1 < 0 or o2 < 0 or o3 < 0:
                continue
            n = len(self.p)
            self.p.append(q)
            if o1 and o2 and o3:
                self.t[idx:idx + 1] = [(a, b, n), (b, c, n), (c, a, n)]
                return True
            if o1 == 0:
                u, w, opp = a, b, c
            elif o2 == 0:
                u, w, opp = b, c, a
            else:
                u, w, opp = c, a, b
            self.t[idx:idx + 1] = [(u, n, opp), (n, w, opp)]
            for j, t in enumerate(self.t):
                for r in range(3):
                    if t[r] == w and t[(r + 1) % 3] == u:
                        opp2 = t[(r + 2) % 3]
                        self.t[j:j + 1] = [(w, n, opp2), (n, u, opp2)]
                        return True
            return True
        return False

    def edges(self):
        return sorted(set((min(a, b), max(a, b)) for t in self.t
                          for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))))


def k_coplanar_retri(rng):
    while True:
        N = rng.choice([32, 64, 256])
        pts = [(rng.randint(0, N) * 4, rng.randint(0, N) * 4) for _ in range(rng.randint(5, 14))]
        hull = convex_hull_int(pts)
        if len(hull) >= 3:
            break
    nh = len(hull)

    def triangulation(style):
        out = []
        if style == 'fan':
            k0 = rng.randrange(nh)
            lst = [(k0 + i) % nh for i in range(nh)]
            for i in range(1, nh - 1):
                out.append((lst[0], lst[i], lst[i + 1]))
        else:
            k0 = rng.randrange(nh)
            random_convex_triangulation(rng, [(k0 + i) % nh for i in range(nh)], out)
        return Tri2(hull, out)
    TA = triangulation(rng.choice(['fan', 'random']))
    for _ in range(rng.choice([0, 0, 1, 2])):
        a, b = rng.choice(TA.edges())
        TA.insert(((TA.p[a][0] + TA.p[b][0]) // 2, (TA.p[a][1] + TA.p[b][1]) // 2))
    TB = triangulation(rng.choice(['fan', 'random']))
    nst = rng.randint(1, 8)
    for _ in range(nst):
        r = rng.random()
        if r < 0.3:
            k = rng.randrange(nh)
            a, b = hull[k], hull[(k + 1) % nh]
            q = ((a[0] + b[0]) // 2, (a[1] + b[1]) // 2)
        elif r < 0.6:
            a, b = rng.choice(TA.edges())
            pa, pb = TA.p[a], TA.p[b]
            q = ((pa[0] + pb[0]) // 2, (pa[1] + pb[1]) // 2)
        else:
            t = rng.choice(TB.t)
            wts = [rng.random() for _ in range(3)]
            s = sum(wts)
            q = (int(sum(wts[i] * TB.p[t[i]][0] for i in range(3)) / s),
                 int(sum(wts[i] * TB.p[t[i]][1] for i in range(3)) / s))
        TB.insert(q)
    sc = 2.0 ** -rng.randint(8, 12)
    plane = rng.choice(['z0', 'z0', 'tilt'])
    ax, ay = (rng.randint(-4, 4) * 0.25, rng.randint(-4, 4) * 0.25) if plane == 'tilt' else (0.0, 0.0)
    lift = rng.random() < 0.25
    lmag = lu(rng, -15, -6)

    def to_mesh(T, lifted):
        m = Mesh()
        ids = []
        for n, (x, y) in enumerate(T.p):
            X, Y = x * sc, y * sc
            Z = ax * X + ay * Y
            if lifted and n >= nh:
                Z += sgn(rng) * lmag
            ids.append(m.add((X, Y, Z)))
        for a, b, c in T.t:
            m.tri(ids[a], ids[b], ids[c])
        return m.compact()
    A = to_mesh(TA, False)
    B = to_mesh(TB, lift)
    A2, B2, sw = maybe_swap(rng, A, B, 0.3)
    return Pair(A2, B2, 'hull=%d steinerB=%d plane=%s(%s,%s) lift=%s%s' %
                (nh, len(TB.p) - nh, plane, ax, ay, fmt(lmag) if lift else 0, sw),
                place=[0.3, 0.4, 0.15, 0.15])


def k_sandwich_tie(rng):
    d = 2.0 ** -rng.randint(0, 40)
    na = rng.randint(1, 3)
    A = grid_mesh(na, na, lambda u, v: (u, v, 0.0), diag_fn(rng))
    variant = rng.choice(['planes', 'mirror_bumps', 'mirror_roof', 'offset_grids'])
    lo, hi = -0.25, 1.25
    B = Mesh()
    if variant in ('planes', 'offset_grids'):
        nt, nb = rng.randint(1, 3), rng.randint(1, 3)
        sh = 0.0 if variant == 'planes' else 0.5 * (hi - lo) / nb
        grid_mesh(nt, nt, lambda u, v: (lerp(lo, hi, u), lerp(lo, hi, v), d), diag_fn(rng), m=B)
        grid_mesh(nb, nb, lambda u, v: (lerp(lo, hi, u) + sh, lerp(lo, hi, v) - sh, -d),
                  diag_fn(rng), m=B)
        vd = '%s top=%d bottom=%d shift=%s' % (variant, nt, nb, sh)
    elif variant == 'mirror_bumps':
        n = rng.randint(1, 3)
        Hh = {}
        for i in range(n + 1):
            for j in range(n + 1):
                Hh[(i, j)] = d * rng.choice([1.0, 1.0, 1.25, 1.5, 2.0, 0.5])
        dg = diag_fn(rng)
        for sg in (1.0, -1.0):
            grid_mesh(n, n, lambda u, v, sg=sg: (lerp(lo, hi, u), lerp(lo, hi, v),
                                                 sg * Hh[(int(round(u * n)), int(round(v * n)))]),
                      dg, m=B)
        vd = 'mirror_bumps n=%d' % n
    else:
        ridge = rng.choice([0.5, 0.25, 0.375])
        s = 2.0 ** -rng.randint(0, 30)
        for sg in (1.0, -1.0):
            xs = [lo, ridge, hi]
            zs = [sg * (d + s * (ridge - lo)), sg * d, sg * (d + s * (hi - ridge))]
            ids = [[B.add((xs[c], y, zs[c])) for c in range(3)] for y in (lo, hi)]
            for c in range(2):
                B.quad(ids[0][c], ids[0][c + 1], ids[1][c + 1], ids[1][c], rng.randrange(2))
        vd = 'mirror_roof ridge=%s slope=%s' % (ridge, fmt(s))
    A2, B2, sw = maybe_swap(rng, A, B, 0.2)
    return Pair(A2, B2, 'flat %dx%d between layers at +-%s: %s%s' % (na, na, fmt(d), vd, sw),
                place=[0.3, 0.45, 0.1, 0.15])


SCALED_SUBKINDS = None


def k_scaled_mix(rng):
    name, fn = rng.choice(SCALED_SUBKINDS)
    pr = fn(rng)
    sc = rng.choice([2.0 ** -rng.randint(18, 22), 2.0 ** rng.randint(18, 22), 1e-6, 1e6,
                     lu(rng, -7, -5), lu(rng, 5, 7)])
    pr.a = pr.a.mapped(lambda p: (p[0] * sc, p[1] * sc, p[2] * sc))
    pr.b = pr.b.mapped(lambda p: (p[0] * sc, p[1] * sc, p[2] * sc))
    pr.desc = 'scale=%r of %s: %s' % (sc, name, pr.desc)
    return pr


SCALED_SUBKINDS = [
    ('lod_sphere', k_lod_sphere), ('lod_saddle', k_lod_saddle), ('quad_diag', k_quad_diag),
    ('flat_apex', k_flat_apex), ('flat_fan', k_flat_fan), ('star_cross', k_star_cross),
    ('thin_wall', k_thin_wall), ('box_union', k_box_union), ('needle_fan', k_needle_fan),
    ('coplanar_retri', k_coplanar_retri), ('mtet_iso', k_mtet_iso), ('ridge_pair', k_ridge_pair),
    ('vertex_nudge', k_vertex_nudge), ('twisted_strip', k_twisted_strip),
    ('sin_bump', k_sin_bump), ('mirror_seam', k_mirror_seam), ('sandwich_tie', k_sandwich_tie)]


# (name, generator, far-offset exponent range or None)
KIND_TABLE = [
    ('lod_sphere', k_lod_sphere, None),
    ('lod_cylinder', k_lod_cylinder, None),
    ('lod_saddle', k_lod_saddle, None),
    ('sin_bump', k_sin_bump, None),
    ('mtet_iso', k_mtet_iso, None),
    ('float32_export', k_float32, None),
    ('quad_diag', k_quad_diag, None),
    ('terrain_crack', k_terrain_crack, None),
    ('mirror_seam', k_mirror_seam, None),
    ('box_union', k_box_union, None),
    ('thin_wall', k_thin_wall, None),
    ('vertex_nudge', k_vertex_nudge, None),
    ('flat_apex', k_flat_apex, None),
    ('flat_fan', k_flat_fan, None),
    ('twisted_strip', k_twisted_strip, None),
    ('degenerate_only', k_degenerate_only, None),
    ('needle_fan', k_needle_fan, None),
    ('star_cross', k_star_cross, None),
    ('ridge_pair', k_ridge_pair, None),
    ('coplanar_retri', k_coplanar_retri, None),
    ('sandwich_tie', k_sandwich_tie, None),
    ('scaled_mix', k_scaled_mix, None),
    ('float32_far', k_float32, (3.0, 5.0)),
    ('lod_sphere_far', k_lod_sphere, (3.0, 7.0)),
    ('quad_diag_far', k_quad_diag, (3.0, 7.0)),
    ('vertex_nudge_far', k_vertex_nudge, (3.0, 7.0)),
    ('thin_wall_far', k_thin_wall, (3.0, 7.0)),
]
KINDS = [k[0] for k in KIND_TABLE]
KIND_FUNCS = dict((k[0], (k[1], k[2])) for k in KIND_TABLE)


# -------------------------------------------------------------- placement
def bbox_size(*meshes):
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    for m in meshes:
        for p in m.v:
            for c in range(3):
                if p[c] < lo[c]:
                    lo[c] = p[c]
                if p[c] > hi[c]:
                    hi[c] = p[c]
    if lo[0] == math.inf:
        return 1.0
    d = math.sqrt(sum((hi[c] - lo[c]) ** 2 for c in range(3)))
    if not (d > 0 and math.isfinite(d)):
        return 1.0
    return d


def quat_matrix(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(c * c for c in q)) or 1.0
    w, x, y, z = [c / n for c in q]
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def axis_matrix(ax, th):
    x, y, z = ax
    c, s = math.cos(th), math.sin(th)
    C = 2.0 * math.sin(0.5 * th) ** 2
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def affine(M, t):
    def f(p):
        return (M[0][0] * p[0] + M[0][1] * p[1] + M[0][2] * p[2] + t[0],
                M[1][0] * p[0] + M[1][1] * p[1] + M[1][2] * p[2] + t[1],
                M[2][0] * p[0] + M[2][1] * p[1] + M[2][2] * p[2] + t[2])
    return f


def make_placement(rng, size, weights=None):
    modes = ['none', 'exact', 'rot', 'exact+tiny']
    w = weights or [0.15, 0.35, 0.3, 0.2]
    mode = rng.choices(modes, w)[0]
    if mode == 'none':
        return (lambda p: p), 'none'
    if mode == 'rot':
        M = quat_matrix(rng)
        t = [rng.gauss(0, 1) * size for _ in range(3)]
        return affine(M, t), 'rot'
    perm = [0, 1, 2]
    rng.shuffle(perm)
    sg = [sgn(rng) for _ in range(3)]
    sc = 2.0 ** rng.randint(-2, 2)
    e = math.floor(math.log2(size))
    t = [rng.randint(-16, 16) * 2.0 ** (e - 2) for _ in range(3)]

    def ex(p):
        return (sg[0] * sc * p[perm[0]] + t[0], sg[1] * sc * p[perm[1]] + t[1],
                sg[2] * sc * p[perm[2]] + t[2])
    d = 'exact perm=%s signs=%s scale=%s' % (''.join(map(str, perm)),
                                              ''.join('+' if s > 0 else '-' for s in sg), sc)
    if mode == 'exact':
        return ex, d
    th = lu(rng, -14, -4)
    R = affine(axis_matrix(rand_unit(rng), th), (0.0, 0.0, 0.0))
    return (lambda p: R(ex(p))), d + ' tiny-rot=%s' % fmt(th)


def far_offset(rng, size, rng_exp):
    D = size * lu(rng, rng_exp[0], rng_exp[1])
    style = rng.random()
    if style < 0.3:
        off = [0.0, 0.0, 0.0]
        off[rng.randrange(3)] = sgn(rng) * D
        sd = 'axis'
    elif style < 0.5:
        off = [sgn(rng) * D / math.sqrt(3.0) for _ in range(3)]
        sd = 'diag'
    else:
        off = list(vmul(rand_unit(rng), D))
        sd = 'random'
    if rng.random() < 0.5:
        q = 2.0 ** (math.floor(math.log2(D)) - rng.randint(0, 24))
        off = [round(c / q) * q for c in off]
        sd += ' dyadic'
    return off, 'far offset=(%r,%r,%r) %s' % (off[0], off[1], off[2], sd)


# ------------------------------------------------------------- validation
def valence_ok(m):
    cnt = {}
    ccnt = {}
    for f in m.f:
        for i in set(f):
            cnt[i] = cnt.get(i, 0) + 1
        for p in set(m.v[i] for i in f):
            ccnt[p] = ccnt.get(p, 0) + 1
    return (max(cnt.values()) <= MAX_VALENCE and max(ccnt.values()) <= MAX_VALENCE)


def soft_ok(m):
    if not 1 <= len(m.f) <= SOFT_MAX_TRIS:
        return False
    for p in m.v:
        for c in p:
            if not math.isfinite(c):
                return False
    return valence_ok(m)


def validate(m, what):
    nf = len(m.f)
    if not 1 <= nf <= MAX_TRIS:
        raise ValueError('%s: %d triangles' % (what, nf))
    nv = len(m.v)
    used = [False] * nv
    for f in m.f:
        if len(f) != 3:
            raise ValueError('%s: face arity' % what)
        for i in f:
            if not (isinstance(i, int) and 0 <= i < nv):
                raise ValueError('%s: bad index %r' % (what, i))
            used[i] = True
    if not all(used):
        raise ValueError('%s: %d unused vertices' % (what, used.count(False)))
    for p in m.v:
        if len(p) != 3:
            raise ValueError('%s: vertex arity' % what)
        for c in p:
            if not (isinstance(c, float) and math.isfinite(c)):
                raise ValueError('%s: bad coordinate %r' % (what, c))
    if not valence_ok(m):
        raise ValueError('%s: more than %d triangles around a vertex' % (what, MAX_VALENCE))


def write_obj(path, m, comment):
    comment = comment.replace('\n', ' ').replace('\r', ' ')
    out = ['# ' + comment]
    out.extend('v %r %r %r' % p for p in m.v)
    out.extend('f %d %d %d' % (a + 1, b + 1, c + 1) for a, b, c in m.f)
    with open(path, 'w') as fh:
        fh.write('\n'.join(out) + '\n')


# ------------------------------------------------------------------ driver
def make_pair(seed):
    rng = random.Random(seed)
    kind = KINDS[seed % len(KINDS)]
    fn, far = KIND_FUNCS[kind]
    for attempt in range(40):
        pr = fn(rng)
        A, B = pr.a, pr.b
        size = bbox_size(A, B)
        place, pdesc = make_placement(rng, size, pr.place)
        A, B = A.mapped(place), B.mapped(place)
        if far:
            off, fdesc = far_offset(rng, bbox_size(A, B), far)
            A = A.mapped(lambda p: (p[0] + off[0], p[1] + off[1], p[2] + off[2]))
            B = B.mapped(lambda p: (p[0] + off[0], p[1] + off[1], p[2] + off[2]))
            pdesc += ' ' + fdesc
        if pr.post is not None:
            A, B = pr.post(rng, A, B)
        if soft_ok(A) and soft_ok(B):
            desc = '%s | place=%s' % (pr.desc, pdesc)
            if attempt:
                desc += ' | redraw=%d' % attempt
            return kind, A, B, desc
    raise ValueError('seed %d kind %s: no valid pair after 40 attempts' % (seed, kind))


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: python3 generate_pairs15.py OUTDIR FROM TO\n')
        return 2
    outdir, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    ntri = []
    for s in range(lo, hi):
        kind, A, B, desc = make_pair(s)
        for tag, m in (('a', A), ('b', B)):
            validate(m, 'seed %d kind %s mesh %s' % (s, kind, tag))
        for tag, m in (('a', A), ('b', B)):
            write_obj(os.path.join(outdir, '%06d_%s_%s.obj' % (s, kind, tag)), m,
                      'gen15 seed=%d kind=%s mesh=%s %s' % (s, kind, tag, desc))
            ntri.append(len(m.f))
    if ntri:
        ntri.sort()
        print('generate_pairs15: %d pairs in %s, triangles/mesh min=%d median=%d max=%d' %
              (hi - lo, outdir, ntri[0], ntri[len(ntri) // 2], ntri[-1]))
    else:
        print('generate_pairs15: 0 pairs')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
