#!/usr/bin/env python3
"""Sixth independent generator of degenerate mesh pairs for Hausdorff Lens (issue 8).

Written BLIND: its author did not read tests/independent/generate_pairs*.py,
tests/degenerate_pairs.h, nor the generator part of tests/independent/check_pairs.cpp.
What was read: main(), run_pair() and the failure messages of tests/independent/check_pairs.cpp
(to learn the --pairs interface and the "_far" naming), README.md (formats, welding, tolerances,
the list of what the earlier generators cover) and docs/degenerate-input-history.md (the failure
classes already found, to aim elsewhere).

It aims at what real pipelines produce: simplified meshes against their originals (edge
collapses), remeshed surfaces with vertices on the surface, scans with noise, CAD exports with
T-junctions, cracks and zero-area repair faces, boxes / stacked boxes / prisms with coplanar faces
split differently, fans of valence 20..60, needles and caps at the same place in both meshes,
exact symmetries (90-degree rotations, reflections) so that distances tie exactly, stacked
parallel layers 1e-8..1e-2 apart, subsets, a mesh against itself with one vertex moved, and
placements far from the origin (kinds ending in "_far": near-coincident pairs 1e3..1e8 sizes
from the origin, which the checker holds to an interval no wider than 1e-9 of the diagonal).

Usage: python3 generate_pairs6.py OUTDIR SEED_FROM SEED_TO
Writes OUTDIR/<seed:06d>_<kind>_a.obj and _b.obj for every seed in [SEED_FROM, SEED_TO),
kind = KINDS[seed % len(KINDS)]. Python 3 standard library only; deterministic per seed
(random.Random(seed)); every mesh has 1..80 triangles and finite coordinates written with repr().
Then: build/bin/hlens_check_pairs --pairs OUTDIR --every-target
"""
import math
import os
import random
import sys

MAX_TRIS = 80


# ------------------------------------------------------------------------------------------------
# small vector helpers
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


def unit(a):
    n = norm(a)
    return (a[0] / n, a[1] / n, a[2] / n) if n > 0 else (0.0, 0.0, 1.0)


def mid(a, b):
    return ((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5)


def lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def rand_dir(rng):
    while True:
        v = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        n = norm(v)
        if n > 1e-3:
            return (v[0] / n, v[1] / n, v[2] / n)


def logu(rng, lo, hi):
    """10**U(lo, hi)"""
    return 10.0 ** rng.uniform(lo, hi)


def rot_matrix(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q))
    w, x, y, z = (c / n for c in q)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def axis_rotation(axis, ang):
    """Rodrigues matrix for a unit axis."""
    x, y, z = axis
    c, s = math.cos(ang), math.sin(ang)
    C = 1 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def apply_mat(M, p):
    return (M[0][0] * p[0] + M[0][1] * p[1] + M[0][2] * p[2],
            M[1][0] * p[0] + M[1][1] * p[1] + M[1][2] * p[2],
            M[2][0] * p[0] + M[2][1] * p[1] + M[2][2] * p[2])


def signed_perm(rng):
    perm = [0, 1, 2]
    rng.shuffle(perm)
    sg = [rng.choice((-1.0, 1.0)) for _ in range(3)]
    return lambda p: (sg[0] * p[perm[0]], sg[1] * p[perm[1]], sg[2] * p[perm[2]])


# ------------------------------------------------------------------------------------------------
# meshes: (V, F), V a list of 3-tuples, F a list of index triples
# ------------------------------------------------------------------------------------------------
class Mesh:
    def __init__(self, V=None, F=None):
        self.V = list(V or [])
        self.F = list(F or [])

    def copy(self):
        return Mesh(self.V, self.F)

    def add_vertex(self, p):
        self.V.append(tuple(float(c) for c in p))
        return len(self.V) - 1

    def add_tri(self, a, b, c):
        i = self.add_vertex(a)
        j = self.add_vertex(b)
        k = self.add_vertex(c)
        self.F.append((i, j, k))

    def extend(self, other):
        off = len(self.V)
        self.V.extend(other.V)
        self.F.extend((a + off, b + off, c + off) for a, b, c in other.F)
        return self

    def mapped(self, f):
        return Mesh([f(p) for p in self.V], self.F)

    def compact(self):
        used = sorted({i for t in self.F for i in t})
        remap = {old: new for new, old in enumerate(used)}
        return Mesh([self.V[i] for i in used], [(remap[a], remap[b], remap[c]) for a, b, c in self.F])

    def edges(self):
        es = set()
        for a, b, c in self.F:
            for u, v in ((a, b), (b, c), (c, a)):
                if u != v:
                    es.add((min(u, v), max(u, v)))
        return sorted(es)

    def shuffled(self, rng):
        """Same surface: vertex order and face order shuffled, each face's corners rotated."""
        n = len(self.V)
        perm = list(range(n))
        rng.shuffle(perm)
        V = [None] * n
        for old, new in enumerate(perm):
            V[new] = self.V[old]
        F = []
        for a, b, c in self.F:
            t = (perm[a], perm[b], perm[c])
            r = rng.randrange(3)
            F.append(t[r:] + t[:r])
        rng.shuffle(F)
        return Mesh(V, F)


def quad(F, a, b, c, d, diag):
    """quad a b c d (counter-clockwise) as two triangles; diag 0: a-c, 1: b-d"""
    if diag == 0:
        F.append((a, b, c))
        F.append((a, c, d))
    else:
        F.append((a, b, d))
        F.append((b, c, d))


def diag_of(pattern, i, j, rng):
    if pattern == "/":
        return 0
    if pattern == "\\":
        return 1
    if pattern == "alt":
        return (i + j) % 2
    if pattern == "ring":  # diagonals pointing to the centre-ish
        return 0 if (i < 1) == (j < 1) else 1
    return rng.randrange(2)


PATTERNS = ("/", "\\", "alt", "rand")


def param_grid(nu, nv, surf, rng, pattern="rand", jitter=0.0, u_range=(0.0, 1.0), v_range=(0.0, 1.0)):
    """Grid of nu x nv cells in parameter space mapped by surf(u, v). Jitter moves interior
    parameters in both directions and boundary parameters only along their boundary, so the
    vertices stay on the surface and the boundary curve is the same whatever the jitter."""
    u0, u1 = u_range
    v0, v1 = v_range
    M = Mesh()
    idx = {}
    for i in range(nu + 1):
        for j in range(nv + 1):
            u = i / nu
            v = j / nv
            if jitter > 0:
                if 0 < i < nu:
                    u += rng.uniform(-jitter, jitter) / nu
                if 0 < j < nv:
                    v += rng.uniform(-jitter, jitter) / nv
            idx[i, j] = M.add_vertex(surf(u0 + (u1 - u0) * u, v0 + (v1 - v0) * v))
    for i in range(nu):
        for j in range(nv):
            quad(M.F, idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1], diag_of(pattern, i, j, rng))
    return M


def sphere_patch(t0, dt, p0, dp):
    """The unit sphere over polar angle t0 + dt u and azimuth p0 + dp v, (u, v) in [0,1]^2."""
    def sph(u, v):
        t = t0 + dt * u
        p = p0 + dp * v
        return (math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t))
    return sph


def random_surface(rng, curved=None):
    """A surface patch over [0,1]^2 in parameter space, about unit size."""
    kinds = ["plane", "saddle", "bump", "sphere", "cylinder", "terrain"]
    if curved is True:
        kinds = kinds[1:]
    elif curved is False:
        kinds = ["plane"]
    k = rng.choice(kinds)
    amp = rng.choice((1.0, 0.3, 0.05, logu(rng, -7, -2)))
    if k == "plane":
        asp = rng.choice((1.0, 1.0, 0.5, 2.0, logu(rng, -3, 0)))
        return k, lambda u, v: (u, v * asp, 0.0)
    if k == "saddle":
        return k, lambda u, v: (u, v, amp * (u - 0.5) * (v - 0.5))
    if k == "bump":
        return k, lambda u, v: (u, v, amp * math.sin(math.pi * u) * math.sin(math.pi * v))
    if k == "sphere":
        t0 = rng.uniform(0.2, 1.2)
        dt = rng.uniform(0.2, 1.2)
        p0 = rng.uniform(0, 6)
        dp = rng.uniform(0.2, 1.5)
        return k, sphere_patch(t0, dt, p0, dp)
    if k == "cylinder":
        a = rng.uniform(0.3, 3.0)
        L = rng.uniform(0.3, 2.0)
        return k, lambda u, v: (math.cos(a * u), math.sin(a * u), v * L)
    waves = [(rng.uniform(0.5, 4), rng.uniform(0.5, 4), rng.uniform(0, 6.3), amp * rng.uniform(0.2, 1)) for _ in range(rng.randint(1, 3))]
    return k, lambda u, v: (u, v, sum(a * math.sin(fu * u * 3 + fv * v * 3 + ph) for fu, fv, ph, a in waves))


def surface_mesh(rng, curved=None, max_cells=30):
    name, surf = random_surface(rng, curved)
    nu = rng.randint(1, 6)
    nv = rng.randint(1, max(1, min(6, max_cells // nu)))
    M = param_grid(nu, nv, surf, rng, rng.choice(PATTERNS), rng.choice((0.0, 0.0, 0.3)))
    return M, surf


def collapse(M, rng, k, place):
    """k random edge collapses, as a decimator does. place: 'end' keeps one endpoint, 'mid' the
    midpoint, 'along' a point on the edge; faces that become degenerate are dropped (or, with
    keep_degenerate, some are kept, as sloppy decimators do)."""
    V = list(M.V)
    F = list(M.F)
    keep_deg = rng.random() < 0.15
    for _ in range(k):
        es = Mesh(V, F).edges()
        if len(F) <= 2 or not es:
            break
        u, v = rng.choice(es)
        if rng.random() < 0.5:
            u, v = v, u
        if place == "mid":
            V[u] = mid(V[u], V[v])
        elif place == "along":
            V[u] = lerp(V[u], V[v], rng.random())
        NF = []
        for t in F:
            t = tuple(u if x == v else x for x in t)
            if len(set(t)) == 3 or (keep_deg and rng.random() < 0.3):
                NF.append(t)
        if NF:
            F = NF
    return Mesh(V, F)


# ------------------------------------------------------------------------------------------------
# kinds (each returns A, B in a local frame of about unit size, plus the transform policy)
# ------------------------------------------------------------------------------------------------
def k_collapse_grid(rng, far=False):
    name, surf = random_surface(rng, curved=rng.random() < 0.7)
    nu, nv = rng.randint(3, 6), rng.randint(3, 6)
    A = param_grid(nu, nv, surf, rng, rng.choice(PATTERNS))
    n = len(A.F)
    B = collapse(A, rng, rng.randint(1, max(1, n // 4)) if not far else rng.randint(1, 3), rng.choice(("end", "mid", "along")))
    if rng.random() < 0.3:
        A, B = B, A
    return A, B


def k_collapse_sphere(rng):
    # a patch of a sphere (lat-long or a subdivided octant) and its decimation
    if rng.random() < 0.5:
        t0 = rng.uniform(0.1, 1.0)
        p0 = rng.uniform(0, 6)
        span = rng.uniform(0.3, 1.5)
        sph = sphere_patch(t0, span, p0, span)
        A = param_grid(rng.randint(3, 6), rng.randint(3, 6), sph, rng, rng.choice(PATTERNS))
    else:
        n = rng.randint(2, 5)  # octant of an octahedron, subdivided n times per edge, projected
        A = Mesh()
        idx = {}
        for i in range(n + 1):
            for j in range(n + 1 - i):
                k = n - i - j
                p = unit((i / n, j / n, k / n))
                idx[i, j] = A.add_vertex(p)
        for i in range(n):
            for j in range(n - i):
                A.F.append((idx[i, j], idx[i + 1, j], idx[i, j + 1]))
                if i + j + 1 < n:
                    A.F.append((idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1]))
    B = collapse(A, rng, rng.randint(1, max(1, len(A.F) // 3)), rng.choice(("end", "mid", "along")))
    if rng.random() < 0.5:
        B = B.shuffled(rng)
    return A, B


def k_remesh_plane(rng, far=False):
    asp = rng.choice((1.0, 0.5, 2.0, logu(rng, -3, 0)))
    surf = lambda u, v: (u, v * asp, 0.0)
    A = param_grid(rng.randint(1, 5), rng.randint(1, 5), surf, rng, rng.choice(PATTERNS), rng.choice((0.0, 0.4)))
    B = param_grid(rng.randint(1, 5), rng.randint(1, 5), surf, rng, rng.choice(PATTERNS), rng.choice((0.0, 0.3, 0.45)))
    return A, B


def k_remesh_curved(rng, far=False):
    name, surf = random_surface(rng, curved=True)
    A = param_grid(rng.randint(2, 6), rng.randint(2, 6), surf, rng, rng.choice(PATTERNS), rng.choice((0.0, 0.3)))
    B = param_grid(rng.randint(2, 6), rng.randint(2, 6), surf, rng, rng.choice(PATTERNS), rng.choice((0.0, 0.3, 0.45)))
    return A, B


def k_scan_noise(rng, far=False):
    name, surf = random_surface(rng)
    nu, nv = rng.randint(2, 6), rng.randint(2, 6)
    pat = rng.choice(PATTERNS)
    A = param_grid(nu, nv, surf, random.Random(rng.random()), pat)
    eps = logu(rng, -9, -3)
    if rng.random() < 0.6:
        B = A.copy()  # same scan twice, different noise
    else:
        B = param_grid(rng.randint(2, 6), rng.randint(2, 6), surf, rng, rng.choice(PATTERNS), rng.choice((0.0, 0.3)))
    along_z = rng.random() < 0.5
    every = rng.random() < 0.5
    NV = []
    for p in B.V:
        if every or rng.random() < 0.5:
            d = (0.0, 0.0, rng.gauss(0, 1)) if along_z else mul(rand_dir(rng), rng.gauss(0, 1))
            p = add(p, mul(d, eps))
        NV.append(p)
    B = Mesh(NV, B.F)
    return A, B


def fold_map(phi):
    c, s = math.cos(phi), math.sin(phi)

    def f(p):
        x, y, z = p
        if x <= 1.0:
            return p
        return (1.0 + (x - 1.0) * c, y, (x - 1.0) * s)
    return f


def seam_pair(rng, nyl, nyr, nxl, nxr, pl, pr):
    L = param_grid(nxl, nyl, lambda u, v: (u, v, 0.0), rng, pl)
    R = param_grid(nxr, nyr, lambda u, v: (1.0 + u, v, 0.0), rng, pr)
    return L, R


def k_tjunction(rng, far=False):
    phi = rng.choice((0.0, 0.0, math.pi / 2, rng.uniform(0.1, 3.0), logu(rng, -9, -3)))
    fold = fold_map(phi)
    ny1 = rng.randint(1, 3)
    ny2 = ny1 * rng.randint(2, 4) if rng.random() < 0.7 else rng.randint(1, 6)
    if ny2 == ny1:
        ny2 += 1
    nxl, nxr = rng.randint(1, 3), rng.randint(1, 3)
    L, R = seam_pair(rng, ny1, ny2, nxl, nxr, rng.choice(PATTERNS), rng.choice(PATTERNS))
    A = L.copy().extend(R).mapped(fold)
    if rng.random() < 0.3:
        # CAD repair: zero-area triangles along the seam joining the T-vertices to the coarse edges
        for j in range(ny2):
            y0, y1 = j / ny2, (j + 1) / ny2
            A.add_tri((1.0, y0, 0.0), (1.0, y1, 0.0), (1.0, (y0 + y1) / 2, 0.0))
    opt = rng.randrange(3)
    if opt == 0:  # conforming mesh of the same surface
        ny = ny2
        L2, R2 = seam_pair(rng, ny, ny, nxl, nxr, rng.choice(PATTERNS), rng.choice(PATTERNS))
    elif opt == 1:  # the T-junctions on the other side
        L2, R2 = seam_pair(rng, ny2, ny1, nxl, nxr, rng.choice(PATTERNS), rng.choice(PATTERNS))
    else:  # another non-conforming export
        L2, R2 = seam_pair(rng, rng.randint(1, 5), rng.randint(1, 5), rng.randint(1, 3), rng.randint(1, 3), rng.choice(PATTERNS), rng.choice(PATTERNS))
    B = L2.extend(R2).mapped(fold)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def k_crack(rng):
    phi = rng.choice((0.0, 0.0, math.pi / 2, rng.uniform(0.1, 3.0)))
    fold = fold_map(phi)
    ny = rng.randint(1, 5)
    nxl, nxr = rng.randint(1, 3), rng.randint(1, 3)
    pl, pr = rng.choice(PATTERNS), rng.choice(PATTERNS)
    L, R = seam_pair(random.Random(rng.random()), ny, ny, nxl, nxr, pl, pr)
    gap = logu(rng, -12, -5)
    mode = rng.choice(("open", "step", "overlap"))
    RV = []
    for p in R.V:
        if p[0] == 1.0 and rng.random() < 0.7:
            if mode == "open":
                p = (1.0 + gap, p[1], p[2])
            elif mode == "overlap":
                p = (1.0 - gap, p[1], p[2])
            else:
                p = (p[0], p[1], gap)
        RV.append(p)
    A = L.copy().extend(Mesh(RV, R.F)).mapped(fold)
    B = L.copy().extend(R).mapped(fold)  # welded: no crack
    if rng.random() < 0.4:
        L2, R2 = seam_pair(rng, rng.randint(1, 5), rng.randint(1, 5), nxl, nxr, rng.choice(PATTERNS), rng.choice(PATTERNS))
        B = L2.extend(R2).mapped(fold)
    return A, B


def box_faces(lo, hi, subdiv, rng, skip=()):
    """Axis box [lo, hi] with each face a k x l grid (k, l from subdiv), lattice-exact vertices."""
    M = Mesh()
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    faces = [  # origin, e1, e2 (e1 x e2 outward)
        ((x0, y0, z0), (0, y1 - y0, 0), (x1 - x0, 0, 0)),  # bottom -z
        ((x0, y0, z1), (x1 - x0, 0, 0), (0, y1 - y0, 0)),  # top +z
        ((x0, y0, z0), (x1 - x0, 0, 0), (0, 0, z1 - z0)),  # -y
        ((x0, y1, z0), (0, 0, z1 - z0), (x1 - x0, 0, 0)),  # +y
        ((x0, y0, z0), (0, 0, z1 - z0), (0, y1 - y0, 0)),  # -x
        ((x1, y0, z0), (0, y1 - y0, 0), (0, 0, z1 - z0)),  # +x
    ]
    for fi, (o, e1, e2) in enumerate(faces):
        if fi in skip:
            continue
        k, l = subdiv()
        # positions from lattice fractions: o + e1*(i/k) + e2*(j/l) with dyadic k, l: exact
        G = param_grid(k, l, lambda u, v, o=o, e1=e1, e2=e2: (o[0] + e1[0] * u + e2[0] * v, o[1] + e1[1] * u + e2[1] * v, o[2] + e1[2] * u + e2[2] * v),
                       rng, rng.choice(PATTERNS))
        M.extend(G)
    return M


def dyadic(rng, lo, hi, den=16):
    return rng.randint(int(lo * den), int(hi * den)) / den


def k_box_split(rng, far=False):
    dims = tuple(dyadic(rng, 0.25, 1.0) for _ in range(3))
    if rng.random() < 0.2:
        dims = (dims[0], dims[1], rng.choice((2.0 ** -10, 2.0 ** -20, 2.0 ** -30)))  # a plate
    lo = (0.0, 0.0, 0.0)
    sub1 = lambda: (rng.choice((1, 1, 2)), rng.choice((1, 1, 2)))
    A = box_faces(lo, dims, sub1, rng)
    opt = rng.randrange(5) if not far else rng.choice((0, 1, 4))
    skip = ()
    if opt == 3:
        skip = (rng.randrange(6),)  # open box against closed box
    B = box_faces(lo, dims, sub1, rng, skip)
    if opt == 1:  # slightly inset or outset
        e = logu(rng, -12, -3) * rng.choice((-1, 1))
        B = box_faces(tuple(c - e for c in lo), tuple(c + e for c in dims), sub1, rng)
    elif opt == 2:  # a box sitting on a face of the other (coplanar contact), or inside a corner
        d2 = tuple(dyadic(rng, 0.125, 0.5) for _ in range(3))
        base = (dyadic(rng, 0, 0.5), dyadic(rng, 0, 0.5), dims[2] if rng.random() < 0.5 else 0.0)
        B = box_faces(base, add(base, d2), sub1, rng)
    elif opt == 4:  # the same box, faces split differently, vertex order shuffled
        B = B.shuffled(rng)
    return A, B


def k_box_stack(rng):
    a, b = dyadic(rng, 0.25, 1.0), dyadic(rng, 0.25, 1.0)
    c1, c2 = dyadic(rng, 0.125, 0.5), dyadic(rng, 0.125, 0.5)
    one = lambda: (1, 1)
    A = box_faces((0.0, 0.0, 0.0), (a, b, c1 + c2), lambda: (rng.choice((1, 2)), 1), rng)
    opt = rng.randrange(3)
    if opt == 0:  # two boxes stacked: their internal faces coincide with opposite orientations
        B = box_faces((0.0, 0.0, 0.0), (a, b, c1), one, rng).extend(box_faces((0.0, 0.0, c1), (a, b, c1 + c2), one, rng))
    elif opt == 1:  # top box shifted sideways by a hair: side faces nearly coplanar
        d = logu(rng, -12, -4)
        B = box_faces((0.0, 0.0, 0.0), (a, b, c1), one, rng).extend(box_faces((d, 0.0, c1), (a + d, b, c1 + c2), one, rng))
    else:  # a smaller box on top: its bottom lies inside the big box's top face
        B = box_faces((0.0, 0.0, 0.0), (a, b, c1), one, rng).extend(
            box_faces((a / 4, b / 4, c1), (a / 2, b / 2, c1 + c2), one, rng))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def prism(rng, n, h, shift, cap_mode, rows):
    """regular n-gon prism; vertices computed from their index, so shifting the index by `shift`
    rotates the prism by a symmetry exactly (same points, different triangulation)."""
    M = Mesh()

    def ring(i, z):
        t = 2 * math.pi * ((i + shift) % n) / n
        return (math.cos(t), math.sin(t), z)
    zs = [h * r / rows for r in range(rows + 1)]
    idx = {}
    for r, z in enumerate(zs):
        for i in range(n):
            idx[r, i] = M.add_vertex(ring(i, z))
    for r in range(rows):
        for i in range(n):
            quad(M.F, idx[r, i], idx[r, (i + 1) % n], idx[r + 1, (i + 1) % n], idx[r + 1, i], rng.randrange(2))
    for r, top in ((0, False), (rows, True)):
        mode = cap_mode()
        cap = []
        if mode == "center":
            c = M.add_vertex((0.0, 0.0, zs[r]))
            for i in range(n):
                cap.append((c, idx[r, i], idx[r, (i + 1) % n]))
        elif mode == "fan":
            s = rng.randrange(n)
            for i in range(1, n - 1):
                cap.append((idx[r, s], idx[r, (s + i) % n], idx[r, (s + i + 1) % n]))
        else:  # zigzag strip
            s = rng.randrange(n)
            lo, hi = 0, n - 1
            seq = []
            while lo <= hi:
                seq.append(lo)
                if lo != hi:
                    seq.append(hi)
                lo += 1
                hi -= 1
            seq = [idx[r, (s + q) % n] for q in seq]
            for q in range(len(seq) - 2):
                t = (seq[q], seq[q + 1], seq[q + 2])
                cap.append(t if q % 2 == 0 else (t[1], t[0], t[2]))
        if not top:
            cap = [(a, c, b) for a, b, c in cap]
        M.F.extend(cap)
    return M


def k_prism_split(rng):
    n = rng.randint(3, 8)
    h = rng.choice((1.0, 0.5, 2.0, logu(rng, -6, -1)))
    cm = lambda: rng.choice(("center", "fan", "zig"))
    A = prism(rng, n, h, 0, cm, rng.choice((1, 1, 2)))
    shift = rng.randrange(n) if rng.random() < 0.5 else 0
    B = prism(rng, n, h, shift, cm, rng.choice((1, 1, 2)))
    if rng.random() < 0.2:  # B cut at half height: a subset-like open prism
        B = prism(rng, n, h / 2, shift, cm, 1)
    return A, B


def fan(rng, N, h, closed, apex=None, rim_h=0.0, step=1, sector=None):
    M = Mesh()
    c = M.add_vertex(apex if apex is not None else (0.0, 0.0, h))
    ang = sector if sector is not None else 2 * math.pi
    count = N if closed else N + 1
    rim = [M.add_vertex((math.cos(ang * i / N), math.sin(ang * i / N), rim_h)) for i in range(0, count, step)]
    m = len(rim)
    for i in range(m if closed else m - 1):
        M.F.append((c, rim[i], rim[(i + 1) % m]))
    return M


def k_fan_valence(rng, far=False):
    N = rng.randint(20, 60)
    closed = rng.random() < 0.6
    sector = None if closed else rng.uniform(0.3, 6.0)
    h = rng.choice((0.0, 0.0, logu(rng, -9, -4), rng.uniform(0.05, 1.0)))
    A = fan(rng, N, h, closed, sector=sector)
    opts = ["move", "height", "split"] if far else ["move", "height", "split", "coarse", "rimfan", "other"]
    opt = rng.choice(opts)
    if opt == "move":
        d = logu(rng, -12, -3)
        B = fan(rng, N, h, closed, apex=add((0.0, 0.0, h), mul(rand_dir(rng), d)), sector=sector)
    elif opt == "height":
        B = fan(rng, N, h * (1 + logu(rng, -12, -3)) if h else logu(rng, -12, -6), closed, sector=sector)
    elif opt == "split":  # the apex split in two close vertices (an edge split)
        d = logu(rng, -12, -2)
        B = Mesh()
        a1 = B.add_vertex((d, 0.0, h))
        a2 = B.add_vertex((-d, 0.0, h))
        ang = sector if sector is not None else 2 * math.pi
        count = N if closed else N + 1
        rim = [B.add_vertex((math.cos(ang * i / N), math.sin(ang * i / N), 0.0)) for i in range(count)]
        m = len(rim)
        ne = m if closed else m - 1  # rim edges
        side = [math.cos(ang * (i + 0.5) / N) >= 0 for i in range(ne)]
        for i in range(ne):
            B.F.append((a1 if side[i] else a2, rim[i], rim[(i + 1) % m]))
        # where consecutive rim edges go to different apexes, a triangle over the split edge
        for i in range(ne if closed else ne - 1):
            if side[i] != side[(i + 1) % ne]:
                B.F.append((a1, rim[(i + 1) % m], a2) if side[i] else (a2, rim[(i + 1) % m], a1))
    elif opt == "coarse":
        B = fan(rng, N, h, closed, step=rng.choice((2, 3)), sector=sector)
    elif opt == "rimfan":  # the same polygon triangulated from a rim vertex: valence N-1 there
        B = Mesh()
        ang = sector if sector is not None else 2 * math.pi
        pts = [(math.cos(ang * i / N), math.sin(ang * i / N), 0.0) for i in range(N if closed else N + 1)]
        if not closed:
            pts.append((0.0, 0.0, 0.0))
        ids = [B.add_vertex(p) for p in pts]
        s = rng.randrange(len(ids))
        for i in range(1, len(ids) - 1):
            B.F.append((ids[s], ids[(s + i) % len(ids)], ids[(s + i + 1) % len(ids)]))
    else:  # another fan over the same rim, its apex elsewhere in the plane
        B = fan(rng, N, h, closed, apex=(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), h), sector=sector)
    if rng.random() < 0.3:
        A, B = B, A
    return A, B


def k_needle_cap(rng, far=False):
    name, surf = random_surface(rng, curved=rng.random() < 0.3)
    n1, n2 = rng.randint(1, 3), rng.randint(1, 3)
    pat = rng.choice(PATTERNS)
    A = param_grid(n1, n2, surf, random.Random(rng.random()), pat)
    B = A.copy() if rng.random() < 0.6 else param_grid(n1, n2, surf, rng, rng.choice(PATTERNS))

    def spt():
        return surf(rng.random(), rng.random())

    def normal_at(u, v):
        e = 1e-4
        p = surf(u, v)
        return unit(cross(sub(surf(u + e, v), p), sub(surf(u, v + e), p)))
    for _ in range(rng.randint(1, 5)):
        kind = rng.choice(("needle_flat", "needle_up", "cap_flat", "cap_up", "spike"))
        u, v = rng.random(), rng.random()
        p = surf(u, v)
        nrm = normal_at(u, v)
        e = logu(rng, -12, -4)
        t = unit(sub(spt(), p))
        if kind == "needle_flat":
            tri = (p, add(p, mul(t, e)), spt())
        elif kind == "needle_up":
            tri = (p, add(p, mul(t, e)), add(p, mul(nrm, rng.uniform(0.05, 0.5))))
        elif kind == "cap_flat":
            a, b = p, spt()
            tri = (a, b, add(mid(a, b), mul(unit(cross(nrm, sub(b, a))), e)))
        elif kind == "cap_up":
            a, b = p, spt()
            tri = (a, b, add(mid(a, b), mul(nrm, e)))
        else:  # needle standing on the surface: two vertices e apart at its foot
            top = add(p, mul(nrm, rng.uniform(0.05, 0.5)))
            tri = (p, add(p, mul(rand_dir(rng), e)), top)
        A.add_tri(*tri)
        var = rng.choice(("same", "same", "jitter", "perm", "split"))
        if var == "same":
            B.add_tri(*tri)
        elif var == "jitter":
            q = list(tri)
            i = rng.randrange(3)
            q[i] = add(q[i], mul(rand_dir(rng), logu(rng, -15, -8)))
            B.add_tri(*q)
        elif var == "perm":
            B.add_tri(tri[2], tri[1], tri[0])
        else:  # split at the midpoint of its longest edge
            L = [norm(sub(tri[(i + 1) % 3], tri[i])) for i in range(3)]
            i = L.index(max(L))
            a, b, c = tri[i], tri[(i + 1) % 3], tri[(i + 2) % 3]
            m = mid(a, b)
            B.add_tri(a, m, c)
            B.add_tri(m, b, c)
    if rng.random() < 0.3:
        A, B = B, A
    return A, B


def sym_ops():
    return {
        "rot90": lambda p: (-p[1], p[0], p[2]),
        "rot180": lambda p: (-p[0], -p[1], p[2]),
        "rot270": lambda p: (p[1], -p[0], p[2]),
        "mirror_x": lambda p: (-p[0], p[1], p[2]),
        "mirror_diag": lambda p: (p[1], p[0], p[2]),
        "rot90_x": lambda p: (p[0], -p[2], p[1]),
    }


def k_sym_rot90(rng, far=False):
    n = rng.randint(2, 5)
    c = n / 2.0
    sym_heights = far or rng.random() < 0.5
    hs = {}
    scale_h = rng.choice((1.0, 0.25, 2.0 ** -10, 2.0 ** -30))

    def height(i, j):
        if sym_heights:
            key = tuple(sorted((abs(i - c), abs(j - c))))
        else:
            key = (i, j)
        if key not in hs:
            hs[key] = rng.randint(-8, 8) / 8.0 * scale_h
        return hs[key]
    M = Mesh()
    idx = {}
    for i in range(n + 1):
        for j in range(n + 1):
            idx[i, j] = M.add_vertex((2.0 * i / n - 1.0 if n in (2, 4) else (2 * i - n) / 4.0, 2.0 * j / n - 1.0 if n in (2, 4) else (2 * j - n) / 4.0, height(i, j)))
    pat = rng.choice(PATTERNS)
    for i in range(n):
        for j in range(n):
            quad(M.F, idx[i, j], idx[i + 1, j], idx[i + 1, j + 1], idx[i, j + 1], diag_of(pat, i, j, rng))
    ops = sym_ops()
    name = rng.choice(sorted(ops) if not far else ["rot90", "rot180", "rot270", "mirror_x", "mirror_diag"])
    B = M.mapped(ops[name])
    if name.startswith("mirror"):
        B = Mesh(B.V, [(a, c_, b) for a, b, c_ in B.F])
    if far and rng.random() < 0.5:
        # near-coincident: the symmetric surface with a few heights changed by tiny dyadic amounts
        B = Mesh([(p[0], p[1], p[2] + rng.choice((0.0, 0.0, 2.0 ** -40, -(2.0 ** -30)))) for p in B.V], B.F)
    if rng.random() < 0.5:
        B = B.shuffled(rng)
    return M, B


def k_sym_reflect(rng):
    # a surface crossing the mirror plane x = 0 against its mirror image (they intersect), or a
    # hinge / V made of a plate and its mirror image against the same with another split
    opt = rng.randrange(3)
    n = rng.choice((2, 4))
    if opt == 0:
        s = rng.choice((0.5, 0.25, 1.0, 2.0 ** -20))
        M = param_grid(n, n, lambda u, v: (u * 1.5 - 0.5, v, s * (u * 1.5 - 0.5) * (v - 0.25)), rng, rng.choice(PATTERNS))
        B = M.mapped(lambda p: (-p[0], p[1], p[2]))
        return M, B
    if opt == 1:
        s = rng.choice((1.0, 0.5, 2.0 ** -10, 2.0 ** -40))
        P = param_grid(n, n, lambda u, v: (u, v, s * u), rng, rng.choice(PATTERNS))
        A = P.copy().extend(P.mapped(lambda p: (-p[0], p[1], p[2])))
        Q = param_grid(n, n, lambda u, v: (u, v, s * u), rng, rng.choice(PATTERNS))
        B = Q.copy().extend(Q.mapped(lambda p: (-p[0], p[1], p[2])))
        return A, B
    # a box and its mirror image across one of its own symmetry planes (same box, other split)
    A = box_faces((-0.5, 0.0, 0.0), (0.5, 0.75, 0.5), lambda: (rng.choice((1, 2)), 1), rng)
    B = A.mapped(lambda p: (-p[0], p[1], p[2]))
    return A, B


def layers(rng, L, h, z0, n_range, lateral=0.0):
    M = Mesh()
    for i in range(L):
        z = z0 + i * h
        n = rng.randint(*n_range)
        m = rng.randint(*n_range)
        M.extend(param_grid(n, m, lambda u, v, z=z: (u + lateral * i, v, z), rng, rng.choice(PATTERNS)))
    return M


def k_stacked_layers(rng, far=False):
    h = logu(rng, -8, -2)
    L = rng.randint(2, 4)
    A = layers(rng, L, h, 0.0, (1, 3))
    opts = ["same", "half", "count"] if far else ["same", "half", "count", "lateral"]
    opt = rng.choice(opts)
    if opt == "same":
        B = layers(rng, L, h, 0.0, (1, 3))
    elif opt == "half":
        B = layers(rng, L, h, h / 2, (1, 3))
    elif opt == "count":
        B = layers(rng, max(1, L + rng.choice((-1, 1))), h, 0.0, (1, 3))
    else:
        B = layers(rng, L, h, 0.0, (1, 3), lateral=rng.uniform(0.1, 0.6))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def any_mesh(rng):
    r = rng.random()
    if r < 0.45:
        return surface_mesh(rng)[0]
    if r < 0.6:
        dims = tuple(dyadic(rng, 0.25, 1.0) for _ in range(3))
        return box_faces((0.0, 0.0, 0.0), dims, lambda: (rng.choice((1, 2)), 1), rng)
    if r < 0.75:
        return prism(rng, rng.randint(3, 8), rng.uniform(0.2, 1.0), 0, lambda: rng.choice(("center", "fan", "zig")), 1)
    if r < 0.9:
        return fan(rng, rng.randint(20, 60), rng.choice((0.0, 0.3)), rng.random() < 0.5, sector=rng.uniform(1, 6))
    return k_tjunction(rng)[0]


def k_subset(rng, far=False):
    A = any_mesh(rng)
    k = rng.randint(1, max(1, len(A.F) - 1)) if rng.random() < 0.8 else len(A.F)
    F = rng.sample(A.F, k)
    B = Mesh(A.V, F).shuffled(rng)
    if rng.random() < 0.3:
        A, B = B, A
    return A, B


def k_moved_vertex(rng, far=False):
    A = any_mesh(rng)
    valence = {}
    for t in A.F:
        for i in t:
            valence[i] = valence.get(i, 0) + 1
    used = sorted(valence)
    v = max(used, key=lambda i: valence[i]) if rng.random() < 0.3 else rng.choice(used)
    d = logu(rng, -12, -3)
    mode = rng.choice(("normal", "random", "tangent"))
    # an approximate normal at v from its faces
    nrm = (0.0, 0.0, 0.0)
    for a, b, c in A.F:
        if v in (a, b, c):
            nrm = add(nrm, cross(sub(A.V[b], A.V[a]), sub(A.V[c], A.V[a])))
    nrm = unit(nrm)
    if mode == "normal":
        dirn = nrm
    elif mode == "random":
        dirn = rand_dir(rng)
    else:
        dirn = unit(cross(nrm, rand_dir(rng)))
    V = list(A.V)
    V[v] = add(V[v], mul(dirn, d))
    B = Mesh(V, A.F)
    if rng.random() < 0.5:
        B = B.shuffled(rng)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def k_zero_area(rng):
    A = surface_mesh(rng, max_cells=16)[0]
    B = A.copy()
    for _ in range(rng.randint(1, 8)):
        opt = rng.choice(("on_edge", "point", "repeat", "spike", "cluster"))
        a, b, c = [A.V[x] for x in rng.choice(A.F)]
        if opt == "on_edge":  # collinear triple along an edge of the mesh (a CAD repair face)
            A.add_tri(a, lerp(a, b, rng.random()), b)
        elif opt == "point":
            A.add_tri(a, a, a)
        elif opt == "repeat":
            A.add_tri(a, b, a)
        elif opt == "spike":  # zero-area face standing off the surface
            nrm = unit(cross(sub(b, a), sub(c, a)))
            t = rng.choice((logu(rng, -12, -6), rng.uniform(0.01, 0.3)))
            A.add_tri(a, add(a, mul(nrm, t)), add(a, mul(nrm, 2 * t)))
        else:  # three points within 1e-12..1e-8 of a mesh vertex
            e = logu(rng, -12, -8)
            A.add_tri(a, add(a, mul(rand_dir(rng), e)), add(a, mul(rand_dir(rng), e)))
    if rng.random() < 0.4:
        A, B = B, A
    return A, B


def k_dup_faces(rng):
    A = any_mesh(rng)
    while len(A.F) > 60:
        A = Mesh(A.V, A.F[: len(A.F) // 2]).compact()
    B = A.copy()
    for _ in range(rng.randint(1, min(15, MAX_TRIS - len(A.F)))):
        t = rng.choice(A.F)
        opt = rng.randrange(4)
        if opt == 0:
            A.F.append(t)
        elif opt == 1:
            A.F.append((t[1], t[2], t[0]))
        elif opt == 2:
            A.F.append((t[0], t[2], t[1]))  # flipped
        else:  # separate vertices at the same coordinates (welded by the loader)
            A.add_tri(A.V[t[0]], A.V[t[1]], A.V[t[2]])
    if rng.random() < 0.4:
        B = B.shuffled(rng)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def k_perp_fold(rng):
    n1, n2, n3, n4 = (rng.randint(1, 3) for _ in range(4))
    floor = lambda u, v: (u, v, 0.0)
    wall = lambda u, v: (0.0, v, u)
    A = param_grid(n1, n2, floor, rng, rng.choice(PATTERNS)).extend(param_grid(n3, n4, wall, rng, rng.choice(PATTERNS)))
    opt = rng.randrange(4)
    if opt == 0:  # same L, split differently
        B = param_grid(rng.randint(1, 3), rng.randint(1, 3), floor, rng, rng.choice(PATTERNS)).extend(
            param_grid(rng.randint(1, 3), rng.randint(1, 3), wall, rng, rng.choice(PATTERNS)))
    elif opt == 1:  # the wall leaning by a tiny angle
        e = logu(rng, -10, -3) * rng.choice((-1, 1))
        s, c = math.sin(e), math.cos(e)
        B = param_grid(n1, n2, floor, rng, rng.choice(PATTERNS)).extend(
            param_grid(n3, n4, lambda u, v: (-s * u, v, c * u), rng, rng.choice(PATTERNS)))
    elif opt == 2:  # a wall standing on the floor inside it (T), exactly touching or a hair off
        x = rng.choice((0.5, 0.25, rng.random()))
        g = rng.choice((0.0, 0.0, logu(rng, -12, -6), -logu(rng, -12, -6)))
        B = param_grid(n1, n2, floor, rng, rng.choice(PATTERNS)).extend(
            param_grid(n3, n4, lambda u, v: (x, v, g + u * 0.5), rng, rng.choice(PATTERNS)))
    else:  # wall only, floor only: shared edge
        B = param_grid(n3, n4, wall, rng, rng.choice(PATTERNS))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B


def k_tilted_grid(rng):
    A = param_grid(rng.randint(1, 5), rng.randint(1, 5), lambda u, v: (u, v, 0.0), rng, rng.choice(PATTERNS), rng.choice((0.0, 0.3)))
    B = param_grid(rng.randint(1, 5), rng.randint(1, 5), lambda u, v: (u, v, 0.0), rng, rng.choice(PATTERNS), rng.choice((0.0, 0.3)))
    ang = logu(rng, -12, -2) * rng.choice((-1, 1))
    t = rng.uniform(0, math.pi)
    axis = (math.cos(t), math.sin(t), 0.0)
    piv = (rng.random(), rng.random(), 0.0)
    R = axis_rotation(axis, ang)
    B = B.mapped(lambda p: add(piv, apply_mat(R, sub(p, piv))))
    return A, B


def strip(rng, bottom, top, w):
    """triangulate between polylines y=0 (xs bottom) and y=w (xs top), both from 0 to 1"""
    M = Mesh()
    bi = [M.add_vertex((x, 0.0, 0.0)) for x in bottom]
    ti = [M.add_vertex((x, w, 0.0)) for x in top]
    i = j = 0
    while i < len(bi) - 1 or j < len(ti) - 1:
        if i < len(bi) - 1 and (j == len(ti) - 1 or bottom[i + 1] <= top[j + 1]):
            M.F.append((bi[i], bi[i + 1], ti[j]))
            i += 1
        else:
            M.F.append((bi[i], ti[j + 1], ti[j]))
            j += 1
    return M


def clustered_xs(rng, k):
    xs = {0.0, 1.0}
    while len(xs) < k:
        c = rng.random()
        xs.add(c)
        for _ in range(rng.randint(0, 3)):
            x = c + rng.uniform(-1, 1) * logu(rng, -12, -5)
            if 0.0 < x < 1.0:
                xs.add(x)
    return sorted(xs)[: k - 1] + [1.0] if len(xs) > k else sorted(xs)


def k_sliver_strip(rng):
    w = rng.choice((1.0, 0.1, logu(rng, -9, -2)))
    A = strip(rng, clustered_xs(rng, rng.randint(2, 20)), clustered_xs(rng, rng.randint(2, 20)), w)
    opt = rng.randrange(3)
    if opt == 0:
        B = strip(rng, [0.0, 1.0], [0.0, 1.0], w)
    elif opt == 1:
        B = strip(rng, clustered_xs(rng, rng.randint(2, 20)), clustered_xs(rng, rng.randint(2, 20)), w)
    else:
        B = param_grid(rng.randint(1, 6), 1, lambda u, v: (u, v * w, 0.0), rng, rng.choice(PATTERNS))
    if rng.random() < 0.3:  # nearly coplanar: B lifted or tilted by a hair
        e = logu(rng, -12, -5) * w
        B = B.mapped(lambda p: (p[0], p[1], p[2] + e * p[0]))
    return A, B


def k_sphere_tess(rng):
    """the same sphere cap tessellated two ways (lat-long vs octant subdivision-like), vertices on
    the sphere: the two surfaces cross each other everywhere"""
    r = 1.0
    t1 = rng.uniform(0.3, 1.4)
    na, nb = rng.randint(3, 8), rng.randint(3, 8)
    ma, mb = rng.randint(1, 4), rng.randint(1, 4)

    def cap(nseg, nring, twist):
        M = Mesh()
        pole = M.add_vertex((0.0, 0.0, r))
        rings = []
        for k in range(1, nring + 1):
            t = t1 * k / nring
            rings.append([M.add_vertex((r * math.sin(t) * math.cos(2 * math.pi * (i + twist * k) / nseg),
                                        r * math.sin(t) * math.sin(2 * math.pi * (i + twist * k) / nseg), r * math.cos(t)))
                          for i in range(nseg)])
        for i in range(nseg):
            M.F.append((pole, rings[0][i], rings[0][(i + 1) % nseg]))
        for k in range(nring - 1):
            for i in range(nseg):
                quad(M.F, rings[k][i], rings[k + 1][i], rings[k + 1][(i + 1) % nseg], rings[k][(i + 1) % nseg], rng.randrange(2))
        return M
    while na * (2 * ma - 1) > MAX_TRIS:
        ma -= 1
    while nb * (2 * mb - 1) > MAX_TRIS:
        mb -= 1
    A = cap(na, ma, 0.0)
    B = cap(nb, mb, rng.choice((0.0, 0.5)))
    return A, B


# ------------------------------------------------------------------------------------------------
# kinds table: name -> (function, exact transform only)
# ------------------------------------------------------------------------------------------------
KIND_FUNCS = [
    ("collapse_grid", lambda r: k_collapse_grid(r), False),
    ("collapse_sphere", k_collapse_sphere, False),
    ("remesh_plane", lambda r: k_remesh_plane(r), False),
    ("remesh_curved", lambda r: k_remesh_curved(r), False),
    ("scan_noise", lambda r: k_scan_noise(r), False),
    ("tjunction", lambda r: k_tjunction(r), False),
    ("crack", k_crack, False),
    ("box_split", lambda r: k_box_split(r), None),
    ("box_stack", k_box_stack, None),
    ("prism_split", k_prism_split, False),
    ("fan_valence", lambda r: k_fan_valence(r), False),
    ("needle_cap", lambda r: k_needle_cap(r), False),
    ("sym_rot90", lambda r: k_sym_rot90(r), True),
    ("sym_reflect", k_sym_reflect, True),
    ("stacked_layers", lambda r: k_stacked_layers(r), None),
    ("subset", lambda r: k_subset(r), False),
    ("moved_vertex", lambda r: k_moved_vertex(r), False),
    ("zero_area", k_zero_area, False),
    ("dup_faces", k_dup_faces, False),
    ("perp_fold", k_perp_fold, None),
    ("tilted_grid", k_tilted_grid, False),
    ("sliver_strip", k_sliver_strip, None),
    ("sphere_tess", k_sphere_tess, False),
    ("collapse_grid_far", lambda r: k_collapse_grid(r, True), False),
    ("remesh_plane_far", lambda r: k_remesh_plane(r, True), None),
    ("remesh_curved_far", lambda r: k_remesh_curved(r, True), False),
    ("scan_noise_far", lambda r: k_scan_noise(r, True), False),
    ("moved_vertex_far", lambda r: k_moved_vertex(r, True), False),
    ("box_split_far", lambda r: k_box_split(r, True), None),
    ("tjunction_far", lambda r: k_tjunction(r, True), False),
    ("needle_cap_far", lambda r: k_needle_cap(r, True), False),
    ("sym_rot90_far", lambda r: k_sym_rot90(r, True), True),
    ("fan_valence_far", lambda r: k_fan_valence(r, True), False),
    ("stacked_layers_far", lambda r: k_stacked_layers(r, True), None),
    ("crack_far", k_crack, False),
    ("dup_faces_far", k_dup_faces, False),
]
KINDS = [k for k, _, _ in KIND_FUNCS]


def place(rng, A, B, exact, far):
    """One similarity (plus offset) applied to both meshes, vertex by vertex, so equal local
    coordinates stay equal. exact True: signed permutation, power-of-two scale, dyadic offset
    (no rounding at all); None: either; False: a general rotation half the time."""
    if exact is None:
        exact = rng.random() < 0.5
    s = logu(rng, -6, 6)
    if exact:
        s = 2.0 ** round(math.log2(s))
        P = signed_perm(rng)
    elif rng.random() < 0.4:
        P = signed_perm(rng)
    else:
        R = rot_matrix(rng)
        P = lambda p: apply_mat(R, p)
    if far:
        dist = logu(rng, 3, 8)
        d = rand_dir(rng) if rng.random() < 0.6 else signed_perm(rng)((1.0, 0.0, 0.0))
        if exact:
            off = tuple(round(c * dist * 64) / 64 * s for c in d)  # dyadic: exact sums
        else:
            off = tuple(c * dist * s for c in d)
    else:
        r = rng.random()
        if r < 0.5:
            off = (0.0, 0.0, 0.0)
        elif exact:
            off = tuple(rng.randint(-64, 64) / 8 * s for _ in range(3))
        else:
            off = tuple(rng.uniform(-10, 10) * s for _ in range(3))
    f = lambda p: add(mul(P(p), s), off) if exact else add(P(mul(p, s)), off)
    return A.mapped(f), B.mapped(f)


def generate(seed):
    rng = random.Random(seed)
    kind, fn, exact = KIND_FUNCS[seed % len(KIND_FUNCS)]
    for _ in range(50):  # a draw with too many triangles is drawn again (same rng: deterministic)
        A, B = fn(rng)
        if 1 <= len(A.F) <= MAX_TRIS and 1 <= len(B.F) <= MAX_TRIS:
            break
    A, B = place(rng, A, B, exact, kind.endswith("_far"))
    A, B = A.compact(), B.compact()
    for M in (A, B):
        if not 1 <= len(M.F) <= MAX_TRIS:
            raise RuntimeError("seed %d (%s): %d triangles" % (seed, kind, len(M.F)))
        for p in M.V:
            if not all(math.isfinite(c) for c in p):
                raise RuntimeError("seed %d (%s): non-finite coordinate" % (seed, kind))
    return kind, A, B


def write_obj(path, M, comment):
    with open(path, "w") as f:
        f.write("# %s\n" % comment)
        for p in M.V:
            f.write("v %s %s %s\n" % (repr(p[0]), repr(p[1]), repr(p[2])))
        for a, b, c in M.F:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: %s OUTDIR SEED_FROM SEED_TO\nkinds (%d): %s\n" % (argv[0], len(KINDS), " ".join(KINDS)))
        return 2
    out, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for seed in range(lo, hi):
        kind, A, B = generate(seed)
        base = os.path.join(out, "%06d_%s" % (seed, kind))
        write_obj(base + "_a.obj", A, "generate_pairs6.py seed %d kind %s mesh A" % (seed, kind))
        write_obj(base + "_b.obj", B, "generate_pairs6.py seed %d kind %s mesh B" % (seed, kind))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
