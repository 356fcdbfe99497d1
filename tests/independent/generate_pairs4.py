#!/usr/bin/env python3
"""Fourth independent generator of degenerate triangle-mesh pairs for Hausdorff Lens QA (issue 8).

Written blind: its author did not read tests/independent/generate_pairs.py, generate_pairs3.py,
the generator part of tests/independent/check_pairs.cpp or tests/degenerate_pairs.h, so that its
blind spots differ from theirs. It aims at what real pipelines produce rather than at textbook
cases: coarse versus fine tessellations of small curved surfaces (level-of-detail), float32 export
round-off, quantized vertices, re-indexed / re-triangulated copies, decimation artefacts (edge
collapses, caps, fold-overs, repeated vertex indices, collinear and all-zero-area meshes, single
points), thin shells, normal offsets, tiny rotations, extreme aspect ratios, nested scales and
symmetric configurations with exact ties. Every pair is then put through a random similarity
transform (scale 10**U(-6, 6)); kinds whose name ends in `_far` are near-coincident pairs moved
1e3..1e8 times their size away from the origin (the checker then also requires a certified
interval no wider than 1e-9 of the diagonal).

Python 3 standard library only; deterministic per seed (random.Random(seed)).

usage: python3 tests/independent/generate_pairs4.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/<seed:06d>_<kind>_a.obj and OUTDIR/<seed:06d>_<kind>_b.obj for every seed in
[SEED_FROM, SEED_TO), kind = KINDS[seed % len(KINDS)]. Check them with
`hlens_check_pairs --pairs OUTDIR`.
"""
import math
import os
import random
import struct
import sys

MAX_TRIS = 80

# ------------------------------------------------------------------------------------------------
# Vectors
# ------------------------------------------------------------------------------------------------


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


def unit(a, fallback=(0.0, 0.0, 1.0)):
    n = norm(a)
    return mul(a, 1.0 / n) if n > 0 else fallback


def lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def mid(a, b):
    return ((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5)


def bary(a, b, c, u, v):
    w = 1.0 - u - v
    return (a[0] * w + b[0] * u + c[0] * v, a[1] * w + b[1] * u + c[1] * v, a[2] * w + b[2] * u + c[2] * v)


def lu(rng, a, b):
    """log-uniform: 10**U(a, b)"""
    return 10.0 ** rng.uniform(a, b)


def sgn(rng):
    return rng.choice((-1.0, 1.0))


def rand_dir(rng):
    while True:
        d = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        n = dot(d, d)
        if 1e-4 < n <= 1:
            return mul(d, 1 / math.sqrt(n))


def perp(d):
    """a unit vector perpendicular to unit d"""
    a = (1.0, 0.0, 0.0) if abs(d[0]) < 0.6 else (0.0, 1.0, 0.0)
    return unit(cross(d, a))


def quat_mat(w, x, y, z):
    n = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
            (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
            (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)))


def rand_rot(rng):  # Shoemake, uniform
    u1, u2, u3 = rng.random(), rng.uniform(0, 2 * math.pi), rng.uniform(0, 2 * math.pi)
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return quat_mat(a * math.sin(u2), a * math.cos(u2), b * math.sin(u3), b * math.cos(u3))


def axis_rot(axis, ang):
    axis = unit(axis)
    s = math.sin(ang / 2)
    return quat_mat(math.cos(ang / 2), axis[0] * s, axis[1] * s, axis[2] * s)


def mat_ap(R, p):
    return (R[0][0] * p[0] + R[0][1] * p[1] + R[0][2] * p[2],
            R[1][0] * p[0] + R[1][1] * p[1] + R[1][2] * p[2],
            R[2][0] * p[0] + R[2][1] * p[1] + R[2][2] * p[2])


def rot_about(R, c, p):
    return add(c, mat_ap(R, sub(p, c)))


def f32(x):
    return struct.unpack('f', struct.pack('f', x))[0]


def f32p(p):
    return (f32(p[0]), f32(p[1]), f32(p[2]))


def quant(x, step):
    return round(x / step) * step


def dy(rng, bits=6, lo=-1.0, hi=1.0):
    """a dyadic number k / 2**bits in [lo, hi]"""
    s = 2 ** bits
    return rng.randint(int(math.ceil(lo * s)), int(math.floor(hi * s))) / s


# ------------------------------------------------------------------------------------------------
# Meshes
# ------------------------------------------------------------------------------------------------


class Mesh:
    def __init__(self, v=None, f=None):
        self.v = list(v or [])
        self.f = list(f or [])

    def av(self, p):
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.v) - 1

    def t(self, i, j, k):
        self.f.append((i, j, k))

    def tp(self, a, b, c):
        self.f.append((self.av(a), self.av(b), self.av(c)))

    def copy(self):
        return Mesh(self.v, self.f)

    def extend(self, o):
        off = len(self.v)
        self.v += o.v
        self.f += [(a + off, b + off, c + off) for a, b, c in o.f]
        return self

    def mapv(self, fn):
        return Mesh([fn(p) for p in self.v], self.f)

    def used(self):
        s = set()
        for t in self.f:
            s.update(t)
        return sorted(s)


def union(*ms):
    r = Mesh()
    for m in ms:
        r.extend(m)
    return r


def unweld(m):
    r = Mesh()
    for a, b, c in m.f:
        r.tp(m.v[a], m.v[b], m.v[c])
    return r


def reverse(m, prob=1.0, rng=None):
    return Mesh(m.v, [(a, c, b) if (rng is None or rng.random() < prob) else (a, b, c) for a, b, c in m.f])


def scramble(m, rng):
    """same geometry: permuted vertices, shuffled faces, rotated corners, some reversed"""
    n = len(m.v)
    perm = list(range(n))
    rng.shuffle(perm)
    inv = [0] * n
    for new, old in enumerate(perm):
        inv[old] = new
    v = [m.v[old] for old in perm]
    f = []
    rp = rng.choice((0.0, 0.5, 1.0))
    for t in m.f:
        t = tuple(inv[i] for i in t)
        k = rng.randint(0, 2)
        t = t[k:] + t[:k]
        if rng.random() < rp:
            t = (t[0], t[2], t[1])
        f.append(t)
    rng.shuffle(f)
    return Mesh(v, f)


def dup_faces(m, rng, k, new_vertices=False):
    r = m.copy()
    for _ in range(k):
        t = rng.choice(m.f)
        if new_vertices:
            t = (r.av(m.v[t[0]]), r.av(m.v[t[1]]), r.av(m.v[t[2]]))
        k2 = rng.randint(0, 2)
        t = t[k2:] + t[:k2]
        if rng.random() < 0.5:
            t = (t[0], t[2], t[1])
        r.f.append(t)
    return r


def vnormals(m):
    acc = [(0.0, 0.0, 0.0)] * len(m.v)
    for a, b, c in m.f:
        n = cross(sub(m.v[b], m.v[a]), sub(m.v[c], m.v[a]))
        for i in (a, b, c):
            acc[i] = add(acc[i], n)
    return [unit(n) for n in acc]


def face_normal(m, t):
    a, b, c = (m.v[i] for i in t)
    return unit(cross(sub(b, a), sub(c, a)))


def edges_of(m):
    e = set()
    for a, b, c in m.f:
        for i, j in ((a, b), (b, c), (c, a)):
            if i != j:
                e.add((min(i, j), max(i, j)))
    return sorted(e)


def subdivide(m, rng=None, prob=1.0):
    """1-to-4 midpoint split of every face (of some, with prob < 1: T-junctions), midpoints
    computed in the mesh's own (possibly far) coordinates"""
    r = Mesh(m.v, [])
    mids = {}

    def mp(i, j):
        k = (min(i, j), max(i, j))
        if k not in mids:
            mids[k] = r.av(mid(m.v[k[0]], m.v[k[1]]))
        return mids[k]

    for a, b, c in m.f:
        if rng is not None and rng.random() >= prob:
            r.t(a, b, c)
            continue
        ab, bc, ca = mp(a, b), mp(b, c), mp(c, a)
        r.f += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return r


# ------------------------------------------------------------------------------------------------
# Small surfaces, parametrised over [0,1]^2, size ~1
# ------------------------------------------------------------------------------------------------

SURFACES = ['plane', 'sphere', 'cyl', 'torus', 'saddle', 'height', 'twist']


def surface(rng, mild=False, names=None):
    names = names or (['plane', 'sphere', 'cyl', 'saddle', 'height'] if mild else SURFACES)
    nm = rng.choice(names)
    s = sgn(rng)
    if nm == 'plane':
        return nm, lambda u, v: (u - 0.5, v - 0.5, 0.0)
    if nm == 'sphere':
        R = lu(rng, 2, 7) if mild else lu(rng, -0.1, 3)

        def f(u, v):
            x, y = u - 0.5, v - 0.5
            r2 = x * x + y * y
            return (x, y, -s * r2 / (math.sqrt(R * R - r2) + R))
        return nm, f
    if nm == 'cyl':
        R = lu(rng, 2, 7) if mild else lu(rng, -0.7, 3)
        sloppy = rng.random() < 0.5  # R cos - R: cancellation, as naive code has it

        def f(u, v):
            a = (u - 0.5) / R
            z = (R * math.cos(a) - R) if sloppy else -2 * R * math.sin(a / 2) ** 2
            return (R * math.sin(a), v - 0.5, s * z)
        return nm, f
    if nm == 'torus':
        r = lu(rng, -1, -0.2)
        Rm = 1.0
        b0 = rng.uniform(0, 2 * math.pi)
        da, db = 1 / (Rm + r), min(1 / r, 5.5)

        def f(u, v):
            a = (u - 0.5) * da
            b = b0 + (v - 0.5) * db
            rr = Rm + r * math.cos(b)
            return (rr * math.cos(a) - (Rm + r * math.cos(b0)), rr * math.sin(a), r * math.sin(b) - r * math.sin(b0))
        return nm, f
    if nm == 'saddle':
        k = lu(rng, -9, -3) if mild else lu(rng, -9, 0.5)
        return nm, lambda u, v: (u - 0.5, v - 0.5, s * k * (u - 0.5) * (v - 0.5))
    if nm == 'height':
        amp = lu(rng, -10, -3) if mild else lu(rng, -10, -0.5)
        waves = [(amp * rng.uniform(0.2, 1), rng.uniform(0.5, 7), rng.uniform(0.5, 7), rng.uniform(0, 6.3))
                 for _ in range(rng.randint(1, 3))]

        def f(u, v):
            x, y = u - 0.5, v - 0.5
            return (x, y, sum(a * math.sin(wx * x + wy * y + ph) for a, wx, wy, ph in waves))
        return nm, f
    if nm == 'twist':  # helicoid strip
        k = lu(rng, -7, 0.4)

        def f(u, v):
            x, y = u - 0.5, v - 0.5
            return (x, y * math.cos(k * x), y * math.sin(k * x))
        return nm, f
    raise ValueError(nm)


DIAGS = ['random', 'a', 'b', 'alt', 'short', 'long']


def pick_diag(rng):
    return rng.choice(DIAGS)



def split_quad(m, a, b, c, d, along_ac):
    """The quad abcd as two triangles, split along ac or bd."""
    if along_ac:
        m.t(a, b, c)
        m.t(a, c, d)
    else:
        m.t(a, b, d)
        m.t(b, c, d)

def grid(f, nu, nv, diag, rng, u0=0.0, u1=1.0, v0=0.0, v1=1.0, skip=None):
    m = Mesh()
    idx = [[m.av(f(u0 + (u1 - u0) * (i / nu), v0 + (v1 - v0) * (j / nv))) for i in range(nu + 1)] for j in range(nv + 1)]
    for j in range(nv):
        for i in range(nu):
            if skip and (i, j) in skip:
                continue
            a, b, c, d = idx[j][i], idx[j][i + 1], idx[j + 1][i + 1], idx[j + 1][i]
            if diag == 'random':
                k = rng.random() < 0.5
            elif diag == 'a':
                k = True
            elif diag == 'b':
                k = False
            elif diag == 'alt':
                k = (i + j) % 2 == 0
            else:
                lac = norm(sub(m.v[c], m.v[a]))
                lbd = norm(sub(m.v[d], m.v[b]))
                k = (lac <= lbd) if diag == 'short' else (lac > lbd)
            split_quad(m, a, b, c, d, k)
    return m, idx


def grid_dims(rng, lo=1, hi=6, max_cells=40):
    while True:
        nu, nv = rng.randint(lo, hi), rng.randint(lo, hi)
        if nu * nv <= max_cells:
            return nu, nv


def surf_mesh(rng, mild=False, names=None, lo=1, hi=6, max_cells=40):
    nm, f = surface(rng, mild, names)
    nu, nv = grid_dims(rng, lo, hi, max_cells)
    m, _ = grid(f, nu, nv, pick_diag(rng), rng)
    return m, nm, f, nu, nv


# ------------------------------------------------------------------------------------------------
# Global similarity transform
# ------------------------------------------------------------------------------------------------


class Xform:
    """p -> s * R p + t. exact: signed axis permutation, power-of-two scale and dyadic translation
    (so dyadic local coordinates stay exact and ties stay ties)"""

    def __init__(self, rng, far=False, exact=False, far_exp=(3.0, 7.0), trans_exp=(-1.0, 1.5),
                 scale_exp=(-6.0, 6.0), rotate=True):
        self.far = far
        if exact:
            perm = [0, 1, 2]
            rng.shuffle(perm)
            R = [[0.0] * 3 for _ in range(3)]
            for i in range(3):
                R[i][perm[i]] = sgn(rng)
            self.R = R if rotate else ((1.0, 0, 0), (0, 1.0, 0), (0, 0, 1.0))
            self.s = 2.0 ** rng.randint(int(scale_exp[0] * 3.32), int(scale_exp[1] * 3.32))
            if far:
                e = rng.randint(int(far_exp[0] * 3.32), int(far_exp[1] * 3.32))
                self.t = tuple(self.s * sgn(rng) * rng.randint(1, 2 ** 10) * 2.0 ** (e - 10) for _ in range(3))
            elif rng.random() < 0.3:
                self.t = (0.0, 0.0, 0.0)
            else:
                self.t = tuple(self.s * rng.randint(-256, 256) / 16 for _ in range(3))
        else:
            self.R = rand_rot(rng) if rotate else ((1.0, 0, 0), (0, 1.0, 0), (0, 0, 1.0))
            self.s = lu(rng, *scale_exp)
            d = rand_dir(rng)
            if far:
                mag = self.s * lu(rng, *far_exp)
            elif rng.random() < 0.3:
                mag = 0.0
            else:
                mag = self.s * lu(rng, *trans_exp)
            self.t = mul(d, mag)

    def p(self, q):
        r = mat_ap(self.R, q)
        return (r[0] * self.s + self.t[0], r[1] * self.s + self.t[1], r[2] * self.s + self.t[2])

    def lin(self, q):  # without translation
        r = mat_ap(self.R, q)
        return (r[0] * self.s, r[1] * self.s, r[2] * self.s)

    def __call__(self, *ms):
        out = tuple(m.mapv(self.p) for m in ms)
        return out if len(out) > 1 else out[0]


def xf(rng, far=False, exact_prob=0.0, **kw):
    return Xform(rng, far=far, exact=rng.random() < exact_prob, **kw)


# ------------------------------------------------------------------------------------------------
# Kinds. Each returns (A, B, note) in world coordinates.
# ------------------------------------------------------------------------------------------------


def k_lod_surface(rng):
    """a coarse tessellation of a small curved surface vs a finer one (vertices of the coarse one
    shared exactly), as a simplification vs its original"""
    nm, f = surface(rng)
    nu, nv = grid_dims(rng, 1, 4, 20)
    k = rng.choice((2, 2, 3))
    while nu * nv * k * k > 40:
        if k > 2:
            k = 2
        elif nu >= nv:
            nu -= 1
        else:
            nv -= 1
    d1, d2 = pick_diag(rng), pick_diag(rng)
    A, _ = grid(f, nu, nv, d1, rng)
    B, _ = grid(f, nu * k, nv * k, d2, rng)
    X = xf(rng)
    return X(A, B) + (f'{nm} {nu}x{nv} vs x{k} {d1}/{d2}',)


def polar(f, ns, nr, rng, diag, pole='quad', seam='open', r0=0.0):
    """polar grid: f(r, angle) with r in [r0,1], ns sectors, nr rings. pole 'quad' keeps the
    collapsed first ring as separate coincident vertices (zero-area triangles, as UV spheres have),
    'weld' indexes them as one vertex (triangles with a repeated index), 'fan' a proper fan.
    seam 'open': the last column is evaluated at 2 pi (sin(2 pi) != 0); 'closed' reuses column 0"""
    m = Mesh()
    cols = ns + 1 if seam == 'open' else ns
    idx = []
    for j in range(nr + 1):
        r = r0 + (1 - r0) * (j / nr)
        row = []
        for i in range(cols):
            if j == 0 and r0 == 0 and pole in ('weld', 'fan') and i > 0:
                row.append(row[0])
                continue
            row.append(m.av(f(r, 2 * math.pi * (i / ns))))
        if seam == 'closed':
            row.append(row[0])
        idx.append(row)
    for j in range(nr):
        for i in range(ns):
            a, b, c, d = idx[j][i], idx[j][i + 1], idx[j + 1][i + 1], idx[j + 1][i]
            if j == 0 and r0 == 0 and pole == 'fan':
                m.t(a, c, d)
                continue
            k = rng.random() < 0.5 if diag == 'random' else (diag in ('a', 'short') or (diag == 'alt' and (i + j) % 2 == 0))
            split_quad(m, a, b, c, d, k)
    return m


def profile(rng):
    nm = rng.choice(['cone', 'parab', 'sphere', 'flat'])
    k = sgn(rng) * lu(rng, -9, 0.5)
    if nm == 'cone':
        zf = lambda r: k * r
    elif nm == 'parab':
        zf = lambda r: k * r * r
    elif nm == 'sphere':
        R = lu(rng, -0.25, 3)
        zf = lambda r: -(0.25 * r * r) / (math.sqrt(R * R - 0.25 * r * r) + R)
    else:
        zf = lambda r: 0.0
    return nm, (lambda r, a: (0.5 * r * math.cos(a), 0.5 * r * math.sin(a), zf(r)))


def k_uv_pole(rng):
    """polar (UV-sphere-like) grids around a pole: coarse vs fine, with the pole's collapsed ring
    as coincident vertices, as a repeated index or as a fan, the seam open (sin(2 pi) != 0) or
    closed; the profile a cone, a paraboloid, a sphere cap or flat"""
    nm, f = profile(rng)
    ns1, nr1 = rng.randint(3, 10), rng.randint(1, 3)
    while ns1 * nr1 > 16:
        nr1 -= 1
    ns2, nr2 = rng.choice((ns1, 2 * ns1, rng.randint(3, 16))), rng.randint(1, 4)
    cap = 12 if nm == 'flat' else 30  # flat fans with a collapsed ring are slow to check
    while ns2 * nr2 > cap:
        if nr2 > 1:
            nr2 -= 1
        else:
            ns2 //= 2
    ns2 = max(ns2, 3)
    p1, p2 = rng.choice(['quad', 'weld', 'fan']), rng.choice(['quad', 'weld', 'fan'])
    s1, s2 = rng.choice(['open', 'closed']), rng.choice(['open', 'closed'])
    A = polar(f, ns1, nr1, rng, pick_diag(rng), p1, s1)
    B = polar(f, ns2, nr2, rng, pick_diag(rng), p2, s2)
    X = xf(rng)
    return X(A, B) + (f'{nm} {ns1}x{nr1} {p1}/{s1} vs {ns2}x{nr2} {p2}/{s2}',)


ICO_F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]


def icosahedron():
    p = (1 + math.sqrt(5)) / 2
    v = [(-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0), (0, -1, p), (0, 1, p), (0, -1, -p), (0, 1, -p),
         (p, 0, -1), (p, 0, 1), (-p, 0, -1), (-p, 0, 1)]
    return Mesh([unit(q) for q in v], ICO_F)


def octahedron():
    v = [(1.0, 0, 0), (-1.0, 0, 0), (0, 1.0, 0), (0, -1.0, 0), (0, 0, 1.0), (0, 0, -1.0)]
    f = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return Mesh(v, f)


def k_icosphere(rng):
    """closed convex polyhedra: an icosahedron / octahedron vs its 1-to-4 subdivision, midpoints
    projected on the sphere or not (then the same surface), or vs a copy scaled by 1+eps"""
    base = icosahedron() if rng.random() < 0.6 else octahedron()
    v = rng.choice(['proj', 'flat', 'scaled', 'proj_rot'])
    if v in ('proj', 'proj_rot'):
        B = subdivide(base).mapv(unit)
        if v == 'proj_rot':
            R = axis_rot(rand_dir(rng), lu(rng, -14, -2))
            B = B.mapv(lambda q: mat_ap(R, q))
    elif v == 'flat':
        B = subdivide(base)
    else:
        e = sgn(rng) * lu(rng, -15, -2)
        B = base.mapv(lambda q: mul(q, 1 + e))
    A = base
    if rng.random() < 0.3:
        A = scramble(A, rng)
    X = xf(rng, exact_prob=0.3)
    return X(A, B) + (f'{len(base.f)} {v}',)


def k_f32_export(rng):
    """a surface vs the same one after a float32 export in world coordinates (offset <= 30 sizes),
    sometimes re-triangulated too"""
    A, nm, f, nu, nv = surf_mesh(rng)
    B = A
    if rng.random() < 0.3:
        B, _ = grid(f, nu, nv, pick_diag(rng), rng)
    X = xf(rng)
    A, B = X(A, B)
    B = B.mapv(f32p)
    if rng.random() < 0.3:
        B = scramble(B, rng)
    return A, B, f'{nm} {nu}x{nv}'


def k_f32_local_far(rng):
    """float32 model coordinates (local frame, double offset): the double mesh vs its float32
    copy, both moved 1e3..1e7 of their size away in double"""
    A, nm, f, nu, nv = surf_mesh(rng, mild=rng.random() < 0.5)
    X = xf(rng)
    A1 = A.mapv(X.lin)
    B1 = A1.mapv(f32p)
    T = mul(rand_dir(rng), X.s * lu(rng, 3, 7))
    A = A1.mapv(lambda q: add(q, T))
    B = B1.mapv(lambda q: add(q, T))
    return A, B, f'{nm} {nu}x{nv}'


def k_quantized(rng):
    """a surface vs its vertices quantized to a world grid (1e-3, 2^-20, 2^-10 of the size, ...);
    coarse steps collapse triangles"""
    A, nm, f, nu, nv = surf_mesh(rng)
    X = xf(rng)
    A = X(A)
    st = rng.choice([1e-3, 2.0 ** -20, 2.0 ** -10, lu(rng, -7, -0.7), 2.0 ** -rng.randint(2, 30), 0.1]) * X.s
    B = A.mapv(lambda q: (quant(q[0], st), quant(q[1], st), quant(q[2], st)))
    return A, B, f'{nm} {nu}x{nv} step/size={st / X.s:.3g}'


def k_quantized_far(rng):
    """quantized in the local frame (step 2^-12..2^-40 of the size) then moved far away"""
    A, nm, f, nu, nv = surf_mesh(rng, mild=rng.random() < 0.5)
    X = xf(rng)
    A1 = A.mapv(X.lin)
    st = X.s * 2.0 ** -rng.randint(12, 40)
    B1 = A1.mapv(lambda q: (quant(q[0], st), quant(q[1], st), quant(q[2], st)))
    T = mul(rand_dir(rng), X.s * lu(rng, 3, 7))
    return A1.mapv(lambda q: add(q, T)), B1.mapv(lambda q: add(q, T)), f'{nm} {nu}x{nv}'


def _reindexed(rng, far):
    if rng.random() < 0.75:
        A, nm, f, nu, nv = surf_mesh(rng, max_cells=30)
    else:
        nm, f = profile(rng)
        A = polar(f, rng.randint(3, 8), rng.randint(1, 3), rng, pick_diag(rng), rng.choice(['quad', 'weld', 'fan']))
    B = A
    ops = []
    if rng.random() < 0.5:
        B = unweld(B)
        ops.append('unweld')
    if rng.random() < 0.4:
        B = dup_faces(B, rng, rng.randint(1, 6), rng.random() < 0.5)
        ops.append('dup')
    if len(B.f) > MAX_TRIS:
        B = Mesh(B.v, B.f[:MAX_TRIS])
    B = scramble(B, rng)
    if rng.random() < 0.3:
        B = reverse(B)
        ops.append('reversed')
    X = xf(rng, far=far, exact_prob=0.3)
    return X(A, B) + (f'{nm} {"+".join(ops)}',)


def k_reindexed(rng):
    """the same surface, re-indexed: unwelded, faces shuffled and reversed, corners rotated, some
    faces duplicated (Hausdorff distance exactly 0)"""
    return _reindexed(rng, False)


def k_reindexed_far(rng):
    """as reindexed, far from the origin"""
    return _reindexed(rng, True)


def _diag_flip(rng, far):
    nm, f = surface(rng, mild=far)
    nu, nv = grid_dims(rng, 1, 6, 40)
    d1 = pick_diag(rng)
    d2 = rng.choice([d for d in DIAGS if d != d1] + ['random'])
    A, _ = grid(f, nu, nv, d1, rng)
    B, _ = grid(f, nu, nv, d2, rng)
    X = xf(rng, far=far)
    return X(A, B) + (f'{nm} {nu}x{nv} {d1}/{d2}',)


def k_diag_flip(rng):
    """the same grid points of a curved surface, two triangulations (diagonal flips)"""
    return _diag_flip(rng, False)


def k_diag_flip_far(rng):
    """diagonal flips of a nearly flat surface, far from the origin"""
    return _diag_flip(rng, True)


def k_edge_collapse(rng):
    """decimation by edge collapses (to an end, the midpoint, just off it, or an end nudged by
    1e-1..1e-12 along the edge), the faces made degenerate kept (a,a,b) or dropped; vs the original"""
    B, nm, f, nu, nv = surf_mesh(rng, lo=2, hi=6, max_cells=36)
    v = list(B.v)
    faces = list(B.f)
    keep = rng.random() < 0.6
    nrm = vnormals(B)
    modes = []
    for _ in range(rng.randint(1, 5)):
        es = edges_of(Mesh(v, faces))
        if not es:
            break
        i, j = rng.choice(es)
        mode = rng.choice(['i', 'j', 'mid', 'mid_off', 'near_i'])
        modes.append(mode)
        pi, pj = v[i], v[j]
        if mode == 'i':
            p = pi
        elif mode == 'j':
            p = pj
        elif mode == 'mid':
            p = mid(pi, pj)
        elif mode == 'mid_off':
            p = add(mid(pi, pj), mul(nrm[i], sgn(rng) * lu(rng, -12, -1) * norm(sub(pi, pj))))
        else:
            p = lerp(pi, pj, lu(rng, -12, -1))
        v[i] = p
        v[j] = p
        nf = []
        for t in faces:
            t = tuple(i if x == j else x for x in t)
            if len(set(t)) < 3 and not keep:
                continue
            nf.append(t)
        faces = nf or [(i, i, i)]
    A = Mesh(v, faces)
    X = xf(rng)
    return X(A, B) + (f'{nm} {nu}x{nv} keep_degenerate={keep} {",".join(modes)}',)


def k_cap_sliver(rng):
    """caps (one angle near 180 degrees): squares whose diagonal is split at a point 1e-1..1e-15
    off it (in the plane, inward or outward, or out of the plane), the cap triangle filling the
    gap; vs the plain squares (or a finer grid)"""
    n = rng.randint(1, 4)
    nm, hf = surface(rng, names=['plane', 'plane', 'saddle', 'height', 'sphere'])
    P = {}

    def g(i, j):
        return hf(i / n, j / n)

    A, B = Mesh(), Mesh()
    notes = []
    for j in range(n):
        for i in range(n):
            p00, p10, p11, p01 = g(i, j), g(i + 1, j), g(i + 1, j + 1), g(i, j + 1)
            if rng.random() < 0.5:
                Pp, Q, R, S = p00, p11, p01, p10
            else:
                Pp, Q, R, S = p10, p01, p00, p11
            B.tp(Pp, S, Q)
            B.tp(Pp, Q, R)
            if rng.random() < 0.7:
                t = rng.choice([0.5, rng.uniform(0.02, 0.98), lu(rng, -8, -1)])
                eps = lu(rng, -15, -1) * norm(sub(Q, Pp))
                base = lerp(Pp, Q, t)
                nrm = unit(cross(sub(S, Pp), sub(Q, Pp)))
                inward = unit(sub(R, lerp(Pp, Q, dot(sub(R, Pp), sub(Q, Pp)) / dot(sub(Q, Pp), sub(Q, Pp)))))
                how = rng.choice(['in', 'out', 'normal'])
                d = inward if how == 'in' else (mul(inward, -1) if how == 'out' else mul(nrm, sgn(rng)))
                m = add(base, mul(d, eps))
                notes.append(how)
                A.tp(Pp, S, Q)
                A.tp(Pp, m, R)
                A.tp(m, Q, R)
                A.tp(Pp, Q, m)
            else:
                A.tp(Pp, S, Q)
                A.tp(Pp, Q, R)
    if rng.random() < 0.3 and n <= 3:
        B, _ = grid(hf, 2 * n, 2 * n, pick_diag(rng), rng)
        notes.append('fine_B')
    X = xf(rng)
    return X(A, B) + (f'{nm} n={n} {",".join(notes)}',)


def k_degenerate_faces(rng):
    """a surface with extra degenerate faces: (a,a,b) on edges, (a,a,a) on vertices, collinear
    (a,b,midpoint), (a,b,copy of b), and sometimes a zero-area 'hair' sticking out; vs the
    clean surface or another triangulation of it"""
    B, nm, f, nu, nv = surf_mesh(rng, max_cells=25)
    A = B.copy()
    es = edges_of(B)
    notes = []
    nrm = vnormals(B)
    for _ in range(rng.randint(1, 12)):
        w = rng.choice(['aab', 'aaa', 'collinear', 'copy', 'aab', 'collinear', 'hair'])
        i, j = rng.choice(es)
        if w == 'hair' and rng.random() < 0.5:
            w = 'collinear'
        notes.append(w)
        if w == 'aab':
            A.t(i, i, j) if rng.random() < 0.5 else A.t(j, i, j)
        elif w == 'aaa':
            A.t(i, i, i)
        elif w == 'collinear':
            m = A.av(lerp(A.v[i], A.v[j], rng.choice([0.5, rng.random()])))
            A.t(i, m, j) if rng.random() < 0.5 else A.t(i, j, m)
        elif w == 'copy':
            c = A.av(A.v[j])
            A.t(i, j, c)
        else:
            L = lu(rng, -9, -0.5)
            p = add(A.v[i], mul(nrm[i], L))
            q = add(A.v[i], mul(nrm[i], L * 0.5))
            A.t(i, A.av(q), A.av(p))
    if rng.random() < 0.4:
        B, _ = grid(f, nu, nv, pick_diag(rng), rng)
    X = xf(rng)
    return X(A, B) + (f'{nm} {nu}x{nv} {",".join(notes)}',)


def polyline_mesh(pts, rng, style=None):
    m = Mesh()
    ids = [m.av(p) for p in pts]
    for k in range(len(ids) - 1):
        a, b = ids[k], ids[k + 1]
        s = style or rng.choice(['aab', 'abb', 'amb', 'aba'])
        if s == 'aab':
            m.t(a, a, b)
        elif s == 'abb':
            m.t(a, b, b)
        elif s == 'aba':
            m.t(a, b, a)
        else:
            m.t(a, m.av(mid(m.v[a], m.v[b])), b)
    if not m.f:
        m.t(ids[0], ids[0], ids[0])
    return m


def k_polyline(rng):
    """a mesh made only of zero-area triangles (a polyline: (a,a,b), (a,b,b), (a,mid,b)) along a
    grid line or the boundary of a surface, near it, or vs another polyline (parallel, reversed
    and resampled, crossing, skew)"""
    B, nm, f, nu, nv = surf_mesh(rng, lo=2, hi=6, max_cells=36)
    var = rng.choice(['grid_line', 'boundary', 'on_surface', 'near', 'poly_parallel', 'poly_resampled', 'poly_cross'])
    style = rng.choice([None, 'aab', 'amb'])
    if var == 'grid_line':
        j = rng.randint(0, nv)
        pts = [f(i / nu, j / nv) for i in range(nu + 1)]
    elif var == 'boundary':
        pts = [f(i / nu, 0.0) for i in range(nu)] + [f(1.0, j / nv) for j in range(nv)] + \
              [f(1 - i / nu, 1.0) for i in range(nu)] + [f(0.0, 1 - j / nv) for j in range(nv + 1)]
    else:
        c = (rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7))
        r = rng.uniform(0.1, 0.3)
        a0 = rng.uniform(0, 6.3)
        da = rng.uniform(1, 6.3)
        k = rng.randint(3, 30)
        pts = [f(c[0] + r * math.cos(a0 + da * t / k), c[1] + r * math.sin(a0 + da * t / k)) for t in range(k + 1)]
        if var == 'near':
            off = lu(rng, -13, -1) * sgn(rng)
            pts = [add(p, (0.0, 0.0, off)) for p in pts]
    A = polyline_mesh(pts, rng, style)
    if var.startswith('poly_'):
        if var == 'poly_parallel':
            d = mul(unit(rand_dir(rng)), lu(rng, -12, -1))
            B = polyline_mesh([add(p, d) for p in pts], rng, style)
        elif var == 'poly_resampled':
            q = []
            for k2 in range(len(pts) - 1, 0, -1):
                q.append(pts[k2])
                if rng.random() < 0.5:
                    q.append(lerp(pts[k2], pts[k2 - 1], rng.random()))
            q.append(pts[0])
            B = polyline_mesh(q, rng)
        else:
            cpt = pts[len(pts) // 2]
            d = rand_dir(rng)
            L = rng.uniform(0.1, 1)
            B = polyline_mesh([add(cpt, mul(d, -L)), cpt, add(cpt, mul(d, L * rng.random()))], rng)
    X = xf(rng)
    return X(A, B) + (f'{nm} {var} {style}',)


def k_point_vs_mesh(rng):
    """a single point ((a,a,a), or three coincident copies, or a few points) on a vertex, an
    edge, a face of a surface, just above it, or away; sometimes point vs point"""
    B, nm, f, nu, nv = surf_mesh(rng, max_cells=30)
    loc = rng.choice(['vertex', 'edge', 'face', 'above', 'away', 'points', 'point_point'])
    t = rng.choice(B.f)
    a, b, c = (B.v[i] for i in t)
    if loc == 'vertex':
        p = a
    elif loc == 'edge':
        p = lerp(a, b, rng.choice([0.5, rng.random(), lu(rng, -12, -1)]))
    elif loc in ('face', 'points'):
        u, v = rng.random(), rng.random()
        if u + v > 1:
            u, v = 1 - u, 1 - v
        p = bary(a, b, c, u, v)
    elif loc == 'above':
        p = add(bary(a, b, c, 1 / 3, 1 / 3), mul(face_normal(B, t), sgn(rng) * lu(rng, -15, 0)))
    else:
        p = add(a, mul(rand_dir(rng), lu(rng, -1, 2)))
    A = Mesh()
    if loc == 'points':
        for _ in range(rng.randint(2, 5)):
            q = rng.choice(B.v)
            i = A.av(q)
            A.t(i, i, i)
    elif rng.random() < 0.5:
        i = A.av(p)
        A.t(i, i, i)
    else:
        A.tp(p, p, p)
    if loc == 'point_point':
        q = add(p, mul(rand_dir(rng), lu(rng, -12, 0)))
        B = Mesh()
        i = B.av(q)
        B.t(i, i, i)
    X = xf(rng, exact_prob=0.2)
    return X(A, B) + (f'{nm} {loc}',)


def shell(f, nu, nv, rng, gap, rim):
    top, idx = grid(f, nu, nv, pick_diag(rng), rng)
    bot, _ = grid(f, nu, nv, pick_diag(rng), rng)
    nrm = vnormals(top)
    bot = Mesh([sub(p, mul(n, gap)) for p, n in zip(bot.v, nrm)], bot.f)
    bot = reverse(bot)
    s = union(top, bot)
    if rim:
        off = len(top.v)
        loop = [idx[0][i] for i in range(nu)] + [idx[j][nu] for j in range(nv)] + \
               [idx[nv][nu - i] for i in range(nu)] + [idx[nv - j][0] for j in range(nv)]
        for k in range(len(loop)):
            a, b = loop[k], loop[(k + 1) % len(loop)]
            s.t(a, b, b + off)
            s.t(a, b + off, a + off)
    return s, top, bot, nrm


def _thin_shell(rng, far):
    nm, f = surface(rng, mild=far)
    nu, nv = grid_dims(rng, 1, 3, 9)
    gap = lu(rng, -12, -3) if far else lu(rng, -12, -1)
    rim = rng.random() < 0.6
    S, top, bot, nrm = shell(f, nu, nv, rng, gap, rim)
    w = rng.choice(['top', 'bottom', 'middle', 'coarse'])
    if w == 'top':
        B = top
    elif w == 'bottom':
        B = bot
    elif w == 'middle':
        B = Mesh([sub(p, mul(n, gap / 2)) for p, n in zip(top.v, nrm)], top.f)
    else:
        B, _ = grid(f, 1, 1, pick_diag(rng), rng)
    X = xf(rng, far=far)
    return X(S, B) + (f'{nm} {nu}x{nv} gap={gap:.3g} rim={rim} vs {w}',)


def k_thin_shell(rng):
    """a plate's two sides 1e-12..1e-1 apart (different triangulations, one reversed, with or
    without the rim strip) vs one side, the middle surface or a coarse patch"""
    return _thin_shell(rng, False)


def k_thin_shell_far(rng):
    """a thin shell (gap 1e-12..1e-3) vs one side, far from the origin"""
    return _thin_shell(rng, True)


def _normal_offset(rng, far):
    mild = far and rng.random() < 0.5
    A, nm, f, nu, nv = surf_mesh(rng, mild=mild)
    d = sgn(rng) * lu(rng, -15, -3)
    nrm = vnormals(A)
    world = far and rng.random() < 0.4
    B = A
    if rng.random() < 0.3 and (mild or not far):  # re-triangulated too (far: only when nearly flat)
        B, _ = grid(f, nu, nv, pick_diag(rng), rng)
    X = xf(rng, far=far, far_exp=(3.0, 8.0))
    if world:  # offset applied in world coordinates, after the move
        A2, B2 = X(A, B)
        nw = [mat_ap(X.R, n) for n in nrm]
        B2 = Mesh([add(p, mul(n, d * X.s)) for p, n in zip(B2.v, nw)], B2.f)
        return A2, B2, f'{nm} {nu}x{nv} d={d:.3g} world'
    B = Mesh([add(p, mul(n, d)) for p, n in zip(B.v, nrm)], B.f)
    return X(A, B) + (f'{nm} {nu}x{nv} d={d:.3g}',)


def k_normal_offset(rng):
    """a surface vs its copy offset along the vertex normals by 1e-15..1e-3 of its size"""
    return _normal_offset(rng, False)


def k_normal_offset_far(rng):
    """normal offset 1e-15..1e-3, moved 1e3..1e8 of the size away (offset applied locally or in
    world coordinates)"""
    return _normal_offset(rng, True)


def k_strip_vs_tri(rng):
    """a strip 1e-6..1e-12 wide (1..8 quads) vs a unit triangle / square / grid: inside it, on
    its edge, crossing its edge, standing on it, above it, slightly tilted"""
    bt = rng.choice(['tri', 'square', 'grid'])
    B = Mesh()
    if bt == 'tri':
        B.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    elif bt == 'square':
        B.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0))
        B.tp((0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0))
    else:
        B, _ = grid(lambda u, v: (u, v, 0.0), 3, 3, pick_diag(rng), rng)
    w = lu(rng, -12, -6)
    m = rng.randint(1, 8)
    pl = rng.choice(['inside', 'on_edge', 'crossing', 'standing', 'above', 'tilted'])

    def inside():
        u, v = rng.uniform(0.05, 0.9), rng.uniform(0.05, 0.9)
        if bt == 'tri' and u + v > 0.95:
            u, v = 0.95 - v, 0.95 - u
        return (u, v, 0.0)

    if pl == 'on_edge':
        p0 = (rng.uniform(-0.2, 0.5), 0.0, 0.0)
        p1 = (rng.uniform(0.5, 1.2), 0.0, 0.0)
    elif pl == 'crossing':
        p0 = inside()
        p1 = (rng.uniform(0.0, 1.0), -rng.uniform(0.01, 0.5), 0.0)
    else:
        p0, p1 = inside(), inside()
        if norm(sub(p0, p1)) < 0.05:
            p1 = add(p0, (0.3, 0.1, 0.0))
    dirn = unit(sub(p1, p0))
    side = unit(cross((0.0, 0.0, 1.0), dirn))
    if pl == 'standing':
        side = (0.0, 0.0, 1.0)
    elif pl == 'tilted':
        ang = lu(rng, -10, 0)
        side = add(mul(side, math.cos(ang)), (0.0, 0.0, math.sin(ang)))
    lift = (0.0, 0.0, sgn(rng) * lu(rng, -12, 0)) if pl == 'above' else (0.0, 0.0, 0.0)
    centred = rng.random() < 0.5 and pl != 'standing'
    A = Mesh()
    lo = [A.av(add(add(lerp(p0, p1, k / m), lift), mul(side, -w / 2 if centred else 0.0))) for k in range(m + 1)]
    hi = [A.av(add(add(lerp(p0, p1, k / m), lift), mul(side, w / 2 if centred else w))) for k in range(m + 1)]
    for k in range(m):
        if rng.random() < 0.5:
            A.t(lo[k], lo[k + 1], hi[k + 1])
            A.t(lo[k], hi[k + 1], hi[k])
        else:
            A.t(lo[k], lo[k + 1], hi[k])
            A.t(lo[k + 1], hi[k + 1], hi[k])
    X = xf(rng, exact_prob=0.3)
    return X(A, B) + (f'{bt} {pl} w={w:.3g} m={m}',)


def k_tiny_on_big(rng):
    """a tiny mesh (1e-9..1e-3 of the big one) on a big source's vertex, edge, ridge, face,
    just above it or beside it; the big source a triangle, a roof (any dihedral) or a cone fan"""
    bt = rng.choice(['tri', 'roof', 'fan'])
    B = Mesh()
    if bt == 'tri':
        B.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.uniform(0, 1), rng.uniform(0.3, 1), 0.0))
        ridge = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
        apex = (0.0, 0.0, 0.0)
    elif bt == 'roof':
        th = rng.choice([lu(rng, -8, 0), math.pi / 2, math.pi - lu(rng, -8, 0), rng.uniform(0, math.pi)])
        B.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 1.0, 0.0))
        B.tp((1.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.5, -math.cos(th), math.sin(th)))
        ridge = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0))
        apex = (0.0, 0.0, 0.0)
    else:
        n = rng.randint(3, 12)
        h = sgn(rng) * rng.choice([0.0, lu(rng, -10, 0)])
        c = B.av((0.0, 0.0, h))
        ring = [B.av((math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n), 0.0)) for k in range(n)]
        for k in range(n):
            B.t(c, ring[k], ring[(k + 1) % n])
        ridge = (B.v[c], B.v[ring[0]])
        apex = B.v[c]
    loc = rng.choice(['vertex', 'edge', 'face', 'above', 'beside'])
    t = B.f[0]
    a, b, c3 = (B.v[i] for i in t)
    nrm = face_normal(B, t)
    if loc == 'vertex':
        p = apex
    elif loc == 'edge':
        p = lerp(ridge[0], ridge[1], rng.choice([0.5, rng.random()]))
    elif loc == 'face':
        p = bary(a, b, c3, 0.3, 0.3)
    elif loc == 'above':
        p = bary(a, b, c3, 0.25, 0.35)
    else:
        p = add(lerp(ridge[0], ridge[1], 0.5), mul(unit(cross(nrm, sub(ridge[1], ridge[0]))), -1.0))
        p = lerp(lerp(ridge[0], ridge[1], 0.5), p, rng.uniform(0, 1) * 1e-3)
    eps = lu(rng, -9, -3)
    if loc == 'above':
        p = add(p, mul(nrm, eps * rng.choice([0.5, 1.0, lu(rng, -3, 3)])))
    shape = rng.choice(['tet', 'tri', 'grid', 'inplane'])
    A = Mesh()
    if shape == 'tet':
        d = [rand_dir(rng) for _ in range(4)]
        q = [add(p, mul(x, eps)) for x in d]
        for i, j, k in ((0, 1, 2), (0, 3, 1), (1, 3, 2), (2, 3, 0)):
            A.tp(q[i], q[j], q[k])
    elif shape == 'tri':
        A.tp(add(p, mul(rand_dir(rng), eps)), add(p, mul(rand_dir(rng), eps)), add(p, mul(rand_dir(rng), eps)))
    else:
        e1 = unit(sub(b, a))
        e2 = unit(cross(nrm, e1))
        if shape == 'grid':
            e2 = unit(add(e2, mul(nrm, rng.uniform(-1, 1))))
        G, _ = grid(lambda u, v: add(p, add(mul(e1, (u - 0.5) * eps), mul(e2, (v - 0.5) * eps))), 2, 2, pick_diag(rng), rng)
        A = G
    X = xf(rng)
    return X(A, B) + (f'{bt} {loc} {shape} eps={eps:.3g}',)


def k_nested_scales(rng):
    """copies of one shape at scales 1, 1e-1..1e-4, 1e-4..1e-9 about a common centre or a common
    vertex vs the shape at one scale (or another scale)"""
    sh = rng.choice(['tri', 'pyramid', 'grid', 'fan'])
    S = Mesh()
    if sh == 'tri':
        S.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.uniform(-0.5, 1), rng.uniform(0.2, 1), 0.0))
    elif sh == 'pyramid':
        base = [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (-1.0, 0.0, 0.0), (0.0, -1.0, 0.0)]
        top = (0.0, 0.0, rng.uniform(-1, 1))
        for k in range(4):
            S.tp(top, base[k], base[(k + 1) % 4])
    elif sh == 'grid':
        S, _ = grid(surface(rng)[1], 2, 2, pick_diag(rng), rng)
    else:
        n = rng.randint(3, 7)
        for k in range(n):
            S.tp((0.0, 0.0, 0.0), (math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n), 0.0),
                 (math.cos(2 * math.pi * (k + 1) / n), math.sin(2 * math.pi * (k + 1) / n), 0.0))
    about = rng.choice(['centroid', 'vertex'])
    c = S.v[S.f[0][0]] if about == 'vertex' else mul(
        (sum(p[0] for p in S.v), sum(p[1] for p in S.v), sum(p[2] for p in S.v)), 1 / len(S.v))
    scales = [1.0, lu(rng, -4, -1), lu(rng, -9, -4)]
    if rng.random() < 0.5:
        scales[1] = 2.0 ** -rng.randint(3, 14)
        scales[2] = 2.0 ** -rng.randint(14, 30)
    tw = rng.random() < 0.3
    A = Mesh()
    for s in scales:
        R = axis_rot(rand_dir(rng), lu(rng, -12, -2)) if tw else None
        A.extend(S.mapv(lambda p: add(c, mul(mat_ap(R, sub(p, c)) if R else sub(p, c), s))))
    bs = rng.choice(scales + [lu(rng, -9, 0)])
    B = S.mapv(lambda p: add(c, mul(sub(p, c), bs)))
    X = xf(rng, exact_prob=0.3)
    return X(A, B) + (f'{sh} about {about} scales {scales[1]:.3g},{scales[2]:.3g} vs {bs:.3g}',)


def k_equidistant(rng):
    """exact ties (dyadic coordinates, exact transform mostly): a target midway between two
    parallel sources, in the mirror plane of mirror-symmetric sources, or on the axis of four
    sources related by quarter turns"""
    var = rng.choice(['parallel', 'mirror', 'fourfold', 'three_planes'])
    A, B = Mesh(), Mesh()
    if var in ('parallel', 'three_planes'):
        h = 2.0 ** -rng.randint(0, 20)

        def sq(z, shift, half):
            x0, y0 = shift
            m, _ = grid(lambda u, v: (x0 + half * (2 * u - 1), y0 + half * (2 * v - 1), z), 2, 2, pick_diag(rng), rng)
            return m
        s1 = (dy(rng, 3), dy(rng, 3))
        s2 = s1 if rng.random() < 0.5 else (dy(rng, 3), dy(rng, 3))
        B = union(sq(h, s1, 0.5), sq(-h, s2, rng.choice([0.5, 0.25, 1.0])))
        if var == 'three_planes':
            B.extend(sq(3 * h, s1, 0.5))
        tgt = rng.choice(['square', 'tri', 'big'])
        if tgt == 'square':
            A = sq(0.0, (dy(rng, 4, -0.5, 0.5), dy(rng, 4, -0.5, 0.5)), dy(rng, 4, 0.0625, 1))
        elif tgt == 'big':
            A = sq(0.0, (0.0, 0.0), 2.0)
        else:
            A.tp((dy(rng), dy(rng), 0.0), (dy(rng), dy(rng), 0.0), (dy(rng), dy(rng), 0.0))
    elif var == 'mirror':
        for _ in range(rng.randint(1, 3)):
            p = [(dy(rng, 5, 0.0, 1.0), dy(rng, 5), dy(rng, 5)) for _ in range(3)]
            B.tp(*p)
            B.tp(*[(-q[0], q[1], q[2]) for q in p])
        if rng.random() < 0.5:
            A, _ = grid(lambda u, v: (0.0, 2 * u - 1, 2 * v - 1), 2, 2, pick_diag(rng), rng)
        else:
            A.tp((0.0, dy(rng), dy(rng)), (0.0, dy(rng), dy(rng)), (0.0, dy(rng), dy(rng)))
    else:
        p = [(dy(rng, 5, 0.0, 1.0), dy(rng, 5, 0.0, 1.0), dy(rng, 5)) for _ in range(3)]
        for k in range(4):
            B.tp(*p)
            p = [(-q[1], q[0], q[2]) for q in p]
        z0, z1 = dy(rng), dy(rng)
        if rng.random() < 0.5:
            A.tp((0.0, 0.0, z0), (0.0, 0.0, z1), (0.0, 0.0, z1))  # a segment on the axis
        else:
            e = 2.0 ** -rng.randint(1, 20)
            A.tp((e, 0.0, z0), (-e, 0.0, z0), (0.0, e, z0))
    X = xf(rng, exact_prob=0.7)
    return X(A, B) + (var,)


def k_fan_apex(rng):
    """a regular n-gon fan (n = 3..24, flat or a cone 1e-12..1 high) vs a point, a small
    triangle or a smaller/rotated/dual fan above its centre (ties among the n faces)"""
    n = rng.randint(3, 24)
    hz = rng.choice([0.0, sgn(rng) * lu(rng, -12, 0)])
    ph = rng.choice([0.0, rng.uniform(0, 6.3)])

    def fan(nn, r, z, zc, phase):
        m = Mesh()
        c = m.av((0.0, 0.0, zc))
        ring = [m.av((r * math.cos(phase + 2 * math.pi * k / nn), r * math.sin(phase + 2 * math.pi * k / nn), z))
                for k in range(nn)]
        for k in range(nn):
            m.t(c, ring[k], ring[(k + 1) % nn])
        return m

    B = fan(n, 1.0, 0.0, hz, ph)
    h = rng.choice([0.0, lu(rng, -10, 0.5), -lu(rng, -10, 0.5)])
    tg = rng.choice(['point', 'tri', 'dual', 'small', 'same_rot'])
    A = Mesh()
    if tg == 'point':
        A.tp((0.0, 0.0, h), (0.0, 0.0, h), (0.0, 0.0, h))
    elif tg == 'tri':
        e = lu(rng, -9, -1)
        A = fan(3, e, h, h, rng.uniform(0, 6.3))
    elif tg == 'dual':
        A = fan(n, 1.0, h, h + hz, ph + math.pi / n)
    elif tg == 'small':
        A = fan(rng.choice([n, 2 * n if 2 * n <= 48 else n]), lu(rng, -6, 0), h, h + hz * rng.random(), ph)
    else:
        A = fan(n, 1.0, h, h + hz, ph + lu(rng, -14, -3))
    X = xf(rng, exact_prob=0.2)
    return X(A, B) + (f'n={n} hz={hz:.3g} {tg} h={h:.3g}',)


def k_cube_corner(rng):
    """three perpendicular squares meeting at a cube corner (concave) vs a triangle across the
    corner perpendicular to (1,1,1), a point on the diagonal, a sphere octant, a nested smaller
    corner, or the convex corner of the opposite cube"""
    def corner(s, o, n):
        m = Mesh()
        for ax in range(3):
            def f(u, v, ax=ax):
                p = [0.0, 0.0, 0.0]
                p[(ax + 1) % 3] = s * u
                p[(ax + 2) % 3] = s * v
                return (o[0] + p[0], o[1] + p[1], o[2] + p[2])
            g, _ = grid(f, n, n, pick_diag(rng), rng)
            m.extend(g)
        return m
    B = corner(1.0, (0.0, 0.0, 0.0), rng.randint(1, 3))
    tg = rng.choice(['cut', 'diag_point', 'octant', 'nested', 'convex'])
    A = Mesh()
    if tg == 'cut':
        c = rng.choice([dy(rng, 5, 0.03, 1.0), lu(rng, -8, 0)])
        A.tp((c, 0.0, 0.0), (0.0, c, 0.0), (0.0, 0.0, c))
    elif tg == 'diag_point':
        t = rng.choice([dy(rng, 6, 0, 1), lu(rng, -10, 0)])
        A.tp((t, t, t), (t, t, t), (t, t, t))
    elif tg == 'octant':
        r = rng.choice([0.5, rng.uniform(0.1, 1)])
        A, _ = grid(lambda u, v: (r * math.cos(u * math.pi / 2) * math.sin(v * math.pi / 2),
                                  r * math.sin(u * math.pi / 2) * math.sin(v * math.pi / 2),
                                  r * math.cos(v * math.pi / 2)), rng.randint(1, 4), rng.randint(1, 4), pick_diag(rng), rng)
    elif tg == 'nested':
        e = 2.0 ** -rng.randint(1, 30)
        A = corner(0.5, (e, e * rng.choice([1, 0, 2]), e), rng.randint(1, 2))
    else:
        A = reverse(corner(-1.0, (0.0, 0.0, 0.0), rng.randint(1, 2)))
    X = xf(rng, exact_prob=0.5)
    return X(A, B) + (tg,)


def k_parallel_edges(rng):
    """closest points forming whole segments: a target edge parallel to a roof's ridge above it,
    midway between two parallel bars, or parallel to a source's boundary edge beside it"""
    var = rng.choice(['ridge', 'bars', 'boundary', 'crossed'])
    A, B = Mesh(), Mesh()
    x0, x1 = dy(rng, 4, -0.5, 0.4), dy(rng, 4, 0.5, 1.5)
    h = 2.0 ** -rng.randint(0, 30)
    if var == 'ridge':
        wy, wz = dy(rng, 4, 0.0625, 1), dy(rng, 4, -1, 1)
        B.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, wy, wz))
        B.tp((1.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.5, -wy, wz))
        th = dy(rng, 4, 0.0, 1.0) * h
        A.tp((x0, 0.0, h), (x1, 0.0, h), (x1, 0.0, h + th) if th > 0 else (x1, 0.0, h))
    elif var == 'bars':
        w = 2.0 ** -rng.randint(5, 30)
        for s in (-1.0, 1.0):
            B.tp((0.0, s * h, 0.0), (1.0, s * h, 0.0), (1.0, s * (h + w), 0.0))
            B.tp((0.0, s * h, 0.0), (1.0, s * (h + w), 0.0), (0.0, s * (h + w), 0.0))
        A.tp((x0, 0.0, 0.0), (x1, 0.0, 0.0), (x1, 0.0, dy(rng, 4, -1, 1) * h))
    elif var == 'boundary':
        B, _ = grid(lambda u, v: (u, v, 0.0), rng.randint(1, 3), rng.randint(1, 3), pick_diag(rng), rng)
        z = rng.choice([0.0, h])
        A.tp((x0, -h, z), (x1, -h, z), ((x0 + x1) / 2, -h - dy(rng, 4, 0, 1), z))
    else:
        B.tp((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 0.0, 0.0))
        A.tp((0.5, -0.5, h), (0.5, 0.5, h), (0.5, 0.5, h))
        if rng.random() < 0.5:
            A.tp((0.25, 0.0, h), (0.75, 0.0, h), (0.75, 0.0, h))
    X = xf(rng, exact_prob=0.6)
    return X(A, B) + (f'{var} h={h:.3g}',)


def _tiny_rot(rng, far):
    A, nm, f, nu, nv = surf_mesh(rng, mild=far and rng.random() < 0.5, max_cells=30)
    ang = sgn(rng) * lu(rng, -14, -4)
    about = rng.choice(['vertex', 'edge', 'centroid', 'point'])
    t = rng.choice(A.f)
    if about == 'vertex':
        c = A.v[t[0]]
        ax = rng.choice([rand_dir(rng), face_normal(A, t), unit(sub(A.v[t[1]], A.v[t[0]]))])
    elif about == 'edge':
        c = A.v[t[0]]
        ax = unit(sub(A.v[t[1]], A.v[t[0]]))
    elif about == 'centroid':
        c = mul((sum(p[0] for p in A.v), sum(p[1] for p in A.v), sum(p[2] for p in A.v)), 1 / len(A.v))
        ax = rand_dir(rng)
    else:
        c = add(A.v[t[0]], mul(rand_dir(rng), rng.uniform(0, 2)))
        ax = rand_dir(rng)
    R = axis_rot(ax, ang)
    X = xf(rng, far=far)
    if far and rng.random() < 0.4:  # rotate in world coordinates, about the world image of c
        A2 = X(A)
        cw = X.p(c)
        Rw = axis_rot(mat_ap(X.R, ax), ang)
        B2 = A2.mapv(lambda p: rot_about(Rw, cw, p))
        return A2, B2, f'{nm} {about} ang={ang:.3g} world'
    B = A.mapv(lambda p: rot_about(R, c, p))
    return X(A, B) + (f'{nm} {about} ang={ang:.3g}',)


def k_tiny_rot(rng):
    """a surface vs its copy rotated by 1e-14..1e-4 rad about an axis through a vertex, along an
    edge, through the centroid or a nearby point"""
    return _tiny_rot(rng, False)


def k_tiny_rot_far(rng):
    """a tiny rotation (1e-14..1e-4 rad) far from the origin, done locally or in world coordinates"""
    return _tiny_rot(rng, True)


def k_wedge_bisector(rng):
    """two sources hinged along a line at dihedral angles from 1e-8 rad to pi (nearly coplanar
    to folded), the target in their bisector plane, reaching over the hinge or not"""
    al = rng.choice([lu(rng, -8, 0), rng.uniform(0.1, 3.0), math.pi / 2, math.pi - lu(rng, -8, -1)])
    gap = rng.choice([0.0, 0.0, lu(rng, -10, -1)])
    nu, nv = rng.randint(1, 3), rng.randint(1, 3)
    c, s = math.cos(al / 2), math.sin(al / 2)

    def side(sg):  # points at distance gap..gap+1 from the hinge (the x axis), at angle al/2 off z=0
        return lambda u, v: (u, (gap + v) * c, sg * (gap + v) * s)
    S1, _ = grid(side(1.0), nu, nv, pick_diag(rng), rng)
    S2, _ = grid(side(-1.0), nu, nv, pick_diag(rng), rng)
    B = union(S1, S2)
    y0 = rng.choice([0.0, -rng.uniform(0, 0.5), rng.uniform(0, 0.5)])
    x0, x1 = rng.choice([(0.0, 1.0), (rng.uniform(-0.5, 0.5), rng.uniform(0.5, 1.5))])
    A, _ = grid(lambda u, v: (x0 + (x1 - x0) * u, y0 + v, 0.0), rng.randint(1, 3), rng.randint(1, 3), pick_diag(rng), rng)
    X = xf(rng)
    return X(A, B) + (f'alpha={al:.3g} gap={gap:.3g} y0={y0:.3g}',)


def k_fold_over(rng):
    """decimation fold-overs: an interior vertex moved onto, just short of, just past or well past
    a neighbour (inverted, overlapping triangles), sometimes lifted off the surface; vs the original"""
    nm, f = surface(rng, names=['plane', 'plane', 'sphere', 'saddle', 'height'])
    n = rng.randint(3, 6)
    B, idx = grid(f, n, n, pick_diag(rng), rng)
    v = list(B.v)
    notes = []
    for _ in range(rng.randint(1, 2)):
        i, j = rng.randint(1, n - 1), rng.randint(1, n - 1)
        vi = idx[j][i]
        nb = sorted({x for t in B.f if vi in t for x in t if x != vi})
        q = v[rng.choice(nb)]
        t = rng.choice([1.0, 1 + lu(rng, -12, -1), rng.uniform(1.1, 2.0), 1 - lu(rng, -12, -1)])
        p = lerp(v[vi], q, t)
        if rng.random() < 0.4:
            p = add(p, (0.0, 0.0, sgn(rng) * lu(rng, -10, -1)))
        v[vi] = p
        notes.append(f'{t:.6g}')
    A = Mesh(v, B.f)
    X = xf(rng)
    return X(A, B) + (f'{nm} n={n} t={",".join(notes)}',)


def k_subdiv_far(rng):
    """a coarse nearly flat mesh vs its 1-to-4 subdivision (all or some faces: T-junctions),
    midpoints computed in far world coordinates (off the faces by round-off only)"""
    A, nm, f, nu, nv = surf_mesh(rng, mild=True, max_cells=10)
    X = xf(rng, far=True)
    A = X(A)
    part = rng.random() < 0.3
    B = subdivide(A, rng, 0.5) if part else subdivide(A)
    return A, B, f'{nm} {nu}x{nv} partial={part}'


def k_remesh_far(rng):
    """a planar convex polygon triangulated twice in far world coordinates: a fan from a vertex
    vs a fan from the computed centroid (with a ring of computed inner points) or a zigzag strip"""
    n = rng.randint(4, 12)
    angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    ex = rng.uniform(0.05, 1) if rng.random() < 0.5 else 1.0
    poly = [(0.5 * math.cos(a), 0.5 * ex * math.sin(a), 0.0) for a in angs]
    X = xf(rng, far=True)
    W = [X.p(p) for p in poly]
    A = Mesh(W, [(0, k, k + 1) for k in range(1, n - 1)])
    var = rng.choice(['centroid', 'ring', 'strip'])
    B = Mesh(W, [])
    if var == 'strip':
        lo, hi = 0, n - 1
        tgl = True
        while hi - lo >= 2:
            if tgl:
                B.t(lo, lo + 1, hi)
                lo += 1
            else:
                B.t(lo, hi - 1, hi)
                hi -= 1
            tgl = not tgl
    else:
        c = mul((sum(p[0] for p in W), sum(p[1] for p in W), sum(p[2] for p in W)), 1.0 / n)
        ci = B.av(c)
        if var == 'centroid':
            for k in range(n):
                B.t(ci, k, (k + 1) % n)
        else:
            t = rng.uniform(0.2, 0.8)
            ms = [B.av(lerp(c, W[k], t)) for k in range(n)]
            for k in range(n):
                k1 = (k + 1) % n
                B.t(ci, ms[k], ms[k1])
                B.t(ms[k], k, k1)
                B.t(ms[k], k1, ms[k1])
    return A, B, f'n={n} {var}'


def k_hole_fill(rng):
    """a surface with a hole of removed cells vs the hole filled by a fan from its computed
    centre (off a curved surface), or vs the whole original surface"""
    nm, f = surface(rng)
    nu, nv = grid_dims(rng, 3, 6, 36)
    i0, j0 = rng.randint(0, nu - 2), rng.randint(0, nv - 2)
    i1, j1 = rng.randint(i0 + 1, min(nu, i0 + 3)), rng.randint(j0 + 1, min(nv, j0 + 3))
    skip = {(i, j) for i in range(i0, i1) for j in range(j0, j1)}
    d = pick_diag(rng)
    rs = rng.getstate()
    A, idx = grid(f, nu, nv, d, rng, skip=skip)
    var = rng.choice(['fan', 'original', 'fan_vertex'])
    if var == 'original':
        rng.setstate(rs)
        B, _ = grid(f, nu, nv, d, rng)
    else:
        B = A.copy()
        loop = [idx[j0][i] for i in range(i0, i1)] + [idx[j][i1] for j in range(j0, j1)] + \
               [idx[j1][i] for i in range(i1, i0, -1)] + [idx[j][i0] for j in range(j1, j0, -1)]
        if var == 'fan':
            c = mul((sum(B.v[k][0] for k in loop), sum(B.v[k][1] for k in loop), sum(B.v[k][2] for k in loop)), 1 / len(loop))
            ci = B.av(c)
            for k in range(len(loop)):
                B.t(ci, loop[k], loop[(k + 1) % len(loop)])
        else:
            for k in range(1, len(loop) - 1):
                B.t(loop[0], loop[k], loop[k + 1])
    X = xf(rng)
    return X(A, B) + (f'{nm} {nu}x{nv} hole [{i0},{i1})x[{j0},{j1}) {var}',)


KINDS = [
    ('lod_surface', k_lod_surface),
    ('uv_pole', k_uv_pole),
    ('icosphere', k_icosphere),
    ('f32_export', k_f32_export),
    ('f32_local_far', k_f32_local_far),
    ('quantized', k_quantized),
    ('quantized_far', k_quantized_far),
    ('reindexed', k_reindexed),
    ('reindexed_far', k_reindexed_far),
    ('diag_flip', k_diag_flip),
    ('diag_flip_far', k_diag_flip_far),
    ('edge_collapse', k_edge_collapse),
    ('cap_sliver', k_cap_sliver),
    ('degenerate_faces', k_degenerate_faces),
    ('polyline', k_polyline),
    ('point_vs_mesh', k_point_vs_mesh),
    ('thin_shell', k_thin_shell),
    ('thin_shell_far', k_thin_shell_far),
    ('normal_offset', k_normal_offset),
    ('normal_offset_far', k_normal_offset_far),
    ('strip_vs_tri', k_strip_vs_tri),
    ('tiny_on_big', k_tiny_on_big),
    ('nested_scales', k_nested_scales),
    ('equidistant', k_equidistant),
    ('fan_apex', k_fan_apex),
    ('cube_corner', k_cube_corner),
    ('parallel_edges', k_parallel_edges),
    ('tiny_rot', k_tiny_rot),
    ('tiny_rot_far', k_tiny_rot_far),
    ('wedge_bisector', k_wedge_bisector),
    ('fold_over', k_fold_over),
    ('subdiv_far', k_subdiv_far),
    ('remesh_far', k_remesh_far),
    ('hole_fill', k_hole_fill),
]


def generate(seed):
    kind, fn = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    A, B, note = fn(rng)
    if rng.random() < 0.5:
        A, B = B, A
    for m in (A, B):
        if not m.f:
            raise RuntimeError(f'seed {seed} {kind}: empty mesh')
        if len(m.f) > MAX_TRIS:
            raise RuntimeError(f'seed {seed} {kind}: {len(m.f)} triangles')
        for t in m.f:
            if not all(0 <= i < len(m.v) for i in t):
                raise RuntimeError(f'seed {seed} {kind}: bad index')
        for p in m.v:
            if not all(math.isfinite(x) for x in p):
                raise RuntimeError(f'seed {seed} {kind}: non-finite coordinate')
    return kind, A, B, note


def write_obj(path, m, note):
    used = m.used()  # only vertices used by a face are written
    ren = {old: new for new, old in enumerate(used)}
    lines = [f'# generate_pairs4.py {note}\n']
    for i in used:
        p = m.v[i]
        lines.append(f'v {p[0]!r} {p[1]!r} {p[2]!r}\n')
    for a, b, c in m.f:
        lines.append(f'f {ren[a] + 1} {ren[b] + 1} {ren[c] + 1}\n')
    with open(path, 'w') as fh:
        fh.writelines(lines)


def main(argv):
    if len(argv) != 4:
        sys.stderr.write(__doc__)
        return 2
    out, s0, s1 = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for s in range(s0, s1):
        kind, A, B, note = generate(s)
        note = f'seed={s} kind={kind} {note}'.replace('\n', ' ')
        write_obj(os.path.join(out, f'{s:06d}_{kind}_a.obj'), A, note)
        write_obj(os.path.join(out, f'{s:06d}_{kind}_b.obj'), B, note)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
