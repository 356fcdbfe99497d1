#!/usr/bin/env python3
"""Ninth generator of degenerate triangle-mesh pairs for Hausdorff Lens (issue 8).

Written by a helper who read only the docstrings and KINDS lists of generate_pairs.py and
generate_pairs3.py .. generate_pairs8.py (not their code).  It follows up on the one kind of
generate_pairs8.py that found real bugs (mixed_scale_sim: 1e6-sized triangles carrying 1e-6-sized
ones under a random similarity) and COMBINES several degeneracies at once at extreme scale ratios:
tiny targets (1e-12..1e-6 of the scene, or only 1..1e4 ulps of their coordinates across) lying on
or near huge slivers, huge zero-area triangles, shared edges and vertices of huge meshes, clusters
at huge vertices / edge midpoints / interiors (coplanar or lifted 1e-15..1e-6), huge slivers
crossing tiny targets at an angle, point-like (ulp-jittered) triangles, tiny fins, duplicated huge
faces moved by 1 ulp, near-coincident copies that differ only in their tiny features.
Python 3 standard library only; deterministic per seed (random.Random(seed)); every mesh has
1..40 triangles and finite coordinates ('v x y z' with %.17g, 'f i j k' 1-based).

Usage:  python3 tests/independent/generate_pairs9.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/<seed:06d>_<kind>_a.obj and OUTDIR/<seed:06d>_<kind>_b.obj for every seed in
[SEED_FROM, SEED_TO), kind = KINDS[seed % len(KINDS)]; then
        hlens_check_pairs --pairs OUTDIR [--every-target | --thorough]

Scene: "huge" = size ~1 in the local frame, "tiny" = 1e-12..1e-6 of it, "ulp" = k ulps of the
feature's world coordinates (k in 1..1e4).  Placement (unless a kind says otherwise): none (10%),
exact (signed axis permutation, power-of-two scale, dyadic offset; 20%) or a random similarity
(rotation not axis-aligned, scale 10**U(-6,6), offset 0 or up to 1e8 sizes; 70%).  Huge parts are
placed as one function for both meshes (exact coincidences survive); tiny parts are added in world
coordinates to their placed anchor (so their relative precision survives a huge offset, unless the
offset is so large that they round to points, which is kept as one more degeneracy).  A and B are
swapped at random in non-far kinds.

Kinds ending in "_far" are near-coincident pairs moved 1e3..1e8 sizes from the origin (the checker
then requires a certified interval no wider than 1e-9 of the diagonal); their differing features
are at least 1e3 times the rounding of the placement (so at 1e8 sizes "tiny" means >= ~1e-5).
No other kind ends in "_far".

Kinds (32):
  sliver_tiny_on_edge    huge sliver (1e-13..1e-6 thin, apex inside/outside its base span) maybe
                         with a huge neighbour on its long edge; tiny / ulp targets on its long
                         edge, apex, base vertices, inside, just beyond its ends
  zeroarea_huge_tiny     huge zero-area triangles (collinear triples, repeated vertex, point) plus
                         a huge face; tiny targets on / across / beside the degenerate line
  shared_edge_tiny       2..4 huge triangles sharing one edge (dihedral pi, pi/2, pi-eps, eps, any)
                         and tiny / ulp targets on the shared edge, its ends, straddling it
  shared_vertex_tiny     a fan of 3..8 huge triangles (flat, cone of tiny height, with slivers)
                         and a tiny cluster at the hub (coplanar, lifted, point-like)
  cluster_vertex         huge triangle(s) in both meshes with different tiny clusters at a vertex
  cluster_midpoint       the same at an edge midpoint
  cluster_interior       the same at an interior point
  sliver_cross_tiny      huge slivers crossing a tiny target at an angle 1e-12..1.5 rad, through
                         its interior, along an edge, through a vertex, or just missing it
  pointlike_huge         ulp-jittered point-like triangles at vertices and on edges of a huge mesh
                         (with slivers), against that huge mesh
  pointlike_tiny_mesh    a huge face carrying a tiny mesh; point-like triangles at the tiny
                         mesh's vertices and edge points
  tinydiff_coinc         both meshes share huge faces exactly and differ only in tiny features
                         (moved, lifted, re-triangulated, rotated, missing)
  tinydiff_coinc_far     the same, far from the origin
  tiny_fins              tiny perpendicular (or 1e-9..1e-3 off) fins standing on / hanging from
                         huge faces at interior points, on edges, at vertices, on shared edges
  dup_ulp_huge_tiny      huge faces duplicated with 1..3-ulp vertex moves, carrying tiny features
  dup_ulp_huge_tiny_far  the same, far from the origin (features differ by >= 1e3 roundings)
  sliver_fan_tiny        a fan of huge slivers (nearly collinear spokes) with tiny targets at
                         the hub or along the spokes
  tiny_tilted_grid       a tiny grid nearly coplanar with a huge face (tilt 1e-12..1e-2 rad, lift)
  tiny_coplanar_retri    a huge triangle re-triangulated through a tiny polygon inside it (huge
                         slivers with tiny edges) against the plain triangle plus the polygon
  zeroarea_cross_tiny    huge zero-area triangles (segments) crossing / grazing a tiny target
  pointlike_ulp_cloud    a target made only of point-like triangles 1..1e4 ulps across, on the
                         vertices, edges and faces of a huge mesh and near each other
  hinge_crease_tiny      a huge hinge nearly flat or nearly shut (1e-12..1e-3 rad) with tiny
                         features on the crease and on both leaves
  dup_layers_tiny        a huge face and its copy 0..1e-9 (or 1 ulp) above, tiny targets between
  huge_vs_tiny_only      a huge mesh against a tiny mesh only (at a vertex, edge, inside, outside)
  nested_three_scales    1, 1e-6 and 1e-12 triangles nested at vertices / edges, different in A, B
  perp_corner_tiny       2..3 huge perpendicular faces (L, box corner) with tiny targets on the
                         crease line and at the corner
  sliver_stack_tiny      huge parallel slivers stacked 1e-15..1e-9 apart (or crossing at tiny
                         angles) with tiny targets between them
  tiny_straddle_edge     tiny triangles straddling a huge boundary edge at tiny angles
  sliver_on_sliver       a tiny sliver (aspect 1e-12..1e-3) on / across a huge sliver
  ulp_vs_ulp             tiny meshes a few ulps across in both meshes at the same anchors on a
                         huge face / vertex / edge
  sliver_tinydiff_far    near-coincident huge slivers with tiny features differing, far away
  cluster_coinc_far      shared huge face(s) with clusters at a vertex, one copy rotated / lifted
  fin_coinc_far          shared huge face(s) with tiny fins of slightly different heights / tilts
"""
import math
import os
import random
import sys

MAXT = 40

# ----------------------------------------------------------------------------- vector helpers


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, k):
    return (a[0] * k, a[1] * k, a[2] * k)


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


def bary(a, b, c, u, v):
    w = 1.0 - u - v
    return tuple(w * a[i] + u * b[i] + v * c[i] for i in range(3))


def rand_unit(r):
    while True:
        v = (r.gauss(0, 1), r.gauss(0, 1), r.gauss(0, 1))
        n = norm(v)
        if n > 1e-3:
            return mul(v, 1.0 / n)


def rand_rot(r):
    q = [r.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q))
    w, x, y, z = (c / n for c in q)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def exact_rot(r):
    p = [0, 1, 2]
    r.shuffle(p)
    R = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        R[i][p[i]] = r.choice((-1.0, 1.0))
    return tuple(tuple(row) for row in R)


def log_u(r, lo, hi):
    return 10.0 ** r.uniform(lo, hi)


# ----------------------------------------------------------------------------- ulp helpers


def ulp_of(p):
    m = max(abs(p[0]), abs(p[1]), abs(p[2]))
    if m == 0.0:
        m = 1e-300
    return math.ulp(m)


def jit(r, p, kmax, base=None):
    """p with each coordinate moved by an integer number in [-kmax, kmax] of ulps of p."""
    u = ulp_of(p if base is None else base)
    return tuple(c + r.randint(-kmax, kmax) * u for c in p)


def nudge1(r, p):
    """p with one or more coordinates moved by exactly 1..3 ulps (nextafter)."""
    q = list(p)
    for i in range(3):
        if r.random() < 0.5 or i == 2:
            for _ in range(r.randint(1, 3)):
                q[i] = math.nextafter(q[i], r.choice((math.inf, -math.inf)))
    return tuple(q)


def ulp_k(r):
    return r.choice((1, 1, 2, 3, 4, 8, 16, 100, 1000, 10000))


def pointlike(r, p, k=None):
    """A triangle a few ulps across (or exactly a point / segment) at world point p."""
    if k is None:
        k = ulp_k(r)
    c = r.random()
    if c < 0.15:
        return (p, p, p)
    if c < 0.35:
        return (p, p, jit(r, p, k))
    if c < 0.5:  # ulp segment: collinear triple
        d = jit(r, p, k)
        return (p, d, tuple(2 * d[i] - p[i] for i in range(3)))
    return (jit(r, p, k), jit(r, p, k), jit(r, p, k))


# ----------------------------------------------------------------------------- placement


class Place:
    def __init__(self, R, s, o, far_e=None):
        self.R, self.s, self.o, self.far_e = R, s, o, far_e
        self.cache = {}

    def vec(self, d):
        R, s = self.R, self.s
        return tuple(s * (R[i][0] * d[0] + R[i][1] * d[1] + R[i][2] * d[2]) for i in range(3))

    def pt(self, p):
        p = tuple(float(c) for c in p)
        w = self.cache.get(p)
        if w is None:
            v = self.vec(p)
            w = (v[0] + self.o[0], v[1] + self.o[1], v[2] + self.o[2])
            self.cache[p] = w
        return w

    def at(self, c, d):
        """world point of local anchor c plus a (tiny) local offset d, added in world coords."""
        w = self.pt(c)
        v = self.vec(d)
        return (w[0] + v[0], w[1] + v[1], w[2] + v[2])

    def tri(self, t):
        return tuple(self.pt(p) for p in t)

    def min_rel(self):
        """smallest relative (local) feature that stays >= 1e3 roundings of the placement."""
        if self.far_e is None:
            return 0.0
        return 10.0 ** self.far_e * 2.3e-16 * 4e3


def make_place(r):
    c = r.random()
    if c < 0.1:
        return Place(((1.0, 0, 0), (0, 1.0, 0), (0, 0, 1.0)), 1.0, (0.0, 0.0, 0.0))
    if c < 0.3:
        s = 2.0 ** r.randint(-20, 20)
        o = tuple(float(r.randint(-1000, 1000)) * 2.0 ** r.randint(-20, 20) for _ in range(3))
        if r.random() < 0.4:
            o = (0.0, 0.0, 0.0)
        return Place(exact_rot(r), s, o)
    s = log_u(r, -6, 6)
    c = r.random()
    if c < 0.2:
        o = (0.0, 0.0, 0.0)
    elif c < 0.75:
        o = mul(rand_unit(r), s * log_u(r, -1, 4))
    else:
        o = mul(rand_unit(r), s * log_u(r, 4, 8))
    return Place(rand_rot(r), s, o)


def make_far_place(r):
    s = log_u(r, -6, 6)
    e = r.uniform(3, 8)
    o = mul(rand_unit(r), s * 10.0 ** e)
    return Place(rand_rot(r), s, o, far_e=e)


# ----------------------------------------------------------------------------- local shapes

O3 = (0.0, 0.0, 0.0)
EX, EY, EZ = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


def huge_tri(r):
    c = r.random()
    if c < 0.35:
        return (O3, EX, (r.uniform(-0.3, 1.3), r.uniform(0.3, 1.2), 0.0))
    if c < 0.55:
        return (O3, EX, EY)
    if c < 0.7:
        return (O3, EX, (0.5, math.sqrt(3) / 2, 0.0))
    if c < 0.85:  # obtuse / long
        return (O3, EX, (r.uniform(-2, 3), r.uniform(0.05, 0.3), 0.0))
    while True:
        pts = [(r.uniform(-1, 1), r.uniform(-1, 1), 0.0) for _ in range(3)]
        if abs(cross(sub(pts[1], pts[0]), sub(pts[2], pts[0]))[2]) > 0.2:
            return tuple(pts)


def huge_square(r):
    a, b, c, d = O3, EX, (1.0, 1.0, 0.0), EY
    if r.random() < 0.5:
        return [(a, b, c), (a, c, d)]
    return [(a, b, d), (b, c, d)]


def sliver_thin(r):
    return log_u(r, -13, -6)


def sliver_tri(r, w=None):
    if w is None:
        w = sliver_thin(r)
    x = r.choice((0.5, r.uniform(0, 1), r.uniform(-0.5, 1.5), 0.0, 1.0, r.uniform(-3, 4)))
    return (O3, EX, (x, w, 0.0))


def tiny_size(r, P=None):
    lo = -12.0
    if P is not None and P.min_rel() > 0:
        lo = max(lo, math.log10(P.min_rel()))
    hi = max(-6.0, lo + 1.0)
    return log_u(r, lo, min(hi, -2.0))


def tiny_lift(r, P=None):
    if r.random() < 0.35:
        return 0.0
    lo = -15.0
    if P is not None and P.min_rel() > 0:
        lo = max(lo, math.log10(P.min_rel()))
    return r.choice((-1.0, 1.0)) * log_u(r, lo, max(-6.0, lo + 1.0))


def tiny_shape2(r, t):
    """2D offsets of a tiny triangle of size ~t (random, sliver, equilateral or zero-area)."""
    c = r.random()
    if c < 0.45:
        pts = [(r.uniform(-1, 1) * t, r.uniform(-1, 1) * t) for _ in range(3)]
    elif c < 0.65:
        h = t * log_u(r, -12, -3)
        pts = [(0.0, 0.0), (t, 0.0), (r.uniform(-0.5, 1.5) * t, h)]
    elif c < 0.85:
        pts = [(t * math.cos(a), t * math.sin(a)) for a in (0.0, 2.0943951023931953, 4.1887902047863905)]
    else:
        a = r.uniform(0, 1)
        pts = [(0.0, 0.0), (t, 0.0), (a * t, 0.0)] if r.random() < 0.7 else [(0.0, 0.0)] * 2 + [(t, 0.0)]
    if r.random() < 0.3:  # anchor at a vertex of the tiny triangle
        x0, y0 = pts[0]
        pts = [(x - x0, y - y0) for x, y in pts]
    ang = r.uniform(0, 2 * math.pi)
    ca, sa = math.cos(ang), math.sin(ang)
    return [(x * ca - y * sa, x * sa + y * ca) for x, y in pts]


def frame_of(tri):
    a, b, c = tri
    u = unit(sub(b, a))
    n = unit(cross(sub(b, a), sub(c, a)))
    v = cross(n, u)
    return (u, v, n)


FZ = (EX, EY, EZ)


def tiny_tri(r, P, c, t=None, lift=None, tilt=None, frame=FZ):
    """A tiny triangle anchored at local point c, in the plane (u, v) of frame, lifted along n,
    optionally tilted by angle tilt about u; world coordinates relative to P.pt(c)."""
    if t is None:
        t = tiny_size(r, P)
    if lift is None:
        lift = tiny_lift(r, P)
    if tilt is None:
        tilt = 0.0 if r.random() < 0.6 else r.choice((1.0, -1.0)) * log_u(r, -12, 0.2)
    u, v, n = frame
    ct, st = math.cos(tilt), math.sin(tilt)
    out = []
    for x, y in tiny_shape2(r, t):
        d = add(add(mul(u, x), mul(v, y * ct)), mul(n, y * st + lift))
        out.append(P.at(c, d))
    return tuple(out)


def tiny_feature(r, P, c, frame=FZ, ulp_prob=0.3):
    if r.random() < ulp_prob and P.far_e is None:
        lift = tiny_lift(r, P)
        return pointlike(r, P.at(c, mul(frame[2], lift)))
    return tiny_tri(r, P, c, frame=frame)


def tiny_cluster(r, P, c, n, frame=FZ, coplanar=None):
    """n tiny triangles around c: fan, grid piece or random soup, coplanar or lifted."""
    t = tiny_size(r, P)
    if coplanar is None:
        coplanar = r.random() < 0.5
    lift = 0.0 if coplanar else tiny_lift(r, P)
    u, v, n3 = frame
    c_ = r.random()
    out = []
    if c_ < 0.4:  # fan around c (or around a point near c)
        hub = (0.0, 0.0) if r.random() < 0.6 else (r.uniform(-1, 1) * t, r.uniform(-1, 1) * t)
        a0 = r.uniform(0, 2 * math.pi)
        span = r.choice((2 * math.pi, math.pi, r.uniform(0.01, 6.0)))
        m = max(1, n)
        rim = []
        for i in range(m + 1):
            a = a0 + span * i / m
            rr = t * r.choice((1.0, r.uniform(0.5, 2.0)))
            rim.append((rr * math.cos(a), rr * math.sin(a)))
        for i in range(m):
            pts = (hub, rim[i], rim[i + 1])
            lf = lift if (coplanar or r.random() < 0.7) else lift * r.uniform(-1, 1)
            out.append(tuple(P.at(c, add(add(mul(u, x), mul(v, y)), mul(n3, lf))) for x, y in pts))
    elif c_ < 0.7:  # k x k grid piece
        k = max(1, int(math.sqrt(n / 2.0)))
        for i in range(k):
            for j in range(k):
                p = [(t * (i + di) / k, t * (j + dj) / k) for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
                w = [P.at(c, add(add(mul(u, x), mul(v, y)), mul(n3, lift))) for x, y in p]
                if (i + j) % 2 or r.random() < 0.3:
                    out += [(w[0], w[1], w[2]), (w[0], w[2], w[3])]
                else:
                    out += [(w[0], w[1], w[3]), (w[1], w[2], w[3])]
    else:
        for _ in range(n):
            out.append(tiny_feature(r, P, c, frame))
    return out[:max(1, n)]


# ----------------------------------------------------------------------------- kinds
# Each kind returns (A, B): lists of world triangles.


def where_on_tri(r, tri):
    a, b, c = tri
    w = r.random()
    if w < 0.25:
        return r.choice(tri), 'vertex'
    if w < 0.45:
        p, q = r.choice(((a, b), (b, c), (c, a)))
        return lerp(p, q, 0.5), 'mid'
    if w < 0.65:
        p, q = r.choice(((a, b), (b, c), (c, a)))
        return lerp(p, q, r.choice((r.random(), 1e-7, 1 - 1e-9, r.random()))), 'edge'
    if w < 0.9:
        u = r.random()
        v = r.random() * (1 - u)
        return bary(a, b, c, u, v), 'inside'
    p, q = r.choice(((a, b), (b, c), (c, a)))
    return lerp(p, q, r.choice((-1e-9, 1 + 1e-7, -r.random(), 1 + r.random()))), 'beyond'


def k_sliver_tiny_on_edge(r, P):
    sl = sliver_tri(r)
    A = [P.tri(sl)]
    if r.random() < 0.5:
        z = 0.0 if r.random() < 0.5 else r.choice((1, -1)) * log_u(r, -12, 0)
        A.append(P.tri((EX, O3, (r.uniform(-0.5, 1.5), -r.uniform(0.2, 1), z))))
    if r.random() < 0.3:
        A.append(P.tri((O3, EX, (sl[2][0], 2 * sl[2][1], 0.0))))  # nested sliver
    B = []
    for _ in range(r.randint(1, 14)):
        w = r.random()
        if w < 0.35:
            c = (r.choice((r.random(), 0.5, 1e-6, 1 - 1e-6)), 0.0, 0.0)
        elif w < 0.5:
            c = sl[2]
        elif w < 0.65:
            c = r.choice((O3, EX))
        elif w < 0.85:
            c = bary(*sl, r.random() * 0.5, r.random() * 0.5)
        else:
            c = (r.choice((-log_u(r, -12, -6), 1 + log_u(r, -12, -6))), 0.0, 0.0)
        B.append(tiny_feature(r, P, c, frame=FZ if r.random() < 0.7 else (EX, EZ, (0.0, -1.0, 0.0))))
    if r.random() < 0.3:
        B.append(A[0])
    return A, B


def k_zeroarea_huge_tiny(r, P):
    p, q = O3, EX
    A = []
    m = r.random()
    A.append(P.tri((p, q, lerp(p, q, r.choice((0.5, r.random(), 2.0, -1.0))))))
    if m < 0.5:
        A.append(P.tri((p, q, q)))
    if r.random() < 0.3:
        A.append(P.tri((p, p, p)))
    if r.random() < 0.6:
        A.append(P.tri(huge_tri(r) if r.random() < 0.5 else (O3, EX, (r.uniform(0, 1), r.uniform(0.1, 1), r.choice((0.0, 0.5))))))
    B = []
    for _ in range(r.randint(1, 12)):
        c = lerp(p, q, r.choice((r.random(), 0.5, 0.0, 1.0, 1 + 1e-9, r.uniform(-1, 2))))
        fr = r.choice((FZ, (EX, EZ, (0.0, -1.0, 0.0)), (EY, EZ, EX)))
        B.append(tiny_feature(r, P, c, frame=fr))
    if r.random() < 0.3:
        B += A[: r.randint(1, len(A))]
    return A, B


def hinge_third(r):
    c = r.random()
    if c < 0.2:
        th = math.pi
    elif c < 0.35:
        th = math.pi / 2
    elif c < 0.55:
        th = math.pi - log_u(r, -12, -2)
    elif c < 0.75:
        th = log_u(r, -12, -2)
    else:
        th = r.uniform(0.1, 3.0)
    x = r.uniform(-0.3, 1.3)
    d = r.uniform(0.2, 1.0)
    return (x, d * math.cos(th), d * math.sin(th)), th


def k_shared_edge_tiny(r, P):
    base = (O3, EX, (r.uniform(-0.3, 1.3), r.uniform(0.2, 1.0), 0.0))
    A = [P.tri(base)]
    for _ in range(r.randint(1, 3)):
        t3, _ = hinge_third(r)
        A.append(P.tri((EX, O3, t3)))
    B = []
    for _ in range(r.randint(1, 12)):
        w = r.random()
        if w < 0.5:
            c = (r.choice((r.random(), 0.5, 1e-9)), 0.0, 0.0)
        elif w < 0.75:
            c = r.choice((O3, EX))
        else:
            c = (r.random(), 0.0, 0.0)
        fr = r.choice((FZ, (EX, EZ, (0.0, -1.0, 0.0)), (EZ, EY, (-1.0, 0.0, 0.0)), (EX, unit((0.0, 1.0, 1.0)), unit((0.0, -1.0, 1.0)))))
        B.append(tiny_feature(r, P, c, frame=fr))
    if r.random() < 0.25:
        B.append(A[0])
    return A, B


def k_shared_vertex_tiny(r, P):
    n = r.randint(3, 8)
    h = 0.0 if r.random() < 0.4 else r.choice((1, -1)) * log_u(r, -12, -1)
    full = r.random() < 0.6
    span = 2 * math.pi if full else r.uniform(0.5, 5.0)
    angs = sorted(r.uniform(0, span) for _ in range(n - 1)) + ([span] if not full else [])
    angs = [0.0] + angs
    if r.random() < 0.4:  # nearly collinear spokes
        k = r.randint(1, len(angs) - 1)
        angs[k] = angs[k - 1] + log_u(r, -12, -4)
    rim = [(math.cos(a), math.sin(a), 0.0) for a in angs]
    hub = (0.0, 0.0, h)
    A = []
    m = len(rim) if full else len(rim) - 1
    for i in range(m):
        A.append(P.tri((hub, rim[i], rim[(i + 1) % len(rim)])))
    B = tiny_cluster(r, P, hub, r.randint(1, 12))
    for _ in range(r.randint(0, 4)):
        B.append(pointlike(r, P.pt(hub)))
    return A[:MAXT], B


def cluster_kind(r, P, where):
    T = huge_tri(r)
    a, b, c = T
    if where == 'vertex':
        anchor = r.choice(T)
    elif where == 'mid':
        p, q = r.choice(((a, b), (b, c), (c, a)))
        anchor = lerp(p, q, 0.5)
    else:
        u = r.uniform(0.05, 0.9)
        anchor = bary(a, b, c, u, r.uniform(0.05, 0.95) * (1 - u))
    base_A = [T]
    base_B = [T]
    if r.random() < 0.4:  # B's huge face split at the anchor
        if where == 'inside':
            base_B = [(a, b, anchor), (b, c, anchor), (c, a, anchor)]
        elif where == 'mid':
            if anchor == lerp(a, b, 0.5):
                base_B = [(anchor, b, c), (a, anchor, c)]
            elif anchor == lerp(b, c, 0.5):
                base_B = [(a, b, anchor), (a, anchor, c)]
            else:
                base_B = [(a, b, anchor), (anchor, b, c)]
        else:
            base_B = [T, T] if r.random() < 0.5 else [(b, c, a)]
    if r.random() < 0.3:  # neighbouring huge face sharing an edge through the anchor region
        t3, _ = hinge_third(r)
        base_A.append((b, a, (a[0] + t3[0] * (b[0] - a[0]), -t3[1], t3[2])))
    A = [P.tri(t) for t in base_A]
    B = [P.tri(t) for t in base_B] if r.random() < 0.75 else []
    A += tiny_cluster(r, P, anchor, r.randint(1, 14))
    B += tiny_cluster(r, P, anchor, r.randint(1, 14))
    return A, B


def k_cluster_vertex(r, P):
    return cluster_kind(r, P, 'vertex')


def k_cluster_midpoint(r, P):
    return cluster_kind(r, P, 'mid')


def k_cluster_interior(r, P):
    return cluster_kind(r, P, 'inside')


def k_sliver_cross_tiny(r, P):
    T = huge_tri(r) if r.random() < 0.5 else (O3, EX, EY)
    c = bary(*T, r.uniform(0.1, 0.5), r.uniform(0.1, 0.4))
    t = tiny_size(r, P)
    tgt = tiny_tri(r, P, c, t=t, lift=0.0, tilt=0.0)
    A = []
    B = [tgt]
    if r.random() < 0.4:
        B.append(P.tri(T))
    for _ in range(r.randint(1, 6)):
        ang = r.choice((r.uniform(0, 1.5), log_u(r, -12, -1), math.pi / 2))
        phi = r.uniform(0, 2 * math.pi)
        d = (math.cos(phi), math.sin(phi), 0.0)
        tilt_axis = (-d[1], d[0], 0.0)
        dirv = add(mul(d, math.cos(ang)), mul(EZ, math.sin(ang)))
        w = r.random()
        # point the sliver passes through: c, a tiny-target vertex offset, or just missing
        if w < 0.4:
            off = (0.0, 0.0, 0.0)
        elif w < 0.7:
            off = mul(tilt_axis, t * r.uniform(-1, 1))
        else:
            off = mul(EZ, tiny_lift(r, P) or t)
        thin = sliver_thin(r)
        L = r.uniform(0.3, 2.0)
        p0 = add(add(c, off), mul(dirv, -L * r.uniform(0.2, 0.8)))
        p1 = add(p0, mul(dirv, L))
        side = unit(cross(dirv, tilt_axis)) if r.random() < 0.5 else tilt_axis
        p2 = add(lerp(p0, p1, r.uniform(-0.5, 1.5)), mul(side, thin))
        A.append(P.tri((p0, p1, p2)))
    return A, B


def k_pointlike_huge(r, P):
    tris = huge_square(r) if r.random() < 0.4 else [huge_tri(r)]
    if r.random() < 0.5:
        tris.append(sliver_tri(r))
    A = [P.tri(t) for t in tris]
    B = []
    for _ in range(r.randint(1, 16)):
        T = r.choice(tris)
        c, _ = where_on_tri(r, T)
        B.append(pointlike(r, P.pt(c)))
    if r.random() < 0.3:
        B += A
    return A, B


def k_pointlike_tiny_mesh(r, P):
    T = huge_tri(r)
    anchor, _ = where_on_tri(r, T)
    A = [P.tri(T)]
    tiny = tiny_cluster(r, P, anchor, r.randint(1, 10), coplanar=r.random() < 0.7)
    A += tiny
    B = []
    for _ in range(r.randint(1, 16)):
        tt = r.choice(tiny)
        w = r.random()
        if w < 0.5:
            p = r.choice(tt)
        else:
            i = r.randint(0, 2)
            p = lerp(tt[i], tt[(i + 1) % 3], r.choice((0.5, r.random())))
        B.append(pointlike(r, p))
    if r.random() < 0.3:
        B.append(A[0])
    return A, B


def tinydiff(r, P, far):
    tris = huge_square(r) if r.random() < 0.4 else [huge_tri(r)]
    if r.random() < 0.3:
        tris.append(sliver_tri(r, w=max(sliver_thin(r), P.min_rel() * 10)))
    A = [P.tri(t) for t in tris]
    B = list(A)
    mr = P.min_rel()
    for _ in range(r.randint(1, 4)):
        T = r.choice(tris)
        anchor, _ = where_on_tri(r, T)
        n = r.randint(1, 6)
        t = tiny_size(r, P)
        lift = tiny_lift(r, P)
        shapes = [tiny_shape2(r, t) for _ in range(n)]
        mode = r.choice(('move', 'lift', 'rot', 'missing', 'retri', 'scale'))
        delta = max(mr, t * log_u(r, -6, 0))

        def emit(shs, lf, dx=(0.0, 0.0), ang=0.0, k=1.0):
            out = []
            ca, sa = math.cos(ang), math.sin(ang)
            for sh in shs:
                out.append(tuple(P.at(anchor, (k * (x * ca - y * sa) + dx[0], k * (x * sa + y * ca) + dx[1], lf)) for x, y in sh))
            return out
        A += emit(shapes, lift)
        if mode == 'move':
            B += emit(shapes, lift, dx=(delta * r.uniform(-1, 1), delta * r.uniform(-1, 1)))
        elif mode == 'lift':
            B += emit(shapes, lift + r.choice((1, -1)) * delta)
        elif mode == 'rot':
            B += emit(shapes, lift, ang=max(delta / t, mr / t) if t > 0 else 1e-3)
        elif mode == 'missing':
            B += emit(shapes[: r.randint(0, n - 1)], lift)
        elif mode == 'retri':
            pts = [p for sh in shapes for p in sh]
            r.shuffle(pts)
            sh2 = [pts[i:i + 3] for i in range(0, len(pts) - 2, 3)]
            B += emit(sh2, lift)
        else:
            B += emit(shapes, lift, k=1.0 + max(delta / t, 1e-12))
    if not far and r.random() < 0.5:
        A, B = B, A
    return A, B


def k_tinydiff_coinc(r, P):
    return tinydiff(r, P, False)


def k_tinydiff_coinc_far(r, P):
    return tinydiff(r, P, True)


def fin_tris(r, P, anchor, frame, t, tilt_off, hang, h=None):
    u, v, n = frame
    if h is None:
        h = t * r.choice((1.0, r.uniform(0.1, 3.0), log_u(r, -6, 0)))
    ang = math.pi / 2 + tilt_off
    up = add(mul(v, math.cos(ang)), mul(n, math.sin(ang) * (-1.0 if hang else 1.0)))
    a = P.at(anchor, mul(u, -t * 0.5))
    b = P.at(anchor, mul(u, t * 0.5))
    c = P.at(anchor, add(mul(u, r.uniform(-0.5, 0.5) * t), mul(up, h)))
    out = [(a, b, c)]
    if r.random() < 0.4:
        d = P.at(anchor, add(mul(u, t * 0.5), mul(up, h)))
        out.append((b, d, c))
    return out


def k_tiny_fins(r, P):
    tris = huge_square(r) if r.random() < 0.5 else [huge_tri(r)]
    if r.random() < 0.3:
        t3, _ = hinge_third(r)
        tris.append((EX, O3, t3))
    A = [P.tri(t) for t in tris]
    B = []
    for _ in range(r.randint(1, 8)):
        T = r.choice(tris)
        anchor, _ = where_on_tri(r, T)
        fu, fv, fn = frame_of(T)
        ang = r.uniform(0, 2 * math.pi)
        u = add(mul(fu, math.cos(ang)), mul(fv, math.sin(ang)))
        if r.random() < 0.4:  # fin aligned with an edge of T
            i = r.randint(0, 2)
            u = unit(sub(T[(i + 1) % 3], T[i]))
        fr = (u, cross(fn, u), fn)
        off = 0.0 if r.random() < 0.5 else r.choice((1, -1)) * log_u(r, -9, -3)
        B += fin_tris(r, P, anchor, fr, tiny_size(r, P), off, r.random() < 0.3)
    if r.random() < 0.3:
        A, B = B, A
    return A, B


def dup_ulp(r, P, far):
    tris = huge_square(r) if r.random() < 0.4 else [huge_tri(r)]
    if r.random() < 0.3:
        tris.append(sliver_tri(r, w=max(sliver_thin(r), P.min_rel() * 10)))
    A = [P.tri(t) for t in tris]
    B = [P.tri(t) for t in tris]
    for t in tris:
        w = P.tri(t)
        if r.random() < 0.8:
            moved = tuple(nudge1(r, p) if r.random() < 0.6 else p for p in w)
            (A if r.random() < 0.5 else B).append(moved)
        if r.random() < 0.3:
            A.append((w[1], w[0], w[2]))
    for _ in range(r.randint(1, 4)):
        T = r.choice(tris)
        anchor, _ = where_on_tri(r, T)
        n = r.randint(1, 5)
        if far:
            A += tiny_cluster(r, P, anchor, n, coplanar=r.random() < 0.5)
            B += tiny_cluster(r, P, anchor, n, coplanar=r.random() < 0.5)
        else:
            (A if r.random() < 0.5 else B).extend(tiny_cluster(r, P, anchor, n))
    return A, B


def k_dup_ulp_huge_tiny(r, P):
    return dup_ulp(r, P, False)


def k_dup_ulp_huge_tiny_far(r, P):
    return dup_ulp(r, P, True)


def k_sliver_fan_tiny(r, P):
    n = r.randint(3, 12)
    a0 = r.uniform(0, 2 * math.pi)
    angs = [a0]
    for _ in range(n):
        angs.append(angs[-1] + r.choice((log_u(r, -12, -4), log_u(r, -4, -1), r.uniform(0.1, 1.0))))
    hub = O3
    rim = [(math.cos(a) * r.choice((1.0, r.uniform(0.5, 1.5))), math.sin(a) * 1.0, 0.0 if r.random() < 0.7 else log_u(r, -12, -3)) for a in angs]
    A = [P.tri((hub, rim[i], rim[i + 1])) for i in range(n)]
    B = []
    for _ in range(r.randint(1, 10)):
        if r.random() < 0.5:
            c = hub
        else:
            c = lerp(hub, r.choice(rim), r.choice((r.random(), 1e-6, 1e-9)))
        B.append(tiny_feature(r, P, c))
    return A, B


def k_tiny_tilted_grid(r, P):
    tris = huge_square(r) if r.random() < 0.5 else [huge_tri(r)]
    A = [P.tri(t) for t in tris]
    if r.random() < 0.3:
        A.append(P.tri(sliver_tri(r)))
    T = tris[0]
    anchor, _ = where_on_tri(r, T)
    t = tiny_size(r, P)
    k = r.randint(1, 4)
    tilt = r.choice((1, -1)) * log_u(r, -12, -2)
    lift = tiny_lift(r, P)
    ang = r.uniform(0, 2 * math.pi)
    u = (math.cos(ang), math.sin(ang), 0.0)
    v0 = (-u[1], u[0], 0.0)
    v = add(mul(v0, math.cos(tilt)), mul(EZ, math.sin(tilt)))
    cx = r.choice((0.0, -0.5, r.uniform(-1, 0)))
    B = []
    for i in range(k):
        for j in range(k):
            q = []
            for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                x, y = t * ((i + di) / k + cx), t * ((j + dj) / k + cx)
                q.append(P.at(anchor, add(add(mul(u, x), mul(v, y)), mul(EZ, lift))))
            if r.random() < 0.5:
                B += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
            else:
                B += [(q[0], q[1], q[3]), (q[1], q[2], q[3])]
    if r.random() < 0.4:
        B += tiny_cluster(r, P, anchor, r.randint(1, 6), coplanar=True)
    if r.random() < 0.3:
        A, B = B, A
    return A, B


def k_tiny_coplanar_retri(r, P):
    T = huge_tri(r)
    a, b, c = T
    anchor = bary(a, b, c, r.uniform(0.1, 0.6), r.uniform(0.1, 0.3))
    if r.random() < 0.3:  # near an edge or vertex
        anchor = lerp(a, b, r.random()) if r.random() < 0.5 else a
        anchor = lerp(anchor, c, log_u(r, -10, -3))
    t = tiny_size(r, P)
    m = r.randint(3, 7)
    a0 = r.uniform(0, 2 * math.pi)
    poly = [(t * math.cos(a0 + 2 * math.pi * i / m), t * math.sin(a0 + 2 * math.pi * i / m), 0.0) for i in range(m)]
    # local coordinates of polygon vertices (rounded locally; all in the plane z = 0 exactly)
    pl = [add(anchor, p) for p in poly]
    A = [P.tri(T)]
    # polygon triangulated as a fan from pl[0] (A) or a fan from its centre (B)
    fanA = [(pl[0], pl[i], pl[i + 1]) for i in range(1, m - 1)]
    A += [P.tri(x) for x in fanA]
    # B: the annulus between the huge triangle and the polygon zipped by angle around the anchor
    # (huge slivers with tiny edges), plus the polygon as a centre fan or a fan from pl[1]
    if cross(sub(b, a), sub(c, a))[2] < 0:
        a, b, c = a, c, b
    vs = [a, b, c]

    def ang_of(p):
        return math.atan2(p[1] - anchor[1], p[0] - anchor[0]) % (2 * math.pi)
    outer = sorted(vs, key=ang_of)
    inner = sorted(pl, key=ang_of)
    ev = sorted([(ang_of(p), 0, p) for p in outer] + [(ang_of(p), 1, p) for p in inner], key=lambda e: (e[0], e[1]))
    B = []
    cur = {0: outer[-1], 1: inner[-1]}
    for _, kind, p in ev:
        B.append(P.tri((cur[0], cur[1], p) if kind == 0 else (cur[0], cur[1], p)))
        cur[kind] = p
    if r.random() < 0.5:
        B += [P.tri((anchor, pl[i], pl[(i + 1) % m])) for i in range(m)]
    else:
        B += [P.tri((pl[1], pl[i], pl[(i + 1) % m])) for i in range(2, m)] + [P.tri((pl[1], pl[0], pl[0]))]
    if r.random() < 0.4:
        A, B = B, A
    return A, B


def k_zeroarea_cross_tiny(r, P):
    T = huge_tri(r)
    c = bary(*T, r.uniform(0.1, 0.5), r.uniform(0.1, 0.4))
    t = tiny_size(r, P)
    B = [tiny_tri(r, P, c, t=t, lift=0.0, tilt=0.0) for _ in range(r.randint(1, 3))]
    if r.random() < 0.4:
        B.append(P.tri(T))
    A = []
    for _ in range(r.randint(1, 6)):
        ang = r.choice((r.uniform(0, 1.5), log_u(r, -12, -1), math.pi / 2, 0.0))
        phi = r.uniform(0, 2 * math.pi)
        d = (math.cos(phi) * math.cos(ang), math.sin(phi) * math.cos(ang), math.sin(ang))
        off = (0.0, 0.0, 0.0) if r.random() < 0.5 else (t * r.uniform(-1, 1), t * r.uniform(-1, 1), r.choice((0.0, tiny_lift(r, P))))
        L = r.uniform(0.5, 2)
        p0 = add(add(c, off), mul(d, -L * r.uniform(0, 1)))
        p1 = add(p0, mul(d, L))
        w = r.random()
        if w < 0.5:
            A.append(P.tri((p0, p1, lerp(p0, p1, r.choice((0.5, r.random(), 1.5))))))
        elif w < 0.8:
            A.append(P.tri((p0, p1, p1)))
        else:
            A.append(P.tri((p0, p1, add(lerp(p0, p1, 0.5), mul(unit(cross(d, EZ)) if ang < 1.5 else EX, sliver_thin(r))))))
    if r.random() < 0.3:
        A.append(P.tri(T))
    return A, B


def k_pointlike_ulp_cloud(r, P):
    tris = huge_square(r) if r.random() < 0.4 else [huge_tri(r)]
    if r.random() < 0.4:
        tris.append(sliver_tri(r))
    if r.random() < 0.3:
        tris.append((O3, EX, EX))
    A = [P.tri(t) for t in tris]
    B = []
    anchors = []
    for _ in range(r.randint(1, 6)):
        c, _ = where_on_tri(r, r.choice(tris))
        anchors.append(P.at(c, (0.0, 0.0, tiny_lift(r, P) if r.random() < 0.3 else 0.0)))
    for _ in range(r.randint(2, 24)):
        p = r.choice(anchors)
        B.append(pointlike(r, p))
    if r.random() < 0.3:
        A += [pointlike(r, r.choice(anchors)) for _ in range(r.randint(1, 6))]
    return A, B


def k_hinge_crease_tiny(r, P):
    eps = log_u(r, -12, -3)
    shut = r.random() < 0.5
    th = eps if shut else math.pi - eps
    x = r.uniform(-0.3, 1.3)
    base = (O3, EX, (r.uniform(-0.3, 1.3), r.uniform(0.2, 1.0), 0.0))
    other = (EX, O3, (x, math.cos(th), math.sin(th)))
    A = [P.tri(base), P.tri(other)]
    B = []
    if r.random() < 0.5:
        B.append(P.tri(base) if r.random() < 0.5 else P.tri(other))
    fo = frame_of(other)
    for _ in range(r.randint(1, 12)):
        w = r.random()
        if w < 0.5:
            c = (r.random(), 0.0, 0.0)
            fr = r.choice((FZ, fo))
        elif w < 0.75:
            c = bary(*base, log_u(r, -9, -1), 0.0) if r.random() < 0.5 else bary(*base, r.random() * 0.5, log_u(r, -12, -3))
            fr = FZ
        else:
            c = bary(*other, r.random() * 0.5, log_u(r, -12, -3))
            fr = fo
        B.append(tiny_feature(r, P, c, frame=fr))
    if r.random() < 0.3:
        A, B = B, A
    return A, B


def k_dup_layers_tiny(r, P):
    T = huge_tri(r)
    A = [P.tri(T)]
    w = r.random()
    if w < 0.3:
        A.append(tuple(nudge1(r, p) for p in P.tri(T)))
        gap = 0.0
    else:
        gap = r.choice((0.0, log_u(r, -15, -9)))
        A.append(tuple(P.at(p, (0.0, 0.0, gap)) for p in T))
    if r.random() < 0.3:
        A.append(P.tri((T[1], T[0], T[2])))
    B = []
    for _ in range(r.randint(1, 10)):
        c, _ = where_on_tri(r, T)
        if r.random() < 0.5:
            B.append(tiny_tri(r, P, c, lift=gap * r.choice((0.5, 0.0, 1.0, r.random())), tilt=r.choice((0.0, log_u(r, -12, -1)))))
        else:
            B.append(pointlike(r, P.at(c, (0.0, 0.0, gap * 0.5))))
    if r.random() < 0.3:
        A, B = B, A
    return A, B


def k_huge_vs_tiny_only(r, P):
    tris = [huge_tri(r)]
    if r.random() < 0.5:
        tris.append(sliver_tri(r))
    if r.random() < 0.3:
        t3, _ = hinge_third(r)
        tris.append((EX, O3, t3))
    A = [P.tri(t) for t in tris]
    c, _ = where_on_tri(r, tris[0])
    if r.random() < 0.2:
        c = (r.uniform(-2, 2), r.uniform(-2, 2), r.uniform(-1, 1))
    B = tiny_cluster(r, P, c, r.randint(1, 10))
    if r.random() < 0.5:
        A, B = B, A
    return A, B


def k_nested_three_scales(r, P):
    T = huge_tri(r) if r.random() < 0.5 else (O3, EX, (0.3, 0.9, 0.0))

    def build():
        out = [P.tri(T)]
        c1, _ = where_on_tri(r, T)
        s1 = log_u(r, -7, -5)
        # middle-size triangle (local coordinates, so that its vertices can anchor the smallest)
        sh = tiny_shape2(r, s1)
        lift1 = 0.0 if r.random() < 0.6 else tiny_lift(r)
        mids = [add(c1, (x, y, lift1)) for x, y in sh]
        out.append(P.tri(tuple(mids)))
        for _ in range(r.randint(1, 4)):
            c2 = r.choice(mids) if r.random() < 0.5 else lerp(r.choice(mids), r.choice(mids), 0.5)
            t2 = s1 * log_u(r, -7, -5)
            out.append(tiny_tri(r, P, c2, t=t2, lift=r.choice((0.0, t2 * log_u(r, -3, 0)))))
            if r.random() < 0.3:
                out.append(pointlike(r, P.pt(c2)))
        return out
    A = build()
    B = build()
    if r.random() < 0.3:
        B = B[1:]
    return A, B


def k_perp_corner_tiny(r, P):
    faces = [(O3, EX, EY), (O3, EY, EZ)]
    if r.random() < 0.5:
        faces.append((O3, EZ, EX))
    if r.random() < 0.3:
        faces.append((EX, (1.0, 1.0, 0.0), EY))
    A = [P.tri(f) for f in faces]
    B = []
    for _ in range(r.randint(1, 12)):
        w = r.random()
        if w < 0.3:
            c = O3
        elif w < 0.7:
            c = r.choice(((r.random(), 0.0, 0.0), (0.0, r.random(), 0.0), (0.0, 0.0, r.random())))
        else:
            c = (log_u(r, -12, -3), log_u(r, -12, -3), log_u(r, -12, -3) if r.random() < 0.5 else 0.0)
        fr = r.choice((FZ, (EY, EZ, EX), (EZ, EX, EY), (unit((1.0, 1.0, 0.0)), EZ, unit((1.0, -1.0, 0.0))), (unit((1.0, 1.0, 1.0)), unit((1.0, -1.0, 0.0)), unit((1.0, 1.0, -2.0)))))
        B.append(tiny_feature(r, P, c, frame=fr))
    return A, B


def k_sliver_stack_tiny(r, P):
    sl = sliver_tri(r)
    n = r.randint(2, 5)
    A = []
    lifts = [0.0]
    for i in range(1, n):
        lifts.append(lifts[-1] + r.choice((log_u(r, -15, -9), 0.0)))
    crossing = r.random() < 0.3
    for i, h in enumerate(lifts):
        if crossing and i % 2:
            ang = log_u(r, -12, -3)
            R = ((math.cos(ang), -math.sin(ang), 0.0), (math.sin(ang), math.cos(ang), 0.0))
            tri = tuple((R[0][0] * p[0] + R[0][1] * p[1], R[1][0] * p[0] + R[1][1] * p[1], h) for p in sl)
            A.append(P.tri(tri))
        else:
            A.append(tuple(P.at(p, (0.0, 0.0, h)) for p in sl))
    B = []
    for _ in range(r.randint(1, 10)):
        c = bary(*sl, r.random() * 0.6, r.random() * 0.4) if r.random() < 0.6 else (r.random(), 0.0, 0.0)
        h = r.choice(lifts) * r.choice((0.5, 1.0, 0.0))
        if r.random() < 0.6:
            B.append(tiny_tri(r, P, c, lift=h))
        else:
            B.append(pointlike(r, P.at(c, (0.0, 0.0, h))))
    if r.random() < 0.3:
        A, B = B, A
    return A, B


def k_tiny_straddle_edge(r, P):
    T = huge_tri(r)
    A = [P.tri(T)]
    if r.random() < 0.3:
        t3, _ = hinge_third(r)
        A.append(P.tri((T[1], T[0], t3)))
    B = []
    for _ in range(r.randint(1, 10)):
        i = r.randint(0, 2)
        p, q = T[i], T[(i + 1) % 3]
        c = lerp(p, q, r.choice((r.random(), 0.5, 0.0, 1.0)))
        eu = unit(sub(q, p))
        en = EZ
        ev = cross(en, eu)
        t = tiny_size(r, P)
        ang = r.choice((0.0, log_u(r, -12, -1), r.uniform(-1.5, 1.5)))
        # tiny triangle crossing the edge line: vertices at both sides, tilted about the edge
        dirv = add(mul(ev, math.cos(ang)), mul(en, math.sin(ang)))
        s = r.uniform(0.1, 0.9)
        pts = [mul(dirv, -s * t), add(mul(eu, t * r.uniform(-1, 1)), mul(dirv, (1 - s) * t)), add(mul(eu, t * r.uniform(-1, 1)), mul(dirv, r.uniform(-1, 1) * t))]
        B.append(tuple(P.at(c, d) for d in pts))
    if r.random() < 0.3:
        A, B = B, A
    return A, B


def k_sliver_on_sliver(r, P):
    sl = sliver_tri(r)
    A = [P.tri(sl)]
    if r.random() < 0.3:
        A.append(P.tri((EX, O3, (sl[2][0], -sl[2][1], 0.0))))
    B = []
    for _ in range(r.randint(1, 8)):
        c = (r.random(), 0.0, 0.0) if r.random() < 0.5 else bary(*sl, r.random() * 0.5, r.random() * 0.5)
        t = tiny_size(r, P)
        asp = log_u(r, -12, -3)
        ang = r.choice((0.0, log_u(r, -12, -1), r.uniform(0, math.pi)))
        u = (math.cos(ang), math.sin(ang), 0.0)
        tilt = r.choice((0.0, 0.0, log_u(r, -12, -1), math.pi / 2))
        v = add(mul(cross(EZ, u), math.cos(tilt)), mul(EZ, math.sin(tilt)))
        lift = r.choice((0.0, tiny_lift(r, P)))
        s0 = r.uniform(-1, 0)
        pts = [add(mul(u, s0 * t), mul(EZ, lift)), add(mul(u, (s0 + 1) * t), mul(EZ, lift)), add(add(mul(u, r.uniform(s0, s0 + 1) * t), mul(v, asp * t)), mul(EZ, lift))]
        B.append(tuple(P.at(c, d) for d in pts))
    if r.random() < 0.4:
        A, B = B, A
    return A, B


def k_ulp_vs_ulp(r, P):
    tris = [huge_tri(r)]
    if r.random() < 0.3:
        tris.append(sliver_tri(r))
    A = [P.tri(t) for t in tris] if r.random() < 0.6 else []
    B = [P.tri(tris[0])] if r.random() < 0.4 else []
    anchors = []
    for _ in range(r.randint(1, 4)):
        c, _ = where_on_tri(r, r.choice(tris))
        anchors.append(P.pt(c))
    k = ulp_k(r)
    for _ in range(r.randint(1, 12)):
        A.append(pointlike(r, r.choice(anchors), k))
    for _ in range(r.randint(1, 12)):
        B.append(pointlike(r, r.choice(anchors), k if r.random() < 0.7 else ulp_k(r)))
    return A, B


def k_sliver_tinydiff_far(r, P):
    mr = P.min_rel()
    sl = sliver_tri(r, w=max(sliver_thin(r), mr * 10))
    A = [P.tri(sl)]
    if r.random() < 0.5:
        A.append(P.tri((EX, O3, (r.uniform(0, 1), -r.uniform(0.2, 1.0), 0.0))))
    B = list(A)
    for _ in range(r.randint(1, 8)):
        c = (r.random(), 0.0, 0.0) if r.random() < 0.5 else bary(*sl, r.random() * 0.5, r.random() * 0.5)
        t = tiny_size(r, P)
        lift = tiny_lift(r, P)
        sh = tiny_shape2(r, t)
        dl = max(mr, t * log_u(r, -4, 0)) * r.choice((1, -1))
        A.append(tuple(P.at(c, (x, y, lift)) for x, y in sh))
        if r.random() < 0.85:
            if r.random() < 0.5:
                B.append(tuple(P.at(c, (x, y, lift + dl)) for x, y in sh))
            else:
                B.append(tuple(P.at(c, (x + dl, y, lift)) for x, y in sh))
    return A, B


def k_cluster_coinc_far(r, P):
    mr = P.min_rel()
    T = huge_tri(r)
    A = [P.tri(T)]
    if r.random() < 0.4:
        t3, _ = hinge_third(r)
        A.append(P.tri((T[1], T[0], t3)))
    B = list(A)
    anchor, _ = where_on_tri(r, T)
    t = tiny_size(r, P)
    n = r.randint(2, 10)
    lift = tiny_lift(r, P)
    shapes = [tiny_shape2(r, t) for _ in range(n)]
    ang = max(mr / t, log_u(r, -8, -1))
    dl = max(mr, t * log_u(r, -4, 0))
    mode = r.choice(('rot', 'lift', 'both'))
    ca, sa = math.cos(ang), math.sin(ang)
    for sh in shapes:
        A.append(tuple(P.at(anchor, (x, y, lift)) for x, y in sh))
        if mode in ('rot', 'both'):
            B.append(tuple(P.at(anchor, (x * ca - y * sa, x * sa + y * ca, lift + (dl if mode == 'both' else 0.0))) for x, y in sh))
        else:
            B.append(tuple(P.at(anchor, (x, y, lift + dl)) for x, y in sh))
    return A, B


def k_fin_coinc_far(r, P):
    mr = P.min_rel()
    tris = huge_square(r) if r.random() < 0.5 else [huge_tri(r)]
    A = [P.tri(t) for t in tris]
    B = list(A)
    for _ in range(r.randint(1, 6)):
        T = r.choice(tris)
        anchor, _ = where_on_tri(r, T)
        fu, fv, fn = frame_of(T)
        ang = r.uniform(0, 2 * math.pi)
        u = add(mul(fu, math.cos(ang)), mul(fv, math.sin(ang)))
        fr = (u, cross(fn, u), fn)
        t = tiny_size(r, P)
        h = t * r.uniform(0.2, 2.0)
        off = 0.0 if r.random() < 0.5 else log_u(r, -6, -2)
        hang = r.random() < 0.2
        mode_h = r.random() < 0.5
        st = r.getstate()
        A += fin_tris(r, P, anchor, fr, t, off, hang, h=h)
        r.setstate(st)
        if mode_h:
            B += fin_tris(r, P, anchor, fr, t, off, hang, h=h + max(mr, h * log_u(r, -4, -1)))
        else:
            B += fin_tris(r, P, anchor, fr, t, off + max(mr / t, log_u(r, -8, -2)), hang, h=h)
    return A, B


KINDS = [
    ('sliver_tiny_on_edge', k_sliver_tiny_on_edge),
    ('zeroarea_huge_tiny', k_zeroarea_huge_tiny),
    ('shared_edge_tiny', k_shared_edge_tiny),
    ('shared_vertex_tiny', k_shared_vertex_tiny),
    ('cluster_vertex', k_cluster_vertex),
    ('cluster_midpoint', k_cluster_midpoint),
    ('cluster_interior', k_cluster_interior),
    ('sliver_cross_tiny', k_sliver_cross_tiny),
    ('pointlike_huge', k_pointlike_huge),
    ('pointlike_tiny_mesh', k_pointlike_tiny_mesh),
    ('tinydiff_coinc', k_tinydiff_coinc),
    ('tinydiff_coinc_far', k_tinydiff_coinc_far),
    ('tiny_fins', k_tiny_fins),
    ('dup_ulp_huge_tiny', k_dup_ulp_huge_tiny),
    ('dup_ulp_huge_tiny_far', k_dup_ulp_huge_tiny_far),
    ('sliver_fan_tiny', k_sliver_fan_tiny),
    ('tiny_tilted_grid', k_tiny_tilted_grid),
    ('tiny_coplanar_retri', k_tiny_coplanar_retri),
    ('zeroarea_cross_tiny', k_zeroarea_cross_tiny),
    ('pointlike_ulp_cloud', k_pointlike_ulp_cloud),
    ('hinge_crease_tiny', k_hinge_crease_tiny),
    ('dup_layers_tiny', k_dup_layers_tiny),
    ('huge_vs_tiny_only', k_huge_vs_tiny_only),
    ('nested_three_scales', k_nested_three_scales),
    ('perp_corner_tiny', k_perp_corner_tiny),
    ('sliver_stack_tiny', k_sliver_stack_tiny),
    ('tiny_straddle_edge', k_tiny_straddle_edge),
    ('sliver_on_sliver', k_sliver_on_sliver),
    ('ulp_vs_ulp', k_ulp_vs_ulp),
    ('sliver_tinydiff_far', k_sliver_tinydiff_far),
    ('cluster_coinc_far', k_cluster_coinc_far),
    ('fin_coinc_far', k_fin_coinc_far),
]


# ----------------------------------------------------------------------------- output


def finite_tri(t):
    return all(math.isfinite(c) for p in t for c in p)


def cap(r, tris):
    tris = [t for t in tris if finite_tri(t)]
    if len(tris) > MAXT:
        keep = tris[:4]
        rest = tris[4:]
        r.shuffle(rest)
        tris = keep + rest[:MAXT - 4]
    return tris


def write_obj(path, tris):
    idx = {}
    vs = []
    fs = []
    for t in tris:
        f = []
        for p in t:
            key = tuple(float(c) + 0.0 for c in p)
            if key not in idx:
                idx[key] = len(vs) + 1
                vs.append(key)
            f.append(idx[key])
        fs.append(f)
    with open(path, 'w') as fh:
        for v in vs:
            fh.write('v %.17g %.17g %.17g\n' % v)
        for f in fs:
            fh.write('f %d %d %d\n' % tuple(f))


def make_pair(seed):
    name, fn = KINDS[seed % len(KINDS)]
    r = random.Random(seed)
    far = name.endswith('_far')
    P = make_far_place(r) if far else make_place(r)
    A, B = fn(r, P)
    if not far and r.random() < 0.3:
        A, B = B, A
    A = cap(r, A)
    B = cap(r, B)
    if not A:
        A = [P.tri(huge_tri(r))]
    if not B:
        B = [P.tri(huge_tri(r))]
    return name, A, B


def main(argv):
    if len(argv) != 4:
        sys.stderr.write(__doc__.split('\n\n')[2] + '\n')
        return 2
    out, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for s in range(lo, hi):
        name, A, B = make_pair(s)
        base = os.path.join(out, '%06d_%s' % (s, name))
        write_obj(base + '_a.obj', A)
        write_obj(base + '_b.obj', B)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
