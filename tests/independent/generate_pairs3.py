#!/usr/bin/env python3
"""A third independent random generator of degenerate triangle-mesh pairs (issue 8).

Written blind, by an author who did not read the project's other generators
(tests/degenerate_pairs.h, tests/independent/check_pairs.cpp,
tests/independent/generate_pairs.py), so that its blind spots differ from theirs.

usage: python3 tests/independent/generate_pairs3.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/<s>_<kind>_a.obj and OUTDIR/<s>_<kind>_b.obj for s in [FROM, TO)
(kind = KINDS[s % 28]); `hlens_check_pairs --pairs OUTDIR` checks them (names
ending in _far get the certified interval's width check). Python 3 standard
library only; deterministic per seed. Its 28 kinds include, beyond the other
generators': a tiny mesh in the plane of a large triangle, on its edge
(mixed_scale: 1e-12 to 1e-4 of its size), stacked coplanar layers an ulp apart,
grids at coordinates 1e6 + k 1e-3, needle fans, dyadic and snapped soups, and
near-coincident copies re-triangulated, jittered or rotated by 1e-13 to 1e-5 rad
far from the origin.
"""
import math
import os
import random
import sys


# ----------------------------------------------------------------- vectors
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


def logu(r, lo, hi):
    """10**uniform(lo, hi)"""
    return 10.0 ** r.uniform(lo, hi)


def rand_unit(r):
    while True:
        v = (r.gauss(0, 1), r.gauss(0, 1), r.gauss(0, 1))
        n = norm(v)
        if n > 1e-3:
            return mul(v, 1.0 / n)


def rot_axis(axis, ang):
    """rotation matrix about unit axis"""
    x, y, z = unit(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def rand_rot(r):
    q = [r.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(t * t for t in q))
    w, x, y, z = [t / n for t in q]
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def matv(M, p):
    return (dot(M[0], p), dot(M[1], p), dot(M[2], p))


def rotate_about(p, origin, M):
    return add(origin, matv(M, sub(p, origin)))


# ------------------------------------------------------------------- meshes
class Mesh:
    def __init__(self):
        self.V = []
        self.F = []

    def v(self, p):
        self.V.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.V) - 1

    def tri(self, a, b, c):
        """add triangle with fresh vertices"""
        i = self.v(a)
        j = self.v(b)
        k = self.v(c)
        self.F.append((i, j, k))

    def f(self, i, j, k):
        self.F.append((i, j, k))

    def extend(self, other):
        off = len(self.V)
        self.V.extend(other.V)
        self.F.extend([(i + off, j + off, k + off) for (i, j, k) in other.F])
        return self

    def copy(self):
        m = Mesh()
        m.V = list(self.V)
        m.F = list(self.F)
        return m

    def map(self, fn):
        m = Mesh()
        m.V = [tuple(float(c) for c in fn(p)) for p in self.V]
        m.F = list(self.F)
        return m

    def compact(self):
        """drop unreferenced vertices (they have unclear semantics)"""
        used = sorted(set(i for f in self.F for i in f))
        remap = {o: n for n, o in enumerate(used)}
        m = Mesh()
        m.V = [self.V[i] for i in used]
        m.F = [(remap[a], remap[b], remap[c]) for (a, b, c) in self.F]
        return m

    def tris(self):
        return [(self.V[a], self.V[b], self.V[c]) for (a, b, c) in self.F]

    def bbox(self):
        xs = [p[0] for p in self.V]
        ys = [p[1] for p in self.V]
        zs = [p[2] for p in self.V]
        return (min(xs), min(ys), min(zs)), (max(xs), max(ys), max(zs))


def mesh_from_tris(tris):
    m = Mesh()
    for t in tris:
        m.tri(*t)
    return m


def grid(r, nx, ny, x0=0.0, y0=0.0, w=1.0, h=1.0, diag=None, zf=None, xs=None, ys=None):
    """nx*ny cell grid in plane z=zf(x,y) (default 0) ; 2*nx*ny triangles"""
    m = Mesh()
    if xs is None:
        xs = [x0 + w * i / nx for i in range(nx + 1)]
    if ys is None:
        ys = [y0 + h * j / ny for j in range(ny + 1)]
    idx = {}
    for i, x in enumerate(xs):
        for j, y in enumerate(ys):
            z = zf(x, y) if zf else 0.0
            idx[i, j] = m.v((x, y, z))
    mode = diag or r.choice(["same", "alt", "rand", "other"])
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            a, b, c, d = idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]
            if mode == "same":
                flip = False
            elif mode == "other":
                flip = True
            elif mode == "alt":
                flip = (i + j) % 2 == 1
            else:
                flip = r.random() < 0.5
            if not flip:
                m.f(a, b, c)
                m.f(a, c, d)
            else:
                m.f(a, b, d)
                m.f(b, c, d)
    return m


def rand_triangulate(r, n):
    """random triangulation of convex polygon 0..n-1 -> list of index triples"""
    out = []
    stack = [list(range(n))]
    while stack:
        poly = stack.pop()
        if len(poly) < 3:
            continue
        if len(poly) == 3:
            out.append(tuple(poly))
            continue
        k = len(poly)
        # random diagonal or ear
        i = r.randrange(k)
        j = (i + r.randrange(2, k - 1)) % k
        if i > j:
            i, j = j, i
        stack.append(poly[i:j + 1])
        stack.append(poly[j:] + poly[:i + 1])
    return out


def convex_polygon(r, n, cx=0.0, cy=0.0, rad=1.0, regular=False):
    if regular:
        a0 = r.uniform(0, 2 * math.pi)
        angs = [a0 + 2 * math.pi * i / n for i in range(n)]
    else:
        angs = sorted(r.uniform(0, 2 * math.pi) for _ in range(n))
    return [(cx + rad * math.cos(a), cy + rad * math.sin(a), 0.0) for a in angs]


def polygon_mesh(r, pts, mode=None):
    m = Mesh()
    ids = [m.v(p) for p in pts]
    n = len(pts)
    mode = mode or r.choice(["fan", "rand", "rand", "steiner", "strip"])
    if mode == "fan":
        k = r.randrange(n)
        for t in range(1, n - 1):
            m.f(ids[k], ids[(k + t) % n], ids[(k + t + 1) % n])
    elif mode == "steiner":
        c = (sum(p[0] for p in pts) / n, sum(p[1] for p in pts) / n, sum(p[2] for p in pts) / n)
        ci = m.v(c)
        for t in range(n):
            m.f(ci, ids[t], ids[(t + 1) % n])
    elif mode == "strip":
        lo, hi = 0, n - 1
        left = True
        while hi - lo >= 2:
            if left:
                m.f(ids[lo], ids[lo + 1], ids[hi])
                lo += 1
            else:
                m.f(ids[lo], ids[hi - 1], ids[hi])
                hi -= 1
            left = not left
    else:
        for (a, b, c) in rand_triangulate(r, n):
            m.f(ids[a], ids[b], ids[c])
    return m


def flip_some(r, m, p=0.3):
    m = m.copy()
    m.F = [(f[0], f[2], f[1]) if r.random() < p else f for f in m.F]
    return m


def shuffle_mesh(r, m):
    m = m.copy()
    perm = list(range(len(m.V)))
    r.shuffle(perm)
    inv = [0] * len(perm)
    for new, old in enumerate(perm):
        inv[old] = new
    m.V = [m.V[o] for o in perm]
    F = [(inv[a], inv[b], inv[c]) for (a, b, c) in m.F]
    F = [f[s:] + f[:s] for f, s in ((f, r.randrange(3)) for f in F)]
    r.shuffle(F)
    m.F = F
    return m


def closed_shape(r, which=None):
    which = which or r.choice(["tet", "cube", "oct", "prism", "ico"])
    m = Mesh()
    if which == "tet":
        P = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
        F = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
    elif which == "cube":
        P = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
        F = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
             (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    elif which == "oct":
        P = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
        F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    elif which == "prism":
        n = r.randint(3, 8)
        P = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), z) for z in (0, 1) for i in range(n)]
        F = []
        for i in range(n):
            j = (i + 1) % n
            F += [(i, j, n + j), (i, n + j, n + i)]
        for i in range(1, n - 1):
            F += [(0, i + 1, i), (n, n + i, n + i + 1)]
    else:
        t = (1 + math.sqrt(5)) / 2
        P = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
        F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for p in P:
        m.v(p)
    m.F = list(F)
    return m


def rand_surface(r, size=1.0):
    """some small ordinary surface"""
    c = r.randrange(5)
    if c == 0:
        return grid(r, r.randint(1, 4), r.randint(1, 4), w=size, h=size)
    if c == 1:
        a, b = r.uniform(-1, 1), r.uniform(-1, 1)
        return grid(r, r.randint(2, 4), r.randint(2, 4), w=size, h=size,
                    zf=lambda x, y: size * 0.3 * math.sin(3 * a * x / size + 2 * b * y / size))
    if c == 2:
        return polygon_mesh(r, convex_polygon(r, r.randint(3, 9), rad=size))
    if c == 3:
        return closed_shape(r).map(lambda p: mul(p, size))
    m = Mesh()
    for _ in range(r.randint(1, 6)):
        m.tri(*[mul((r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)), size) for _ in range(3)])
    return m


# --------------------------------------------------------------- transforms
def perm_transform(r):
    perm = [0, 1, 2]
    r.shuffle(perm)
    sg = [r.choice((1.0, -1.0)) for _ in range(3)]
    return lambda p: (sg[0] * p[perm[0]], sg[1] * p[perm[1]], sg[2] * p[perm[2]])


def random_transform(r, exact=False):
    """returns (name, fn)"""
    if exact:
        c = r.randrange(4)
        P = perm_transform(r)
        if c == 0:
            return "id", lambda p: p
        if c == 1:
            return "perm", P
        s = 2.0 ** r.randint(-20, 20)
        t = tuple(r.randint(-2 ** 20, 2 ** 20) * 2.0 ** r.randint(-10, 10) for _ in range(3))
        if c == 2:
            return "pow2", lambda p: mul(P(p), s)
        return "pow2t", lambda p: add(mul(P(p), s), t)
    c = r.randrange(7)
    if c == 0:
        return "id", lambda p: p
    if c == 1:
        return "perm", perm_transform(r)
    s = logu(r, -6, 6)
    if c == 2:
        return "scale", lambda p: mul(p, s)
    R = rand_rot(r)
    if c == 3:
        return "rot", lambda p: matv(R, p)
    d = rand_unit(r)
    far = logu(r, 0, 8)
    t = mul(d, far * s)
    if c == 4:
        return "translate", lambda p: add(p, mul(d, far))
    if c == 5:
        P = perm_transform(r)
        return "permst", lambda p: add(mul(P(p), s), t)
    return "sim", lambda p: add(mul(matv(R, p), s), t)


# ----------------------------------------------------------------- kinds
def k_coplanar_overlap(r):
    c = r.randrange(6)
    if c == 0:
        # same polygon, two different triangulations, shared vertices
        pts = convex_polygon(r, r.randint(4, 14), regular=r.random() < 0.4)
        return polygon_mesh(r, pts), polygon_mesh(r, pts)
    if c == 1:
        # overlapping distinct polygons, unshared vertices
        pa = convex_polygon(r, r.randint(3, 12), rad=1.0)
        off = logu(r, -12, 0)
        ang = r.uniform(0, 2 * math.pi)
        pb = convex_polygon(r, r.randint(3, 12), cx=off * math.cos(ang), cy=off * math.sin(ang),
                            rad=r.choice([1.0, logu(r, -3, 1)]))
        return polygon_mesh(r, pa), polygon_mesh(r, pb)
    if c == 2:
        # grids of different resolution over overlapping rectangles
        A = grid(r, r.randint(1, 5), r.randint(1, 5))
        dx, dy = r.choice([0.0, logu(r, -14, 0)]), r.choice([0.0, logu(r, -14, 0)])
        B = grid(r, r.randint(1, 5), r.randint(1, 5), x0=dx, y0=dy, w=r.choice([1.0, r.uniform(0.2, 2)]),
                 h=r.choice([1.0, r.uniform(0.2, 2)]))
        return A, B
    if c == 3:
        # same grid vertices, different diagonals
        nx, ny = r.randint(1, 5), r.randint(1, 5)
        return grid(r, nx, ny, diag="same"), grid(r, nx, ny, diag=r.choice(["other", "alt", "rand"]))
    if c == 4:
        # polygon with some shared vertices, some new ones on the boundary
        n = r.randint(4, 10)
        pts = convex_polygon(r, n)
        A = polygon_mesh(r, pts)
        pb = []
        for i in range(n):
            pb.append(pts[i])
            if r.random() < 0.4:
                pb.append(lerp(pts[i], pts[(i + 1) % n], r.choice([0.5, r.random()])))
        if r.random() < 0.5:
            pb = [p for p in pb if r.random() < 0.8]
            if len(pb) < 3:
                pb = pts
        return A, polygon_mesh(r, pb)
    # one triangle containing a triangulated polygon strictly or touching
    big = Mesh()
    big.tri((-2, -2, 0), (3, -2, 0), (-2, 3, 0))
    small = polygon_mesh(r, convex_polygon(r, r.randint(3, 9), rad=r.choice([1.0, logu(r, -8, 0)])))
    return (big, small) if r.random() < 0.5 else (small, big)


def k_tilted_grid(r):
    nx, ny = r.randint(1, 5), r.randint(1, 5)
    A = grid(r, nx, ny)
    tilt = logu(r, -12, -2) * r.choice([1, -1])
    lift = r.choice([0.0, 0.0, logu(r, -15, -3), -logu(r, -15, -3)])
    mx, my = r.randint(1, 5), r.randint(1, 5)
    same = r.random() < 0.3
    B = grid(r, nx, ny) if same else grid(r, mx, my, x0=r.choice([0.0, r.uniform(-0.5, 0.5)]),
                                             y0=r.choice([0.0, r.uniform(-0.5, 0.5)]))
    axis = r.choice([(1, 0, 0), (0, 1, 0), (r.uniform(-1, 1), r.uniform(-1, 1), 0)])
    pivot = r.choice([(0, 0, 0), (0.5, 0.5, 0), (r.uniform(-1, 2), r.uniform(-1, 2), 0)])
    M = rot_axis(axis, tilt)
    B = B.map(lambda p: add(rotate_about(p, pivot, M), (0, 0, lift)))
    return A, B


def sliver_tri(r, ratio, kind=None):
    kind = kind or r.choice(["flat", "obtuse", "needle", "cap"])
    L = 1.0
    if kind == "flat":  # apex close to base, inside base span
        return ((0, 0, 0), (L, 0, 0), (r.uniform(0, L), ratio * L, 0))
    if kind == "obtuse":  # apex beyond the base span
        return ((0, 0, 0), (L, 0, 0), (r.choice([-1, 1]) * r.uniform(1, 3) * L, ratio * L, 0))
    if kind == "needle":  # two vertices almost equal
        return ((0, 0, 0), (L, 0, 0), (L, ratio * L, 0))
    # cap: one very short edge with large angle
    return ((0, 0, 0), (L, 0, 0), (L * (1 + ratio), ratio * L * 0.5, 0))


def place(r, tri, M=None, t=(0, 0, 0)):
    M = M or rand_rot(r)
    return tuple(add(matv(M, p), t) for p in tri)


def k_sliver(r):
    A = Mesh()
    B = Mesh()
    n = r.randint(1, 12)
    c = r.randrange(5)
    for _ in range(n):
        ratio = logu(r, -14, -3)
        s = sliver_tri(r, ratio)
        if c == 0:  # coplanar random orientation in xy plane
            M = rot_axis((0, 0, 1), r.uniform(0, 2 * math.pi))
            A.tri(*place(r, s, M, (r.uniform(-1, 1), r.uniform(-1, 1), 0)))
        elif c == 1:  # random 3d
            A.tri(*place(r, s, None, (r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1))))
        elif c == 2:  # slivers standing on the plane
            M = rot_axis((1, 0, 0), math.pi / 2)
            M2 = rot_axis((0, 0, 1), r.uniform(0, 2 * math.pi))
            A.tri(*[add(matv(M2, matv(M, p)), (r.uniform(-1, 1), r.uniform(-1, 1), 0)) for p in s])
        elif c == 3:  # slivers all sharing their long edge
            A.tri(*place(r, s, rot_axis((1, 0, 0), r.uniform(0, 2 * math.pi))))
        else:  # slivers along the diagonal of a unit square
            d = ((0, 0, 0), (1, 1, 0), lerp((0, 0, 0), (1, 1, 0), r.random()))
            off = mul((1, -1, 0), ratio * r.choice([1, -1]))
            A.tri(d[0], d[1], add(d[2], off))
    against = r.randrange(4)
    if against == 0:
        B = grid(r, r.randint(1, 3), r.randint(1, 3), x0=-1.5, y0=-1.5, w=3, h=3)
    elif against == 1:
        for _ in range(r.randint(1, 10)):
            s = sliver_tri(r, logu(r, -14, -3))
            if c in (0, 4):
                M = rot_axis((0, 0, 1), r.uniform(0, 2 * math.pi))
                B.tri(*place(r, s, M, (r.uniform(-1, 1), r.uniform(-1, 1), r.choice([0.0, logu(r, -14, -2)]))))
            else:
                B.tri(*place(r, s, None, (r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1))))
    elif against == 2:
        B = rand_surface(r)
    else:
        # the same slivers, perturbed
        eps = logu(r, -15, -5)
        B = A.map(lambda p: (p[0] + eps * r.uniform(-1, 1), p[1] + eps * r.uniform(-1, 1), p[2]))
        if r.random() < 0.5:
            B = shuffle_mesh(r, B)
    return A, B


def k_perpendicular(r):
    A = r.choice([lambda: grid(r, r.randint(1, 4), r.randint(1, 4), x0=-1, y0=-1, w=2, h=2),
                  lambda: mesh_from_tris([((-1, -1, 0), (2, -1, 0), (-1, 2, 0))])])()
    B = Mesh()
    for _ in range(r.randint(1, 8)):
        mode = r.choice(["edge", "vertex", "pierce", "float", "sunk", "gridedge"])
        tilt = r.choice([0.0, 0.0, logu(r, -12, -3) * r.choice([1, -1])])
        h = logu(r, -2, 0.3)
        x0, y0 = r.uniform(-1, 1), r.uniform(-1, 1)
        if mode == "gridedge":
            x0 = r.choice([-1.0, 0.0, 1.0, -0.5, 0.5])
        L = logu(r, -3, 0)
        dir_ = r.choice([(1, 0, 0), (0, 1, 0), unit((1, 1, 0)), unit((r.uniform(-1, 1), r.uniform(-1, 1), 0))])
        p0 = (x0, y0, 0.0)
        p1 = add(p0, mul(dir_, L))
        top = add(lerp(p0, p1, r.uniform(-0.5, 1.5)), (0, 0, h))
        if mode == "vertex":
            p1 = add(p0, add(mul(dir_, L), (0, 0, h * 0.5)))
        elif mode == "pierce":
            dz = -r.uniform(0.01, 1) * h
            p0 = add(p0, (0, 0, dz))
            p1 = add(p1, (0, 0, dz))
        elif mode == "float":
            dz = logu(r, -14, -2)
            p0 = add(p0, (0, 0, dz))
            p1 = add(p1, (0, 0, dz))
            top = add(top, (0, 0, dz))
        elif mode == "sunk":
            top = add(top, (0, 0, -2 * h))
        if tilt:
            M = rot_axis(dir_, tilt)
            top = rotate_about(top, p0, M)
        B.tri(p0, p1, top)
    return A, B


def k_dihedral(r):
    """shared edge / shared vertex pairs with dihedral 0, pi, pi/2 and near."""
    base = r.choice([0.0, math.pi, math.pi / 2])
    exact = r.random() < 0.4
    eps = 0.0 if exact else logu(r, -14, -2) * r.choice([1, -1])
    th = base + eps
    if exact:
        cs, sn = {0.0: (1.0, 0.0), math.pi: (-1.0, 0.0), math.pi / 2: (0.0, 1.0)}[base]
    else:
        cs, sn = math.cos(th), math.sin(th)
    shared = r.choice(["edge", "edge", "vertex"])
    A = Mesh()
    B = Mesh()
    n = r.randint(1, 6)
    for k in range(n):
        a = r.uniform(-1, 2)
        ha = r.choice([1.0, logu(r, -6, 1)])
        b = r.uniform(-1, 2) if r.random() < 0.7 else a
        hb = r.choice([ha, 1.0, logu(r, -6, 1)])
        p, q = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)
        if shared == "vertex":
            q2 = (r.uniform(0.2, 2), r.uniform(-0.5, 0.5) * (1 if not exact else 0), 0.0)
        else:
            q2 = q
        ca = (a, ha, 0.0)
        cb = (b, hb * cs, hb * sn)
        # rotate each sub-pair around x to make fans
        rot = rot_axis((1, 0, 0), 2 * math.pi * k / n) if n > 1 and not exact else None
        if rot:
            ca, cb = matv(rot, ca), matv(rot, cb)
            q2 = matv(rot, q2)
        A.tri(p, q, ca)
        if shared == "vertex":
            B.tri(p, (q2[0], q2[1] * cs - q2[2] * sn, q2[1] * sn + q2[2] * cs), cb)
        else:
            B.tri(p, q, cb)
    if r.random() < 0.5:
        A, B = B, A
    if r.random() < 0.3:
        A = flip_some(r, A, 0.5)
    return A, B


def k_zero_area(r):
    A = rand_surface(r)
    dz0 = r.choice([0.0, logu(r, -10, -1)])
    B = rand_surface(r) if r.random() < 0.5 else A.map(lambda p: add(p, (0, 0, dz0)))
    lo, hi = A.bbox()

    def deg(m, src):
        c = r.randrange(6)
        if src.F and r.random() < 0.6:
            t = src.tris()[r.randrange(len(src.F))]
            p = t[r.randrange(3)]
            q = t[(r.randrange(3))]
            bc = [r.random() for _ in range(3)]
            sbc = sum(bc)
            inside = add(add(mul(t[0], bc[0] / sbc), mul(t[1], bc[1] / sbc)), mul(t[2], bc[2] / sbc))
        else:
            p = tuple(r.uniform(lo[i] - 1, hi[i] + 1) for i in range(3))
            q = tuple(r.uniform(lo[i] - 1, hi[i] + 1) for i in range(3))
            inside = p
        if c == 0:  # collinear
            m.tri(p, q, lerp(p, q, r.choice([0.5, r.uniform(-1, 2)])))
        elif c == 1:  # repeated vertex
            m.tri(p, p, q)
        elif c == 2:  # single point
            m.tri(inside, inside, inside)
        elif c == 3:  # point far away
            far = tuple(x * logu(r, 0, 3) for x in rand_unit(r))
            m.tri(far, far, far)
        elif c == 4:  # repeated index
            i = m.v(inside)
            j = m.v(q)
            m.f(i, i, j)
        else:  # all indices equal
            i = m.v(inside)
            m.f(i, i, i)

    for m, src in ((A, B), (B, A)):
        for _ in range(r.randint(0, 6)):
            deg(m, src)
    # sometimes one mesh consists only of degenerate triangles
    if r.random() < 0.15:
        D = Mesh()
        for _ in range(r.randint(1, 4)):
            deg(D, A)
        B = D
    if r.random() < 0.5:
        A, B = B, A
    return shuffle_mesh(r, A), shuffle_mesh(r, B)


def k_dup_faces(r):
    A = rand_surface(r)

    def dupify(m):
        m = m.copy()
        F = list(m.F)
        for f in list(m.F):
            if r.random() < 0.4:
                c = r.randrange(4)
                if c == 0:
                    F.append(f)
                elif c == 1:
                    F.append((f[1], f[2], f[0]))
                elif c == 2:
                    F.append((f[0], f[2], f[1]))
                else:  # duplicate with duplicated vertices
                    i, j, k = m.v(m.V[f[0]]), m.v(m.V[f[1]]), m.v(m.V[f[2]])
                    F.append(r.choice([(i, j, k), (k, j, i)]))
        # some faces replaced to reference duplicated vertices
        for t in range(len(F)):
            if r.random() < 0.2:
                a, b, c = F[t]
                F[t] = (m.v(m.V[a]), b, c)
        m.F = F
        return m

    c = r.randrange(4)
    if c == 0:
        B = A.copy()
    elif c == 1:
        B = dupify(A)
    elif c == 2:
        eps = logu(r, -14, -3)
        B = dupify(A).map(lambda p: add(p, mul(rand_unit(r), eps)))
    else:
        B = rand_surface(r)
    A = dupify(A)
    if r.random() < 0.5:
        A = shuffle_mesh(r, A)
    return A, B


def k_near_coinc(r, how):
    """surface and copy offset by 1e-13..1e-4 of its size; placed far away."""
    size = 1.0
    c = r.randrange(4)
    nx, ny = r.randint(1, 5), r.randint(1, 5)
    a = r.uniform(0.5, 3)
    zf = (lambda x, y: 0.2 * math.sin(a * x) * math.cos(a * y)) if c == 1 else None
    regrid = None
    if c in (0, 1):
        if c == 1:
            nx, ny = max(nx, 2), max(ny, 2)
        A = grid(r, nx, ny, diag="same", zf=zf)
        regrid = lambda: grid(r, nx, ny, diag=r.choice(["other", "alt", "rand"]), zf=zf)
        nrm = lambda p: (0.0, 0.0, 1.0)
        inplane = unit((r.uniform(-1, 1), r.uniform(-1, 1), 0))
    elif c == 2:
        pts = convex_polygon(r, r.randint(3, 10))
        A = polygon_mesh(r, pts)
        regrid = lambda: polygon_mesh(r, pts)
        nrm = lambda p: (0.0, 0.0, 1.0)
        inplane = unit((r.uniform(-1, 1), r.uniform(-1, 1), 0))
    else:
        A = closed_shape(r)
        nrm = lambda p: unit(p) if norm(p) > 0 else (0, 0, 1)
        inplane = rand_unit(r)
    lo, hi = A.bbox()
    size = norm(sub(hi, lo))
    d = logu(r, -13, -4) * size
    if how == "inplane":
        off = mul(inplane, d)
        B = A.map(lambda p: add(p, off))
    elif how == "normal":
        if c == 3:
            B = A.map(lambda p: mul(p, 1 + d / size * r.choice([1, -1])))
        else:
            B = A.map(lambda p: add(p, (0, 0, d)))
    elif how == "both":
        off = add(mul(inplane, d * r.uniform(0.1, 1)), mul(rand_unit(r), d))
        B = A.map(lambda p: add(p, off))
    elif how == "retri":
        # same surface re-triangulated + offset
        off = mul(rand_unit(r), d)
        B = regrid() if regrid else shuffle_mesh(r, A)
        B = B.map(lambda p: add(p, off))
    elif how == "rot":
        M = rot_axis(rand_unit(r), d / size)
        B = A.map(lambda p: matv(M, p))
    else:  # jitter: each vertex independently
        B = A.map(lambda p: add(p, mul(rand_unit(r), d * r.random())))
    if r.random() < 0.3:
        A, B = B, A
    # place far away
    R = rand_rot(r) if r.random() < 0.5 else None
    scale = logu(r, -6, 6) if r.random() < 0.5 else 1.0
    dist = logu(r, 2, 8) * size * scale
    dirv = r.choice([rand_unit(r), (1.0, 0.0, 0.0), unit((1, 1, 1))])
    t = mul(dirv, dist)

    def tf(p):
        if R:
            p = matv(R, p)
        return add(mul(p, scale), t)

    return A.map(tf), B.map(tf)


def k_dyadic(r):
    """exact small-integer / dyadic coordinates; many exact coincidences."""
    den = 2 ** r.randint(0, 4)

    def q(x):
        return round(x * den) / den

    A = Mesh()
    B = Mesh()
    c = r.randrange(3)
    if c == 0:
        n = r.randint(1, 4)
        A = grid(r, n, n, w=float(n), h=float(n))
        B = Mesh()
        for _ in range(r.randint(1, 10)):
            B.tri(*[(q(r.uniform(-1, n + 1)), q(r.uniform(-1, n + 1)), q(r.choice([0, 0, r.uniform(-1, 1)])))
                    for _ in range(3)])
    elif c == 1:
        for m in (A, B):
            for _ in range(r.randint(1, 12)):
                m.tri(*[(q(r.uniform(-2, 2)), q(r.uniform(-2, 2)), q(r.uniform(-2, 2))) for _ in range(3)])
    else:
        # integer lattice tets/cubes with midpoint refinements
        A = closed_shape(r, r.choice(["cube", "oct", "tet"]))
        B = Mesh()
        for (a, b, cc) in A.tris():
            if r.random() < 0.6:
                ab, bc, ca = lerp(a, b, 0.5), lerp(b, cc, 0.5), lerp(cc, a, 0.5)
                for t in ((a, ab, ca), (ab, b, bc), (ca, bc, cc), (ab, bc, ca)):
                    if r.random() < 0.85:
                        B.tri(*t)
        if not B.F:
            B = A.copy()
        if r.random() < 0.5:
            sh = tuple(q(r.choice([0, 0, r.uniform(-1, 1)])) for _ in range(3))
            B = B.map(lambda p: add(p, sh))
    return A, B


def k_tjunction(r):
    c = r.randrange(3)
    if c == 0:
        n = r.randint(1, 3)
        k = r.randint(2, 3) if n <= 2 else 2
        return grid(r, n, n), grid(r, n * k, r.choice([n, n * k]))
    if c == 1:
        # non-conforming mesh: big triangle + small triangles using a vertex on its edge
        A = Mesh()
        a, b, cc = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
        A.tri(a, b, cc)
        t = r.choice([0.5, r.random(), 1e-12, 1 - 1e-12])
        m = lerp(a, b, t)
        z = r.choice([0.0, logu(r, -12, -2)])
        A.tri(a, m, (t * 0.5, -r.uniform(0.1, 1), z))
        A.tri(m, b, (0.5 + t * 0.5, -r.uniform(0.1, 1), -z))
        B = r.choice([lambda: grid(r, 2, 2, x0=-0.5, y0=-1, w=2, h=2),
                      lambda: A.map(lambda p: add(p, (0, 0, logu(r, -13, -3)))),
                      lambda: mesh_from_tris([(a, b, (0.5, -1.0, 0.0))])])()
        return A, B
    # B's vertices on A's edges
    A = polygon_mesh(r, convex_polygon(r, r.randint(3, 8)))
    B = Mesh()
    tris = A.tris()
    for _ in range(r.randint(1, 8)):
        t = tris[r.randrange(len(tris))]
        i = r.randrange(3)
        p = lerp(t[i], t[(i + 1) % 3], r.choice([0.5, r.random()]))
        q = lerp(t[(i + 1) % 3], t[(i + 2) % 3], r.choice([0.5, r.random()]))
        top = r.choice([t[(i + 2) % 3], add(lerp(p, q, 0.5), (0, 0, r.choice([0.5, -0.5, logu(r, -12, -1)])))])
        B.tri(p, q, top)
    return A, B


def k_subset(r):
    A = rand_surface(r)
    if len(A.F) < 2:
        A.extend(rand_surface(r))
    keep = [f for f in A.F if r.random() < r.uniform(0.2, 0.9)]
    if not keep:
        keep = [A.F[0]]
    B = A.copy()
    B.F = keep
    B = B.compact()
    if r.random() < 0.3:
        B = shuffle_mesh(r, B)
    if r.random() < 0.3:
        eps = logu(r, -14, -6)
        B = B.map(lambda p: add(p, (eps, 0, 0)))
    if r.random() < 0.5:
        A, B = B, A
    return A, B


def k_touch_point(r):
    A = Mesh()
    B = Mesh()
    c = r.randrange(5)
    gap = r.choice([0.0, 0.0, logu(r, -14, -4)])
    if c == 0:  # vertex-vertex
        A.tri((0, 0, 0), (1, 0, 0), (0, 1, 0))
        d = rand_unit(r)
        d = (d[0], d[1], abs(d[2]) + 0.1)
        e = rand_unit(r)
        B.tri((0, 0, gap), add(mul(d, 1), (0, 0, gap)), add(mul(unit(cross(d, e)), 1), (0, 0, gap)))
        if B.tris()[0][1][2] < 0 or B.tris()[0][2][2] < 0:
            B = Mesh()
            B.tri((0, 0, gap), (-1, -1, 1), (-1, 0.5, 1.5))
    elif c == 1:  # vertex on edge
        A.tri((0, 0, 0), (1, 0, 0), (0, 1, 0))
        t = r.random()
        B.tri((t, -gap, 0), (t, -1, 0.5), (t + 0.3, -1, -0.5))
    elif c == 2:  # vertex on face
        A.tri((0, 0, 0), (1, 0, 0), (0, 1, 0))
        p = (0.25, 0.25, gap)
        B.tri(p, (0.3, 0.2, 1), (0.1, 0.4, 1))
    elif c == 3:  # edge crosses edge at one point (skew)
        A.tri((0, 0, 0), (1, 0, 0), (0.5, 0.0, 1))
        B.tri((0.5, -0.5, gap), (0.5, 0.5, gap), (0.5, 0.0, -1))
    else:  # two coplanar triangles touching at a vertex (bow-tie)
        A.tri((0, 0, 0), (1, 0, 0), (0, 1, 0))
        B.tri((0, 0, 0), (-1, 0, 0), (0, -1, gap))
    if r.random() < 0.5:
        A.extend(grid(r, 1, 1, x0=2, y0=2).map(lambda p: add(p, (0, 0, -0.5))))
    return A, B


def k_hinge_rot(r):
    A = r.choice([lambda: grid(r, r.randint(1, 4), r.randint(1, 4)),
                  lambda: polygon_mesh(r, convex_polygon(r, r.randint(3, 9))),
                  lambda: closed_shape(r)])()
    tris = A.tris()
    t = tris[r.randrange(len(tris))]
    i = r.randrange(3)
    p, q = t[i], t[(i + 1) % 3]
    ang = logu(r, -14, -2) * r.choice([1, -1])
    M = rot_axis(sub(q, p), ang)
    B = A.map(lambda x: rotate_about(x, p, M))
    if r.random() < 0.3:
        B = shuffle_mesh(r, B)
    return A, B


def k_bigcoord_grid(r):
    base = r.choice([1e6, 1e6, 1e3, 1e9, logu(r, 3, 9)])
    step = r.choice([1e-3, 1e-3, logu(r, -6, 0)])
    nx, ny = r.randint(1, 5), r.randint(1, 5)
    xs = [base + k * step for k in range(nx + 1)]
    ys = [base + k * step for k in range(ny + 1)]
    zb = r.choice([0.0, base])
    A = grid(r, nx, ny, xs=xs, ys=ys, zf=lambda x, y: zb)
    c = r.randrange(4)
    if c == 0:  # same points, other triangulation
        B = grid(r, nx, ny, xs=xs, ys=ys, zf=lambda x, y: zb, diag=r.choice(["other", "rand", "alt"]))
    elif c == 1:  # finer grid at k*step/2
        xs2 = [base + k * step / 2 for k in range(2 * nx + 1)]
        B = grid(r, 2 * nx, ny, xs=xs2, ys=ys, zf=lambda x, y: zb)
    elif c == 2:  # lifted by tiny offset
        dz = r.choice([step, step * logu(r, -10, 0)])
        B = grid(r, nx, ny, xs=xs, ys=ys, zf=lambda x, y: zb + dz)
    else:  # shifted by half-step computed in float
        xs2 = [base + (k + 0.5) * step for k in range(nx + 1)]
        slope = logu(r, -12, -3)
        B = grid(r, nx, ny, xs=xs2, ys=ys, zf=lambda x, y: zb + (x - base) * slope)
    return A, B


def k_parallel_edge(r):
    """B has an edge parallel to A's plane (and to an edge of A)."""
    A = r.choice([lambda: mesh_from_tris([((0, 0, 0), (1, 0, 0), (0, 1, 0))]),
                  lambda: grid(r, r.randint(1, 3), r.randint(1, 3))])()
    B = Mesh()
    for _ in range(r.randint(1, 6)):
        h = r.choice([0.0, logu(r, -14, -1), -logu(r, -14, -1)])
        y = r.choice([0.0, 0.5, r.uniform(-0.5, 1.5)])
        x0 = r.uniform(-0.5, 0.5)
        x1 = x0 + r.uniform(0.1, 1.5)
        dz = r.choice([1.0, -1.0, 0.3, logu(r, -6, 0)])
        apex = (r.uniform(0, 1), y + r.uniform(-1, 1), h + dz)
        if r.random() < 0.3:  # edge direction generic but still parallel to the plane
            ang = r.uniform(0, math.pi)
            p0 = (x0, y, h)
            p1 = (x0 + math.cos(ang), y + math.sin(ang), h)
        else:
            p0, p1 = (x0, y, h), (x1, y, h)
        B.tri(p0, p1, apex)
    if r.random() < 0.4:  # or: triangle plane parallel to A's edge along x
        B = Mesh()
        for _ in range(r.randint(1, 4)):
            z = r.choice([0.0, logu(r, -12, 0)])
            B.tri((r.uniform(-1, 0), r.uniform(-1, 1), z + r.uniform(-1, 1)),
                  (r.uniform(1, 2), r.uniform(-1, 1), z + 0.0), (r.uniform(-1, 2), r.uniform(-1, 1), z))
            # a triangle whose plane contains the x direction: make all z affine in y only
            y0, y1 = r.uniform(-1, 1), r.uniform(-1, 1)
            sl = r.choice([0.0, logu(r, -12, 1)])
            B.tri((r.uniform(-1, 0), y0, z + sl * y0), (r.uniform(1, 2), y0, z + sl * y0),
                  (r.uniform(-1, 2), y1, z + sl * y1))
    return A, B


def k_closed(r):
    A = closed_shape(r)
    c = r.randrange(5)
    if c == 0:
        eps = logu(r, -14, -2) * r.choice([1, -1])
        B = A.map(lambda p: mul(p, 1 + eps))
    elif c == 1:  # inverted orientation
        B = A.copy()
        B.F = [(f[0], f[2], f[1]) for f in B.F]
    elif c == 2:  # subdivided copy (midpoint), same surface
        B = Mesh()
        for (a, b, cc) in A.tris():
            ab, bc, ca = lerp(a, b, 0.5), lerp(b, cc, 0.5), lerp(cc, a, 0.5)
            for t in ((a, ab, ca), (ab, b, bc), (ca, bc, cc), (ab, bc, ca)):
                B.tri(*t)
    elif c == 3:  # a different closed shape
        B = closed_shape(r).map(lambda p: mul(p, r.uniform(0.5, 1.5)))
    else:  # open version (one face removed) slightly rotated
        B = A.copy()
        B.F = B.F[1:]
        M = rot_axis(rand_unit(r), logu(r, -14, -3))
        B = B.map(lambda p: matv(M, p))
    return A, B


def k_fold(r):
    """mesh folded onto itself (dihedral pi inside one mesh) vs flat mesh."""
    n = r.randint(1, 4)
    A = grid(r, n, n)
    fx = r.choice([0.5, r.uniform(0.2, 0.8)])
    ang = r.choice([math.pi, math.pi - logu(r, -12, -2), math.pi / 2, logu(r, -12, -2)])
    M = rot_axis((0, 1, 0), ang)

    def fold(p):
        if p[0] > fx:
            return rotate_about(p, (fx, 0, 0), M)
        return p

    xs = sorted(set([i / n for i in range(n + 1)] + [fx]))
    F = grid(r, len(xs) - 1, n, xs=xs, ys=[j / n for j in range(n + 1)]).map(fold)
    if r.random() < 0.5:
        return F, A
    return A, F


def k_needle_fan(r):
    n = r.randint(3, 30)
    c = (0.0, 0.0, 0.0)
    A = Mesh()
    ci = A.v(c)
    da = logu(r, -12, -2)
    a0 = r.uniform(0, 2 * math.pi)
    R = 1.0
    prev = A.v((R * math.cos(a0), R * math.sin(a0), 0))
    for k in range(1, n + 1):
        a = a0 + k * da
        cur = A.v((R * math.cos(a), R * math.sin(a), 0))
        A.f(ci, prev, cur)
        prev = cur
    lz = logu(r, -14, -4)
    B = r.choice([lambda: polygon_mesh(r, convex_polygon(r, r.randint(3, 12), rad=1.0)),
                  lambda: mesh_from_tris([(c, (math.cos(a0), math.sin(a0), 0.0),
                                           (math.cos(a0 + n * da), math.sin(a0 + n * da), 0.0))]),
                  lambda: A.map(lambda p: (p[0], p[1], lz))])()
    return A, B


def k_stacked(r):
    """many parallel layers with tiny spacing vs a single layer."""
    layers = r.randint(2, 8)
    sp = logu(r, -14, -2)
    A = Mesh()
    for k in range(layers):
        A.extend(grid(r, r.randint(1, 2), r.randint(1, 2), zf=lambda x, y, k=k: k * sp))
    zb = r.choice([0.0, layers * sp / 2, -sp, (layers - 1) * sp])
    B = grid(r, r.randint(1, 3), r.randint(1, 3), zf=lambda x, y: zb)
    return A, B


def k_mixed_scale(r):
    big = r.choice([lambda: mesh_from_tris([((-1, -1, 0), (2, -1, 0), (-1, 2, 0))]),
                    lambda: grid(r, r.randint(1, 3), r.randint(1, 3))])()
    s = logu(r, -12, -3)
    small = rand_surface(r, size=s)
    pos = r.choice([(0.3, 0.3, 0.0), (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 0.5, 0.0),
                    (r.uniform(0, 1), r.uniform(0, 1), r.choice([0.0, s, -s, 10 * s]))])
    small = small.map(lambda p: add(p, pos))
    return (big, small) if r.random() < 0.5 else (small, big)


def k_snap_soup(r):
    den = r.choice([1, 2, 4, 8])
    n = r.choice([1, 2])

    def pt():
        return tuple(r.randint(-n * den, n * den) / den for _ in range(3))

    A = Mesh()
    B = Mesh()
    for m in (A, B):
        for _ in range(r.randint(1, 15)):
            m.tri(pt(), pt(), pt())
    if r.random() < 0.3:
        A.extend(B.copy())
    return A, B


def k_crossing_lines(r):
    """B's triangles cross A's plane exactly along A's edges / through vertices."""
    n = r.randint(1, 4)
    A = grid(r, n, n)
    B = Mesh()
    for _ in range(r.randint(1, 8)):
        i, j = r.randint(0, n), r.randint(0, n)
        p = (i / n, j / n, 0.0)
        c = r.randrange(3)
        if c == 0:  # through a grid line
            q = ((i + r.choice([-1, 1])) / n, j / n, 0.0)
            h = r.uniform(0.1, 1)
            B.tri(lerp(p, q, -0.5), lerp(p, q, 1.5), add(lerp(p, q, 0.5), (0, r.uniform(-0.3, 0.3), h)))
            B.tri(lerp(p, q, -0.5), lerp(p, q, 1.5), add(lerp(p, q, 0.5), (0, r.uniform(-0.3, 0.3), -h)))
        elif c == 1:  # vertical fin through a diagonal
            q = ((i + 1) / n, (j + 1) / n, 0.0)
            B.tri(add(p, (0, 0, -0.3)), add(q, (0, 0, -0.3)), add(lerp(p, q, 0.5), (0, 0, 0.7)))
        else:  # apex exactly at a grid vertex, from above/below
            h = r.choice([1.0, -1.0])
            B.tri(p, add(p, (0.3, 0.1, h)), add(p, (-0.1, 0.3, h)))
    return A, B


def k_rot_tiny_far(r):
    A = r.choice([lambda: grid(r, r.randint(1, 4), r.randint(1, 4)), lambda: closed_shape(r)])()
    ang = logu(r, -13, -5)
    M = rot_axis(rand_unit(r), ang)
    B = A.map(lambda p: matv(M, p))
    dist = logu(r, 2, 8)
    t = mul(rand_unit(r), dist)
    return A.map(lambda p: add(p, t)), B.map(lambda p: add(p, t))


KINDS = [
    ("coplanar_overlap", k_coplanar_overlap, False),
    ("tilted_grid", k_tilted_grid, False),
    ("sliver", k_sliver, False),
    ("perpendicular", k_perpendicular, False),
    ("dihedral", k_dihedral, False),
    ("zero_area", k_zero_area, False),
    ("dup_faces", k_dup_faces, False),
    ("coinc_inplane_far", lambda r: k_near_coinc(r, "inplane"), None),
    ("dyadic", k_dyadic, True),
    ("tjunction", k_tjunction, False),
    ("subset", k_subset, False),
    ("touch_point", k_touch_point, False),
    ("coinc_normal_far", lambda r: k_near_coinc(r, "normal"), None),
    ("hinge_rot", k_hinge_rot, False),
    ("bigcoord_grid", k_bigcoord_grid, None),
    ("parallel_edge", k_parallel_edge, False),
    ("coinc_both_far", lambda r: k_near_coinc(r, "both"), None),
    ("closed", k_closed, False),
    ("fold", k_fold, False),
    ("needle_fan", k_needle_fan, False),
    ("coinc_retri_far", lambda r: k_near_coinc(r, "retri"), None),
    ("stacked", k_stacked, False),
    ("mixed_scale", k_mixed_scale, False),
    ("snap_soup", k_snap_soup, True),
    ("coinc_jitter_far", lambda r: k_near_coinc(r, "jitter"), None),
    ("crossing_lines", k_crossing_lines, False),
    ("coinc_rot_far", lambda r: k_near_coinc(r, "rot"), None),
    ("rot_tiny_far", k_rot_tiny_far, None),
]


def write_obj(path, m):
    with open(path, "w") as fh:
        for p in m.V:
            fh.write("v %r %r %r\n" % p)
        for (a, b, c) in m.F:
            fh.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def valid(m):
    if not m.F:
        return False
    for p in m.V:
        for c in p:
            if not math.isfinite(c):
                return False
    return all(0 <= i < len(m.V) for f in m.F for i in f)


def generate(seed):
    r = random.Random(seed)
    name, fn, exact = KINDS[seed % len(KINDS)]
    A, B = fn(r)
    # random similarity transform applied to both meshes
    if exact is None:
        if r.random() < 0.3:
            P = perm_transform(r)
            A, B = A.map(P), B.map(P)
    elif r.random() < 0.6:
        _, T = random_transform(r, exact=exact)
        A, B = A.map(T), B.map(T)
    if r.random() < 0.5 and name not in ("zero_area",):
        A, B = B, A
    A, B = A.compact(), B.compact()
    if r.random() < 0.2:
        A = shuffle_mesh(r, A)
    if r.random() < 0.2:
        B = shuffle_mesh(r, B)
    assert valid(A) and valid(B), (seed, name)
    return name, A, B


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    out = sys.argv[1]
    s0, s1 = int(sys.argv[2]), int(sys.argv[3])
    os.makedirs(out, exist_ok=True)
    counts = {}
    for s in range(s0, s1):
        name, A, B = generate(s)
        counts[name] = counts.get(name, 0) + 1
        write_obj(os.path.join(out, "%d_%s_a.obj" % (s, name)), A)
        write_obj(os.path.join(out, "%d_%s_b.obj" % (s, name)), B)
    for k in sorted(counts):
        print("%-20s %d" % (k, counts[k]), file=sys.stderr)


if __name__ == "__main__":
    main()
