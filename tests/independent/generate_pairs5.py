#!/usr/bin/env python3
"""Fifth independent generator of random degenerate mesh pairs for Hausdorff Lens (issue 8).

Written BLIND: its author did not read tests/independent/generate_pairs.py, generate_pairs3.py,
generate_pairs4.py, tests/degenerate_pairs.h nor the generator part of
tests/independent/check_pairs.cpp; only the checker's main(), its failure messages, the README and
docs/degenerate-input-history.md. Its constructions are its own, so that its blind spots differ.

Usage:  python3 tests/independent/generate_pairs5.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/<seed:06d>_<kind>_a.obj and OUTDIR/<seed:06d>_<kind>_b.obj for every seed in
[SEED_FROM, SEED_TO), kind = KINDS[seed % len(KINDS)]; then
        build/bin/hlens_check_pairs --pairs OUTDIR
Python 3 standard library only; each pair depends on its seed alone (random.Random(seed)).
Every mesh has 1..80 triangles and finite coordinates (printed with repr, so they round-trip).
Kinds ending in "_far" are near-coincident pairs moved 1e3..1e8 times their size from the origin
(the checker then requires a certified interval no wider than 1e-9 of the diagonal).

Most kinds are built in a local frame of size ~1 and then placed by one of: nothing (exact
coordinates kept), a signed axis permutation with a power-of-two scale (still exact), or a random
similarity (a rotation that is not axis-aligned, scale 10**U(-6,6), an offset up to 1e4 sizes).

Kinds:
  coplanar_retri     one convex polygon (vertices on an ellipse) triangulated two ways: fans from
                     different corners, a centre fan, a zigzag, a moved copy, a grid over it
  tilted_grid        grids of different resolution and in-plane angle, one tilted by 1e-12..1e-2
                     about an in-plane axis and/or lifted by up to 1e-4
  sliver_strip       zigzag strips of height 1e-12..1e-4 against coplanar grids, shifted or
                     crossing strips, needle fans, triangles hovering above
  perp_stand         a wall standing on, crossing or hovering over a grid, on a grid line, a
                     diagonal or anywhere
  boolean_cross      a bent sheet (the union of two half planes) against the two crossing planes it
                     came from, conforming along the crossing line or with T-junctions there
  shared_edge_hinge  two fans sharing one edge at dihedral 0, pi, pi/2, nearly 0 or nearly pi
  zero_area          meshes with collinear triples, coincident-vertex triangles, point triangles,
                     zero-area segments standing off the surface; sometimes a mesh of only those
  dup_faces          closed or open meshes with faces repeated (reversed, rotated, own vertices)
  t_junction         a square against the same square with T-junctions along seams and edges
  vertex_touch       pyramids / cones touching the other mesh at one point only (apex to apex,
                     apex on a vertex, on an edge, inside a face)
  cyl_lod            a CAD cylinder at coarse vs fine tessellation, caps fanned to a pole, phases
  cone_fan           cones (steep to nearly flat) at different tessellations, bicones, cone vs disc
  sphere_lod         UV spheres (pole fans) vs subdivided octahedra / icosahedra / other UV axes
  seam_strip         long thin bands around or along a cylinder's seam against the cylinder
  regular_ties       regular polygons and k-fold symmetric copies around an axis: exact ties
  voxel_stairs       a voxelised (stair-step) surface against the smooth plane / cap it samples
  mirror             a height field against its mirror image (through its middle, a vertex, any)
  terrain_plateau    quantised height fields with flat plateaus against other triangulations,
                     the smooth field, or a plane at a plateau's level
  f32_copy           a placed mesh against its float32-rounded copy
  grid_snap          a curved patch against its copy snapped to a coarse grid (2^-k or 10^-k)
  huge_tiny          huge triangles next to tiny ones (1e-7..1e-5) and 1e6 aspect ratios
  collinear_line     fans whose vertices lie on one line, from apexes on either side / off plane
  cocircular         fans whose vertices lie on one circle: centre fan, off-centre fan, cone, chord
                     triangulation
  point_like         triangles whose corners lie within 1e-15..1e-9 of a point, on vertices,
                     edges, faces of the other mesh or near them
  integer_coords     small-integer coordinates (many exact ties), random triangles and grids
  pow2_coords        coordinates that are powers of two (geometric grids), scaled by 2^E
  rot_hinge          a bent mesh against itself rotated by 1e-10..1e-1 about an axis through a
                     vertex or along an edge, under a random similarity
  scaled_copy        a patch / closed mesh against a copy scaled about a point by 1 + 1e-9..1e-1
  coinc_noise_far    a copy with vertices moved by 1e-9..1e-3 of the size, far away
  coinc_retess_far   a slightly curved patch tessellated twice, far away
  f32_far            a mesh 1e3..3e5 sizes from the origin against its float32 rounding
  snap_far           a mesh far away against its copy rounded in world coordinates to a step
  dup_offset_far     a plane with duplicated faces against a copy offset by 1e-9..1e-3, far away
"""
import math
import os
import random
import struct
import sys

MAXT = 80


# ------------------------------------------------------------------------------------------------
# Geometry helpers
# ------------------------------------------------------------------------------------------------
def vadd(a, b): return (a[0] + b[0], a[1] + b[1], a[2] + b[2])
def vsub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def vmul(a, s): return (a[0] * s, a[1] * s, a[2] * s)
def vdot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def vcross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def vlen(a): return math.sqrt(vdot(a, a))
def vunit(a):
    n = vlen(a)
    return vmul(a, 1.0 / n) if n > 0 else (1.0, 0.0, 0.0)
def lerp(a, b, t): return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def rand_unit(rng):
    while True:
        v = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        n = vlen(v)
        if n > 1e-6:
            return vmul(v, 1.0 / n)


def mat_apply(R, p):
    return (R[0][0] * p[0] + R[0][1] * p[1] + R[0][2] * p[2],
            R[1][0] * p[0] + R[1][1] * p[1] + R[1][2] * p[2],
            R[2][0] * p[0] + R[2][1] * p[1] + R[2][2] * p[2])


def quat_rot(rng):
    w, x, y, z = (rng.gauss(0, 1) for _ in range(4))
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def axis_rot(axis, ang):
    x, y, z = vunit(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1 - c
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def signed_perm(rng):
    perm = [0, 1, 2]
    rng.shuffle(perm)
    R = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        R[i][perm[i]] = rng.choice((-1.0, 1.0))
    return R


def U(rng, a, b): return rng.uniform(a, b)
def E(rng, a, b): return 10.0 ** rng.uniform(a, b)


# ------------------------------------------------------------------------------------------------
# Mesh
# ------------------------------------------------------------------------------------------------
class Mesh:
    def __init__(self):
        self.v = []
        self.f = []

    def add(self, p):
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.v) - 1

    def face(self, i, j, k):
        self.f.append((i, j, k))

    def tri(self, a, b, c):
        self.f.append((self.add(a), self.add(b), self.add(c)))

    def extend(self, o):
        base = len(self.v)
        self.v.extend(o.v)
        self.f.extend((a + base, b + base, c + base) for a, b, c in o.f)
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

    def shuffled(self, rng):
        m = self.copy()
        rng.shuffle(m.f)
        return m


def union(*ms):
    out = Mesh()
    for m in ms:
        out.extend(m)
    return out


def grid(m, nx, ny, x0, y0, w, h, zf=None, diag="rand", rng=None, fn=None):
    """nx x ny cells over [x0, x0+w] x [y0, y0+h]; z = zf(x, y); fn maps the point afterwards."""
    idx = []
    for i in range(nx + 1):
        row = []
        for j in range(ny + 1):
            x = x0 + w * i / nx
            y = y0 + h * j / ny
            p = (x, y, zf(x, y) if zf else 0.0)
            row.append(m.add(fn(p) if fn else p))
        idx.append(row)
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = idx[i][j], idx[i + 1][j], idx[i + 1][j + 1], idx[i][j + 1]
            if diag == "a":
                o = 0
            elif diag == "b":
                o = 1
            elif diag == "alt":
                o = (i + j) % 2
            else:
                o = rng.randrange(2)
            if o == 0:
                m.face(a, b, c); m.face(a, c, d)
            else:
                m.face(a, b, d); m.face(b, c, d)
    return idx


def stitch(m, low, high, key):
    """Triangulate between two polylines (vertex index lists, both increasing along key)."""
    i = j = 0
    while i < len(low) - 1 or j < len(high) - 1:
        adv_low = j == len(high) - 1 or (i < len(low) - 1 and key(low[i + 1]) <= key(high[j + 1]))
        if adv_low:
            m.face(low[i], low[i + 1], high[j]); i += 1
        else:
            m.face(low[i], high[j + 1], high[j]); j += 1


def fan(m, apex, ring, closed=False):
    n = len(ring)
    for i in range(n if closed else n - 1):
        m.face(apex, ring[i], ring[(i + 1) % n])


def smooth_fn(rng, amp):
    terms = [(rng.uniform(-1, 1), rng.uniform(0.5, 3.0), rng.uniform(0.5, 3.0), rng.uniform(0, 6.3))
             for _ in range(rng.randint(1, 3))]
    return lambda x, y: amp * sum(a * math.sin(f * x + g * y + p) for a, f, g, p in terms)


def sorted_params(rng, n, exact_ends=True):
    ts = sorted(rng.random() for _ in range(n))
    if exact_ends:
        ts = [0.0] + ts + [1.0]
    return ts


def tube(m, n, rings, H, radius=1.0, phase=0.0, z0=0.0):
    rows = []
    for r in range(rings + 1):
        z = z0 + H * r / rings
        rows.append([m.add((radius * math.cos(phase + 2 * math.pi * k / n), radius * math.sin(phase + 2 * math.pi * k / n), z))
                     for k in range(n)])
    for r in range(rings):
        lo, hi = rows[r], rows[r + 1]
        for k in range(n):
            k1 = (k + 1) % n
            m.face(lo[k], lo[k1], hi[k1]); m.face(lo[k], hi[k1], hi[k])
    return rows


def uv_sphere(m, cols, rows, R=1.0, phase=0.0, Rot=None):
    def P(p): return mat_apply(Rot, p) if Rot else p
    north = m.add(P((0.0, 0.0, R)))
    south = m.add(P((0.0, 0.0, -R)))
    ring = []
    for i in range(1, rows):
        th = math.pi * i / rows
        ring.append([m.add(P((R * math.sin(th) * math.cos(phase + 2 * math.pi * k / cols),
                              R * math.sin(th) * math.sin(phase + 2 * math.pi * k / cols), R * math.cos(th))))
                     for k in range(cols)])
    for k in range(cols):
        k1 = (k + 1) % cols
        m.face(north, ring[0][k], ring[0][k1])
        m.face(south, ring[-1][k1], ring[-1][k])
        for i in range(rows - 2):
            a, b, c, d = ring[i][k], ring[i][k1], ring[i + 1][k1], ring[i + 1][k]
            m.face(a, d, c); m.face(a, c, b)


def octa_sphere(m, level, R=1.0):
    pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return subdiv_sphere(m, pts, faces, level, R)


def icosa_sphere(m, level, R=1.0):
    t = (1 + math.sqrt(5)) / 2
    pts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
           (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
             (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
             (8, 6, 7), (9, 8, 1)]
    return subdiv_sphere(m, pts, faces, level, R)


def subdiv_sphere(m, pts, faces, level, R):
    pts = [vmul(vunit(p), R) for p in pts]
    for _ in range(level):
        cache = {}
        nf = []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                pts.append(vmul(vunit(lerp(pts[a], pts[b], 0.5)), R))
                cache[key] = len(pts) - 1
            return cache[key]
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = nf
    base = len(m.v)
    for p in pts:
        m.add(p)
    for a, b, c in faces:
        m.face(a + base, b + base, c + base)


def closed_base(rng):
    m = Mesh()
    k = rng.randrange(4)
    if k == 0:  # tetrahedron
        p = [m.add(q) for q in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))]
        for f in ((0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)):
            m.face(p[f[0]], p[f[1]], p[f[2]])
    elif k == 1:  # cube
        p = [m.add((x, y, z)) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
        quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        for a, b, c, d in quads:
            if rng.random() < 0.5:
                m.face(p[a], p[b], p[c]); m.face(p[a], p[c], p[d])
            else:
                m.face(p[a], p[b], p[d]); m.face(p[b], p[c], p[d])
    elif k == 2:
        octa_sphere(m, 0)
    else:
        grid(m, rng.randint(1, 3), rng.randint(1, 3), 0, 0, 1, 1, smooth_fn(rng, U(rng, 0, 0.4)), "rand", rng)
    return m


def curved_patch(rng, nmax=5):
    m = Mesh()
    k = rng.randrange(3)
    n = rng.randint(2, nmax)
    if k == 0:
        grid(m, n, n, 0, 0, 1, 1, smooth_fn(rng, U(rng, 0.05, 0.5)), "rand", rng)
    elif k == 1:  # piece of a sphere
        R = E(rng, 0, 1)
        grid(m, n, n, -0.5, -0.5, 1, 1, None, "alt", rng,
             fn=lambda p: (p[0], p[1], math.sqrt(max(R * R - p[0] ** 2 - p[1] ** 2, 0.0)) - R))
    else:  # piece of a cylinder
        R = E(rng, -0.3, 1)
        grid(m, n, n, -0.5, -0.5, 1, 1, None, "rand", rng,
             fn=lambda p: (R * math.sin(p[0] / R), p[1], R * math.cos(p[0] / R) - R))
    return m


# ------------------------------------------------------------------------------------------------
# Kinds (local frame, size ~1). Each returns (A, B, placement).
# ------------------------------------------------------------------------------------------------
def k_coplanar_retri(rng):
    n = rng.randint(4, 12)
    a, b = U(rng, 0.3, 1.0), 1.0
    angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n)) if rng.random() < 0.6 else [2 * math.pi * i / n for i in range(n)]
    poly = [(a * math.cos(t), b * math.sin(t), 0.0) for t in angs]
    A = Mesh()
    ia = [A.add(p) for p in poly]
    s = rng.randrange(n)
    fan(A, ia[s], [ia[(s + i) % n] for i in range(1, n)])
    B = Mesh()
    mode = rng.randrange(5)
    if mode == 0:
        ib = [B.add(p) for p in poly]
        s2 = (s + rng.randint(1, n - 1)) % n
        fan(B, ib[s2], [ib[(s2 + i) % n] for i in range(1, n)])
    elif mode == 1:
        ib = [B.add(p) for p in poly]
        c = B.add((0.0, 0.0, 0.0) if rng.random() < 0.5 else (sum(p[0] for p in poly) / n, sum(p[1] for p in poly) / n, 0.0))
        fan(B, c, ib, closed=True)
    elif mode == 2:
        ib = [B.add(p) for p in poly]
        lo, hi = 0, n - 1
        turn = 0
        while hi - lo >= 2:
            if turn == 0:
                B.face(ib[lo], ib[lo + 1], ib[hi]); lo += 1
            else:
                B.face(ib[lo], ib[hi - 1], ib[hi]); hi -= 1
            turn ^= 1
    elif mode == 3:
        R = axis_rot((0, 0, 1), rng.choice((0.0, U(rng, 0, 6.3), math.pi / n)))
        d = (rng.choice((0.0, U(rng, -0.5, 0.5))), rng.choice((0.0, U(rng, -0.5, 0.5))), 0.0)
        ib = [B.add(vadd(mat_apply(R, p), d)) for p in poly]
        s2 = rng.randrange(n)
        fan(B, ib[s2], [ib[(s2 + i) % n] for i in range(1, n)])
    else:
        k = rng.randint(1, 5)
        grid(B, k, k, -1, -1, 2, 2, None, "rand", rng)
    if rng.random() < 0.3:
        A, B = B, A
    return A, B.shuffled(rng) if rng.random() < 0.5 else B, "any"


def k_tilted_grid(rng):
    A = Mesh()
    grid(A, rng.randint(1, 5), rng.randint(1, 5), 0, 0, 1, 1, None, rng.choice(("a", "alt", "rand")), rng)
    B = Mesh()
    rot = axis_rot((0, 0, 1), rng.choice((0.0, 0.0, U(rng, 0, 6.3), math.pi / 4)))
    tilt_axis = mat_apply(axis_rot((0, 0, 1), U(rng, 0, 6.3)), (1, 0, 0))
    pivot = (U(rng, 0, 1), U(rng, 0, 1), 0.0) if rng.random() < 0.7 else (0.0, 0.0, 0.0)
    T = axis_rot(tilt_axis, rng.choice((-1, 1)) * E(rng, -12, -2))
    dz = rng.choice((0.0, 0.0, rng.choice((-1, 1)) * E(rng, -12, -4)))

    def f(p):
        q = vsub(mat_apply(rot, vsub(p, (0.5, 0.5, 0))), vsub(pivot, (0.5, 0.5, 0)))
        q = vadd(mat_apply(T, q), pivot)
        return (q[0], q[1], q[2] + dz)
    nb = rng.randint(1, 6)
    grid(B, nb, rng.randint(1, 6), -0.2, -0.2, 1.4, 1.4, None, "rand", rng, fn=f)
    return A, B, "any"


def k_sliver_strip(rng):
    h = E(rng, -12, -4)
    n = rng.randint(2, 20)
    A = Mesh()
    bot = [A.add((i / n, 0.0, 0.0)) for i in range(n + 1)]
    top = [A.add(((i + 0.5) / n, h, 0.0)) for i in range(n)]
    stitch(A, bot, top, key=lambda i: A.v[i][0])
    if rng.random() < 0.3:  # a cap sliver: apex nearly on the opposite edge
        A.tri((0, -0.5, 0), (1, -0.5, 0), (U(rng, 0, 1), -0.5 + h, 0))
    B = Mesh()
    mode = rng.randrange(5)
    if mode == 0:
        k = rng.randint(1, 4)
        grid(B, k, 1, -0.1, -0.6, 1.2, 1.2, None, "rand", rng)
    elif mode == 1:
        m = rng.randint(2, 20)
        s = rng.choice((0.5 * h, h, 2 * h, U(rng, 0, h)))
        bb = [B.add((i / m, s, 0.0)) for i in range(m + 1)]
        tt = [B.add(((i + 0.5) / m, s + h, 0.0)) for i in range(m)]
        stitch(B, bb, tt, key=lambda i: B.v[i][0])
    elif mode == 2:
        ang = rng.choice((U(rng, 0.01, 3.1), E(rng, -8, -2)))
        R = axis_rot((0, 0, 1), ang)
        m = rng.randint(2, 12)
        c = (0.5, 0.0, 0.0)
        bb = [B.add(vadd(mat_apply(R, (i / m - 0.5, 0.0, 0.0)), c)) for i in range(m + 1)]
        tt = [B.add(vadd(mat_apply(R, ((i + 0.5) / m - 0.5, h, 0.0)), c)) for i in range(m)]
        stitch(B, bb, tt, key=lambda i: vdot(vsub(B.v[i], c), mat_apply(R, (1, 0, 0))))
    elif mode == 3:
        z = E(rng, -9, -1)
        k = rng.randint(1, 3)
        grid(B, k, k, 0, -0.5, 1, 1, None, "rand", rng, fn=lambda p: (p[0], p[1], z))
    else:  # needle fan
        apex = B.add((U(rng, 0, 1), rng.choice((0.0, 0.5, -0.5)), 0.0))
        for _ in range(rng.randint(1, 12)):
            x = U(rng, 0, 1)
            B.face(apex, B.add((x, 0.0, 0.0)), B.add((x + h, 0.0, 0.0)))
    if rng.random() < 0.3:
        A, B = B, A
    return A, B, "any"


def k_perp_stand(rng):
    n = rng.randint(1, 5)
    A = Mesh()
    grid(A, n, n, 0, 0, 1, 1, None, rng.choice(("a", "alt", "rand")), rng)
    c = rng.choice((rng.randint(0, n) / n, U(rng, 0, 1)))
    mode = rng.randrange(3)
    if mode == 0:
        z0, z1 = 0.0, U(rng, 0.2, 1)
    elif mode == 1:
        z0, z1 = -U(rng, 0.1, 1), U(rng, 0.1, 1)
    else:
        z0 = E(rng, -12, -3) * rng.choice((1, -1))
        z1 = z0 + U(rng, 0.2, 1)
    ang = rng.choice((0.0, math.pi / 4, U(rng, 0, math.pi)))
    R = axis_rot((0, 0, 1), ang)
    y0 = rng.choice((0.0, U(rng, -0.5, 0.5)))
    y1 = rng.choice((1.0, U(rng, 0.5, 1.5)))
    B = Mesh()
    grid(B, rng.randint(1, 4), rng.randint(1, 3), y0, z0, y1 - y0, z1 - z0, None, "rand", rng,
         fn=lambda p: vadd(mat_apply(R, (0.0, p[0] - 0.5, p[1])), (c if ang == 0 else 0.5, 0.5, 0.0)))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def halfplane(m, line_ts, far_ts, u, w, L0=(0.0, 0.0, 0.0), Ld=(1.0, 0.0, 0.0), line_idx=None):
    low = line_idx if line_idx is not None else [m.add(vadd(L0, vmul(Ld, t))) for t in line_ts]
    high = [m.add(vadd(vadd(L0, vmul(Ld, t)), vmul(u, w))) for t in far_ts]
    stitch(m, low, high, key=lambda i: vdot(vsub(m.v[i], L0), Ld))
    return low


def k_boolean_cross(rng):
    alpha = rng.choice((math.pi / 2, U(rng, 0.1, math.pi - 0.1), E(rng, -6, -1), math.pi / 3))
    u1p, u1m = (0.0, 1.0, 0.0), (0.0, -1.0, 0.0)
    u2p = (0.0, math.cos(alpha), math.sin(alpha))
    u2m = vmul(u2p, -1.0)
    w = U(rng, 0.3, 1.0)
    def ts(): return sorted_params(rng, rng.randint(0, 5))
    tsL = ts()
    # A: the union's surface, a bent sheet: P1 on one side, P2 on one side, conforming on L
    A = Mesh()
    low = halfplane(A, tsL, ts(), rng.choice((u1p, u1m)), w)
    halfplane(A, tsL, ts(), rng.choice((u2p, u2m)), w, line_idx=low)
    # B: both inputs whole: P1 and P2 crossing along L
    B = Mesh()
    conf = rng.random() < 0.5
    tB1 = tsL if conf else ts()
    tB2 = tB1 if rng.random() < 0.5 else ts()
    l1 = halfplane(B, tB1, ts(), u1p, w)
    halfplane(B, tB1, ts(), u1m, w, line_idx=l1 if rng.random() < 0.7 else None)
    l2 = halfplane(B, tB2, ts(), u2p, w)
    halfplane(B, tB2, ts(), u2m, w, line_idx=l2 if rng.random() < 0.7 else None)
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def k_shared_edge_hinge(rng):
    th = rng.choice((0.0, math.pi, math.pi / 2, E(rng, -10, -2), math.pi - E(rng, -10, -2), U(rng, 0, math.pi)))
    def ts(): return rng.choice(([0.0, 1.0], sorted_params(rng, rng.randint(1, 5))))
    tA = ts()
    tB = tA if rng.random() < 0.4 else ts()
    A = Mesh()
    halfplane(A, tA, ts(), (0.0, 1.0, 0.0), U(rng, 0.2, 1.0))
    B = Mesh()
    halfplane(B, tB, ts(), (0.0, math.cos(th), math.sin(th)), U(rng, 0.2, 1.0))
    if rng.random() < 0.3:  # a second hinge on the other side of A
        halfplane(A, tA, ts(), (0.0, -math.cos(th), -math.sin(th)), U(rng, 0.2, 1.0))
    return A, B, "any"


def add_degenerates(m, rng, count):
    nv = len(m.v)
    for _ in range(count):
        k = rng.randrange(5)
        if k == 0 and m.f:  # midpoint of an edge: collinear triple
            a, b, _c = rng.choice(m.f)
            mid = m.add(lerp(m.v[a], m.v[b], rng.choice((0.5, U(rng, 0, 1)))))
            m.face(a, mid, b)
        elif k == 1 and m.f:  # a coincident copy of a vertex
            a, b, _c = rng.choice(m.f)
            m.face(a, b, m.add(m.v[a]))
        elif k == 2:  # a point triangle (three coincident vertices)
            p = m.v[rng.randrange(nv)] if nv and rng.random() < 0.6 else (U(rng, 0, 1), U(rng, 0, 1), U(rng, -0.2, 0.2))
            m.tri(p, p, p)
        elif k == 3:  # a segment standing off the surface
            p = m.v[rng.randrange(nv)] if nv else (0.5, 0.5, 0.0)
            d = rand_unit(rng) if rng.random() < 0.5 else (0.0, 0.0, 1.0)
            l = U(rng, 0.05, 0.5)
            m.tri(p, vadd(p, vmul(d, l * U(rng, 0, 1))), vadd(p, vmul(d, l)))
        else:  # a collinear triple anywhere in the plane z = 0
            p, q = (U(rng, 0, 1), U(rng, 0, 1), 0.0), (U(rng, 0, 1), U(rng, 0, 1), 0.0)
            m.tri(p, lerp(p, q, U(rng, 0, 1)), q)


def k_zero_area(rng):
    A = Mesh()
    grid(A, rng.randint(1, 4), rng.randint(1, 4), 0, 0, 1, 1, rng.choice((None, smooth_fn(rng, 0.2))), "rand", rng)
    add_degenerates(A, rng, rng.randint(1, 8))
    B = Mesh()
    mode = rng.randrange(4)
    if mode == 0:
        grid(B, rng.randint(1, 4), rng.randint(1, 4), 0, 0, 1, 1, None, "rand", rng)
        add_degenerates(B, rng, rng.randint(0, 6))
    elif mode == 1:
        B = A.copy()
        add_degenerates(B, rng, rng.randint(1, 6))
        B = B.shuffled(rng)
    elif mode == 2:  # only zero-area triangles
        tmp = Mesh()
        grid(tmp, 2, 2, 0, 0, 1, 1, None, "a", rng)
        B.v = list(tmp.v)
        add_degenerates(B, rng, rng.randint(1, 10))
    else:
        z = rng.choice((0.0, E(rng, -10, -2)))
        grid(B, rng.randint(1, 3), rng.randint(1, 3), -0.2, -0.2, 1.4, 1.4, None, "rand", rng, fn=lambda p: (p[0], p[1], z))
        add_degenerates(B, rng, rng.randint(0, 4))
    if not B.f:
        B.tri((0, 0, 0), (0.5, 0, 0), (1, 0, 0))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def with_dups(m, rng, count):
    out = m.copy()
    for _ in range(count):
        a, b, c = rng.choice(m.f)
        k = rng.randrange(4)
        if k == 0:
            out.face(a, b, c)
        elif k == 1:
            out.face(a, c, b)
        elif k == 2:
            out.face(b, c, a)
        else:
            out.tri(m.v[a], m.v[b], m.v[c])
    return out.shuffled(rng) if rng.random() < 0.7 else out


def k_dup_faces(rng):
    base = closed_base(rng)
    A = with_dups(base, rng, rng.randint(1, len(base.f)))
    mode = rng.randrange(3)
    if mode == 0:
        B = with_dups(base, rng, rng.randint(0, len(base.f)))
    elif mode == 1:
        B = base.flipped().shuffled(rng)
    else:
        d = vmul(rand_unit(rng), E(rng, -12, -3))
        B = with_dups(base, rng, rng.randint(0, 4)).mapped(lambda p: vadd(p, d))
    return A, B, "any"


def k_t_junction(rng):
    A = Mesh()
    k = rng.randint(1, 3)
    grid(A, k, k, 0, 0, 1, 1, None, rng.choice(("a", "b", "rand")), rng)
    B = Mesh()
    lift = rng.choice((0.0, 0.0, E(rng, -12, -6)))
    ka, kb = rng.randint(1, 4), rng.randint(1, 4)
    xs = rng.choice((0.5, U(rng, 0.2, 0.8), 1.0 / 3))
    # left and right halves with different subdivisions along the seam x = xs
    left_seam = [B.add((xs, j / ka, lift)) for j in range(ka + 1)]
    left_edge = [B.add((0.0, j / ka, 0.0)) for j in range(ka + 1)]
    stitch(B, left_seam, left_edge, key=lambda i: B.v[i][1])
    right_seam = [B.add((xs, j / kb, lift)) for j in range(kb + 1)]
    right_edge = [B.add((1.0, j / kb, 0.0)) for j in range(kb + 1)] if rng.random() < 0.5 else [B.add((1.0, 0.0, 0.0)), B.add((1.0, 1.0, 0.0))]
    stitch(B, right_edge, right_seam, key=lambda i: B.v[i][1])
    if rng.random() < 0.4:  # T-junctions on A's own diagonal: a point on it, fan around
        C = Mesh()
        t = rng.choice((0.5, U(rng, 0, 1)))
        c = C.add((t, t, 0.0))
        corners = [C.add(p) for p in ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0))]
        mids = [C.add(p) for p in ((0.5, 0, 0), (1, 0.5, 0), (0.5, 1, 0), (0, 0.5, 0))]
        ring = [corners[0], mids[0], corners[1], mids[1], corners[2], mids[2], corners[3], mids[3]]
        fan(C, c, ring, closed=True)
        B = C
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def pyramid(m, n, h, r=1.0, apex=(0.0, 0.0, 0.0), phase=0.0, base=True):
    a = m.add(apex)
    ring = [m.add((apex[0] + r * math.cos(phase + 2 * math.pi * k / n), apex[1] + r * math.sin(phase + 2 * math.pi * k / n), apex[2] - h))
            for k in range(n)]
    fan(m, a, ring, closed=True)
    if base and n >= 3:
        for k in range(1, n - 1):
            m.face(ring[0], ring[k + 1], ring[k])


def k_vertex_touch(rng):
    A = Mesh()
    pyramid(A, rng.randint(3, 8), U(rng, 0.2, 1.0), U(rng, 0.3, 1.0), phase=U(rng, 0, 1), base=rng.random() < 0.5)
    B = Mesh()
    mode = rng.randrange(5)
    if mode == 0:  # apex to apex
        pyramid(B, rng.randint(3, 8), -U(rng, 0.2, 1.0), U(rng, 0.3, 1.0), phase=rng.choice((0.0, U(rng, 0, 1))), base=rng.random() < 0.5)
        if rng.random() < 0.5:
            R = axis_rot(rand_unit(rng), U(rng, 0, 0.3))  # tilted a little about the shared apex
            B = B.mapped(lambda p: mat_apply(R, p))
    elif mode == 1:  # on a grid vertex
        k = rng.randint(1, 3)
        grid(B, 2 * k, 2 * k, -1, -1, 2, 2, None, "rand", rng)
    elif mode == 2:  # inside an edge
        B.tri((-1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0))
        B.tri((-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0))
    elif mode == 3:  # inside a face
        B.tri((-1.0, -0.7, 0.0), (1.3, -0.5, 0.0), (0.1, 1.1, 0.0))
    else:  # an upside-down tetrahedron on the apex, or hovering 1e-12..1e-3 above it
        pyramid(B, 3, -0.5, 0.5, apex=(0.0, 0.0, 0.0), phase=U(rng, 0, 6.3), base=True)
        lift = E(rng, -12, -3) * rng.choice((0, 1))
        B = B.mapped(lambda p: (p[0], p[1], p[2] + lift))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_cyl_lod(rng):
    H = U(rng, 0.2, 3.0)
    caps_a = rng.randrange(3)
    caps_b = rng.randrange(3)
    n1 = rng.randint(3, 8)
    r1 = rng.randint(1, 2)
    rings2 = rng.randint(1, 2)
    n2max = MAXT // (2 * rings2 + caps_b)
    n2 = rng.choice((min(2 * n1, n2max), min(3 * n1, n2max), rng.randint(n1 + 1, max(n1 + 1, min(24, n2max)))))
    phase = rng.choice((0.0, math.pi / n2, U(rng, 0, 6.3)))
    radius_b = rng.choice((1.0, 1.0, 1.0 / math.cos(math.pi / n2)))

    def make(n, rings, caps, ph, rad):
        m = Mesh()
        rows = tube(m, n, rings, H, rad, ph)
        if caps >= 1:
            c = m.add((0.0, 0.0, 0.0))
            fan(m, c, rows[0][::-1], closed=True)
        if caps >= 2:
            c = m.add((0.0, 0.0, H))
            fan(m, c, rows[-1], closed=True)
        return m
    A = make(n1, r1, caps_a, 0.0, 1.0)
    B = make(n2, rings2, caps_b, phase, radius_b)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_cone_fan(rng):
    h = rng.choice((U(rng, 0.3, 2.0), E(rng, -6, -1)))
    n1 = rng.randint(3, 12)
    n2 = rng.randint(3, 30)

    def cone(n, height, ph, rings=1, cap=False):
        m = Mesh()
        apex = m.add((0.0, 0.0, height))
        rows = []
        for r in range(1, rings + 1):
            f = r / rings
            rows.append([m.add((f * math.cos(ph + 2 * math.pi * k / n), f * math.sin(ph + 2 * math.pi * k / n), height * (1 - f)))
                         for k in range(n)])
        fan(m, apex, rows[0], closed=True)
        for r in range(rings - 1):
            lo, hi = rows[r], rows[r + 1]
            for k in range(n):
                k1 = (k + 1) % n
                m.face(lo[k], hi[k], hi[k1]); m.face(lo[k], hi[k1], lo[k1])
        if cap:
            c = m.add((0.0, 0.0, 0.0))
            fan(m, c, rows[-1][::-1], closed=True)
        return m
    A = cone(n1, h, 0.0, 1, rng.random() < 0.4)
    mode = rng.randrange(4)
    ph = rng.choice((0.0, math.pi / n2, U(rng, 0, 6.3)))
    if mode == 0:
        rings = rng.randint(1, 2) if n2 <= 26 else 1
        B = cone(n2, h, ph, rings, rng.random() < 0.3 and n2 * (2 * rings) <= MAXT)
    elif mode == 1:  # bicone: the mirrored cone sharing the base circle
        B = cone(n1 if rng.random() < 0.5 else n2, -h, 0.0 if rng.random() < 0.5 else ph, 1)
    elif mode == 2:  # the flat disc
        B = Mesh()
        ring = [B.add((math.cos(ph + 2 * math.pi * k / n2), math.sin(ph + 2 * math.pi * k / n2), 0.0)) for k in range(n2)]
        fan(B, B.add((0.0, 0.0, 0.0)), ring, closed=True)
    else:  # the same cone, its apex moved a little
        B = cone(n1, h * (1 + rng.choice((1, -1)) * E(rng, -10, -2)), 0.0, 1)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_sphere_lod(rng):
    A = Mesh()
    c = rng.randint(3, 10)
    r = rng.randint(2, max(2, min(6, MAXT // (2 * c) + 1)))
    uv_sphere(A, c, r)
    B = Mesh()
    mode = rng.randrange(5)
    if mode == 0:
        octa_sphere(B, rng.randint(0, 1))
    elif mode == 1:
        icosa_sphere(B, rng.randint(0, 1) if rng.random() < 0.5 else 0)
    elif mode == 2:
        c2 = rng.randint(3, 10)
        r2 = rng.randint(2, max(2, min(6, MAXT // (2 * c2) + 1)))
        uv_sphere(B, c2, r2, phase=rng.choice((0.0, math.pi / c2)), Rot=rng.choice((None, quat_rot(rng), axis_rot((1, 0, 0), math.pi / 2))))
    elif mode == 3:
        uv_sphere(B, c, r, phase=E(rng, -10, -2))
    else:
        uv_sphere(B, c, r, R=1 + rng.choice((1, -1)) * E(rng, -10, -2))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_seam_strip(rng):
    n = rng.randint(6, 24)
    H = U(rng, 0.5, 3)
    B = Mesh()
    tube(B, n, 1, H)
    A = Mesh()
    w = E(rng, -7, -2)
    if rng.random() < 0.5:  # thin band all the way round, at the rim or anywhere
        z0 = rng.choice((0.0, H - w, U(rng, 0, H - w)))
        m2 = rng.choice((n, min(2 * n, 40), rng.randint(3, 30)))
        rows = tube(A, m2, 1, w, rng.choice((1.0, math.cos(math.pi / n))), 0.0, z0)
    else:  # thin strip along the seam (angle 0), long in z
        k = rng.randint(1, 8)
        a0 = rng.choice((0.0, -w / 2, -w))
        left = [A.add((math.cos(a0), math.sin(a0), H * j / k)) for j in range(k + 1)]
        right = [A.add((math.cos(a0 + w), math.sin(a0 + w), H * (j + 0.5) / k if rng.random() < 0.5 else H * j / k)) for j in range(k + 1)]
        stitch(A, left, right, key=lambda i: A.v[i][2])
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def k_regular_ties(rng):
    k = rng.randint(3, 8)
    A = Mesh()
    ring = [A.add((math.cos(2 * math.pi * i / k), math.sin(2 * math.pi * i / k), 0.0)) for i in range(k)]
    fan(A, A.add((0.0, 0.0, 0.0)), ring, closed=True)
    B = Mesh()
    mode = rng.randrange(4)
    if mode == 0:
        m = rng.choice((k, 2 * k, k + 1))
        h = rng.choice((0.0, U(rng, 0.1, 1), E(rng, -9, -2)))
        r = rng.choice((1.0, U(rng, 0.3, 1.5)))
        rb = [B.add((r * math.cos(math.pi / k + 2 * math.pi * i / m), r * math.sin(math.pi / k + 2 * math.pi * i / m), h)) for i in range(m)]
        fan(B, B.add((0.0, 0.0, h)), rb, closed=True)
    elif mode == 1:  # k copies of one triangle around the z axis
        t = [(U(rng, 0.2, 1.2), U(rng, -0.5, 0.5), U(rng, -0.5, 0.5)) for _ in range(3)]
        for i in range(k):
            R = axis_rot((0, 0, 1), 2 * math.pi * i / k)
            B.tri(*[mat_apply(R, p) for p in t])
    elif mode == 2:  # an annulus around the disc
        rin = U(rng, 0.1, 0.9)
        m = rng.choice((k, 2 * k))
        inner = [B.add((rin * math.cos(2 * math.pi * i / m), rin * math.sin(2 * math.pi * i / m), 0.0)) for i in range(m)]
        outer = [B.add((1.2 * math.cos(2 * math.pi * i / m), 1.2 * math.sin(2 * math.pi * i / m), 0.0)) for i in range(m)]
        for i in range(m):
            j = (i + 1) % m
            B.face(inner[i], outer[i], outer[j]); B.face(inner[i], outer[j], inner[j])
    else:  # walls of a regular prism around the axis (each equidistant from the centre)
        d = U(rng, 0.2, 1.0)
        for i in range(k):
            a0, a1 = 2 * math.pi * i / k, 2 * math.pi * (i + 1) / k
            p0 = (d * math.cos(a0), d * math.sin(a0))
            p1 = (d * math.cos(a1), d * math.sin(a1))
            B.tri((p0[0], p0[1], -0.5), (p1[0], p1[1], -0.5), (p1[0], p1[1], 0.5))
            B.tri((p0[0], p0[1], -0.5), (p1[0], p1[1], 0.5), (p0[0], p0[1], 0.5))
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def k_voxel_stairs(rng):
    n = rng.randint(2, 4)
    s = 1.0 / n
    if rng.random() < 0.5:
        a, b = rng.choice((0.5, 1.0 / 3, U(rng, -1, 1))), rng.choice((0.0, 0.25, U(rng, -1, 1)))
        c0 = rng.choice((0.0, U(rng, 0, 1)))
        f = lambda x, y: a * x + b * y + c0
    else:
        R = U(rng, 1.0, 3.0)
        f = lambda x, y: math.sqrt(max(R * R - (x - 0.5) ** 2 - (y - 0.5) ** 2, 0.0)) - R + 0.5
    hq = [[math.floor(f((i + 0.5) * s, (j + 0.5) * s) / s + 0.5) * s for j in range(n)] for i in range(n)]
    A = Mesh()
    for i in range(n):
        for j in range(n):
            z = hq[i][j]
            x0, y0, x1, y1 = i * s, j * s, (i + 1) * s, (j + 1) * s
            A.tri((x0, y0, z), (x1, y0, z), (x1, y1, z)); A.tri((x0, y0, z), (x1, y1, z), (x0, y1, z))
    for i in range(n):
        for j in range(n):
            if i + 1 < n and hq[i][j] != hq[i + 1][j]:
                x = (i + 1) * s
                z0, z1 = hq[i][j], hq[i + 1][j]
                A.tri((x, j * s, z0), (x, (j + 1) * s, z0), (x, (j + 1) * s, z1)); A.tri((x, j * s, z0), (x, (j + 1) * s, z1), (x, j * s, z1))
            if j + 1 < n and hq[i][j] != hq[i][j + 1]:
                y = (j + 1) * s
                z0, z1 = hq[i][j], hq[i][j + 1]
                A.tri((i * s, y, z0), ((i + 1) * s, y, z0), ((i + 1) * s, y, z1)); A.tri((i * s, y, z0), ((i + 1) * s, y, z1), (i * s, y, z1))
    B = Mesh()
    m = rng.randint(1, 6)
    grid(B, m, m, 0, 0, 1, 1, f, "rand", rng)
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_mirror(rng):
    A = Mesh()
    n = rng.randint(2, 5)
    mode = rng.randrange(3)
    grid(A, n, rng.randint(1, 4), -0.5, 0, 1, 1, smooth_fn(rng, U(rng, 0.05, 0.5)), "rand", rng)
    if mode == 0:  # through the middle
        nrm, c = (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    elif mode == 1:  # through a vertex
        nrm, c = rand_unit(rng), rng.choice(A.v)
    else:
        nrm, c = rand_unit(rng), (U(rng, -0.5, 0.5), U(rng, 0, 1), U(rng, -0.2, 0.2))

    def refl(p):
        d = vdot(vsub(p, c), nrm)
        return vsub(p, vmul(nrm, 2 * d))
    B = A.mapped(refl).flipped()
    if rng.random() < 0.5:
        B = B.shuffled(rng)
    return A, B, "any"


def k_terrain_plateau(rng):
    n = rng.randint(3, 6)
    L = rng.randint(2, 4)
    sm = smooth_fn(rng, 1.0)
    step = 1.0 / L
    hq = lambda x, y: math.floor(sm(x, y) / step + 0.5) * step * 0.3
    A = Mesh()
    grid(A, n, n, 0, 0, 1, 1, hq, rng.choice(("a", "b", "alt")), rng)
    B = Mesh()
    mode = rng.randrange(4)
    if mode == 0:
        grid(B, n, n, 0, 0, 1, 1, hq, "rand", rng)
    elif mode == 1:
        m = rng.randint(2, 6)
        grid(B, m, m, 0, 0, 1, 1, lambda x, y: sm(x, y) * 0.3, "rand", rng)
    elif mode == 2:
        lvl = rng.choice(A.v)[2]
        grid(B, rng.randint(1, 2), 1, -0.1, -0.1, 1.2, 1.2, None, "rand", rng, fn=lambda p: (p[0], p[1], lvl))
    else:
        eps = rng.choice((1, -1)) * E(rng, -12, -5)
        grid(B, n, n, 0, 0, 1, 1, lambda x, y: hq(x, y) + eps, "rand", rng)
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def sim_transform(rng, size, max_off_exp=4):
    R = quat_rot(rng)
    s = E(rng, -6, 6)
    off = vmul(rand_unit(rng), s * size * rng.choice((0.0, U(rng, 0, 3), E(rng, 1, max_off_exp))))
    return lambda p: vadd(vmul(mat_apply(R, p), s), off)


def k_f32_copy(rng):
    A = rng.choice((curved_patch(rng), closed_base(rng)))
    A = A.mapped(sim_transform(rng, bbox_diag([A])))
    B = A.mapped(lambda p: tuple(f32(c) for c in p))
    if rng.random() < 0.3:
        B = B.flipped()
    if rng.random() < 0.3:
        A, B = B, A
    return A, B, "done"


def k_grid_snap(rng):
    A = curved_patch(rng, 5)
    g = rng.choice((2.0 ** -rng.randint(1, 8), 10.0 ** -rng.randint(1, 3), U(rng, 0.02, 0.3)))
    B = A.mapped(lambda p: tuple(round(c / g) * g for c in p))
    if rng.random() < 0.3:
        A, B = B, A
    return A, B, rng.choice(("exact", "any"))


def k_huge_tiny(rng):
    A = Mesh()
    A.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    eps = E(rng, -7, -5)
    anchor = rng.choice(((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 0.0, 0.0), (0.25, 0.25, 0.0)))
    for _ in range(rng.randint(1, 10)):
        off = (U(rng, -1, 1) * eps, U(rng, -1, 1) * eps, rng.choice((0.0, U(rng, -1, 1) * eps)))
        p = vadd(anchor, off)
        A.tri(anchor if rng.random() < 0.5 else p, vadd(p, (eps, 0, 0)), vadd(p, (0, eps, rng.choice((0.0, eps)))))
    if rng.random() < 0.5:  # a 1e6 aspect triangle
        A.tri((0.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.5, 0.5 + 1e-6 * U(rng, 0.5, 2), 0.0))
    B = Mesh()
    mode = rng.randrange(3)
    if mode == 0:
        k = rng.randint(1, 4)
        grid(B, k, k, -0.1, -0.1, 1.2, 1.2, None, "rand", rng, fn=lambda p: (p[0], p[1], rng.choice((0.0, E(rng, -9, -3)))))
    elif mode == 1:  # one huge triangle and a long thin one
        B.tri((-10.0, -10.0, 0.0), (10.0, -10.0, 0.0), (0.0, 10.0, E(rng, -9, -4)))
        B.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 1e-6, 0.0))
    else:  # a fan of long needles from the anchor
        for i in range(rng.randint(2, 10)):
            t = U(rng, 0, 1.5)
            B.tri(anchor, (math.cos(t), math.sin(t), 0.0), (math.cos(t + 1e-6), math.sin(t + 1e-6), 0.0))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_collinear_line(rng):
    def pts(): return sorted_params(rng, rng.randint(2, 18))
    A = Mesh()
    ta = pts()
    line = [A.add((t, 0.0, 0.0)) for t in ta]
    fan(A, A.add((U(rng, -0.5, 1.5), U(rng, 0.2, 1.0), 0.0)), line)
    B = Mesh()
    tb = ta if rng.random() < 0.3 else pts()
    lb = [B.add((t, 0.0, 0.0)) for t in tb]
    mode = rng.randrange(4)
    if mode == 0:
        apex = (U(rng, -0.5, 1.5), -U(rng, 0.2, 1.0), 0.0)
    elif mode == 1:
        apex = (U(rng, -0.5, 1.5), U(rng, 0.2, 1.0), 0.0)
    elif mode == 2:
        apex = (U(rng, -0.5, 1.5), 0.0, U(rng, 0.2, 1.0))
    else:
        apex = (U(rng, -0.5, 1.5), E(rng, -10, -3), rng.choice((0.0, E(rng, -10, -3))))
    fan(B, B.add(apex), lb)
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def k_cocircular(rng):
    def angles(n):
        if rng.random() < 0.5:
            return [2 * math.pi * i / n for i in range(n)]
        return sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    n1 = rng.randint(3, 24)
    a1 = angles(n1)
    A = Mesh()
    ring = [A.add((math.cos(t), math.sin(t), 0.0)) for t in a1]
    fan(A, A.add((0.0, 0.0, 0.0)), ring, closed=True)
    B = Mesh()
    mode = rng.randrange(4)
    a2 = a1 if rng.random() < 0.4 else angles(rng.randint(3, 24))
    rb = [B.add((math.cos(t), math.sin(t), 0.0)) for t in a2]
    if mode == 0:
        fan(B, B.add((U(rng, -0.5, 0.5), U(rng, -0.5, 0.5), 0.0)), rb, closed=True)
    elif mode == 1:
        fan(B, B.add((0.0, 0.0, rng.choice((U(rng, 0.1, 1.0), E(rng, -9, -2))))), rb, closed=True)
    elif mode == 2:
        fan(B, rb[0], rb[1:])
    else:  # the same circle's points, its fan apex on the circle too, tilted out of plane about a diameter
        R = axis_rot((1, 0, 0), rng.choice((math.pi / 2, E(rng, -9, -2), U(rng, 0, 3))))
        B = Mesh()
        rb = [B.add(mat_apply(R, (math.cos(t), math.sin(t), 0.0))) for t in a2]
        fan(B, B.add((0.0, 0.0, 0.0)), rb, closed=True)
    if rng.random() < 0.4:
        A, B = B, A
    return A, B, "any"


def k_point_like(rng):
    B = rng.choice((closed_base(rng), curved_patch(rng, 3)))
    A = Mesh()
    eps = E(rng, -15, -9)
    for _ in range(rng.randint(1, 10)):
        a, b, c = rng.choice(B.f)
        pa, pb, pc = B.v[a], B.v[b], B.v[c]
        k = rng.randrange(5)
        if k == 0:
            p = pa
        elif k == 1:
            p = lerp(pa, pb, rng.choice((0.5, U(rng, 0, 1))))
        elif k == 2:
            u, v = rng.random(), rng.random()
            if u + v > 1:
                u, v = 1 - u, 1 - v
            p = vadd(pa, vadd(vmul(vsub(pb, pa), u), vmul(vsub(pc, pa), v)))
        elif k == 3:
            nrm = vunit(vcross(vsub(pb, pa), vsub(pc, pa)))
            p = vadd(lerp(pa, pc, 0.3), vmul(nrm, E(rng, -9, 0)))
        else:
            p = (U(rng, -0.5, 1.5), U(rng, -0.5, 1.5), U(rng, -0.5, 1.5))
        A.tri(p, vadd(p, vmul(rand_unit(rng), eps * rng.random())), vadd(p, vmul(rand_unit(rng), eps * rng.random())))
    if rng.random() < 0.3:
        A.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.5))
    if rng.random() < 0.2:  # both point-like
        C = Mesh()
        for _ in range(rng.randint(1, 5)):
            p = rng.choice(A.v)
            C.tri(p, vadd(p, vmul(rand_unit(rng), eps)), vadd(p, vmul(rand_unit(rng), eps)))
        B = C
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "any"


def k_integer_coords(rng):
    def rnd_tris(m, k, r):
        for _ in range(k):
            m.tri(*[(rng.randint(-r, r), rng.randint(-r, r), rng.randint(-r, r) if rng.random() < 0.6 else 0) for _ in range(3)])
    A = Mesh()
    B = Mesh()
    r = rng.randint(1, 4)
    mode = rng.randrange(3)
    if mode == 0:
        rnd_tris(A, rng.randint(1, 12), r)
        rnd_tris(B, rng.randint(1, 12), r)
    elif mode == 1:
        n = rng.randint(1, 4)
        grid(A, n, n, 0, 0, n, n, lambda x, y: 0, "rand", rng)
        sx, sy = rng.randint(-1, 1), rng.randint(-1, 1)
        grid(B, n, n, -1, -1, n, n, lambda x, y: sx * x + sy * y, "rand", rng)
    else:
        n = rng.randint(1, 3)
        grid(A, n, n, 0, 0, n, n, None, "rand", rng)
        rnd_tris(B, rng.randint(1, 10), r)
    f = rng.choice((1, 1, 1000, 12345, 2 ** 20))
    if f != 1:
        A = A.mapped(lambda p: tuple(c * f for c in p))
        B = B.mapped(lambda p: tuple(c * f for c in p))
    return A, B, "exact"


def k_pow2_coords(rng):
    def p2(): return rng.choice((-1.0, 1.0)) * 2.0 ** rng.randint(-20, 20) if rng.random() < 0.85 else 0.0
    A = Mesh()
    B = Mesh()
    mode = rng.randrange(3)
    if mode == 0:
        for m in (A, B):
            for _ in range(rng.randint(1, 10)):
                m.tri(*[(p2(), p2(), p2()) for _ in range(3)])
    else:
        base = rng.randint(-4, 0)
        for m in (A, B):  # geometric grid: x_i = 2^(base + i)
            n = rng.randint(2, 5)
            xs = [0.0] + [2.0 ** (base + i) for i in range(n)]
            ys = [0.0] + [2.0 ** (base + i + rng.randint(-1, 1)) for i in range(n)]
            ys = sorted(set(ys))
            zf = (lambda x, y: 0.0) if mode == 1 else (lambda x, y: 2.0 ** rng.randint(-6, 0) if x > 0.5 else 0.0)
            idx = [[m.add((x, y, zf(x, y))) for y in ys] for x in xs]
            for i in range(len(xs) - 1):
                for j in range(len(ys) - 1):
                    a, b, c, d = idx[i][j], idx[i + 1][j], idx[i + 1][j + 1], idx[i][j + 1]
                    if rng.random() < 0.5:
                        m.face(a, b, c); m.face(a, c, d)
                    else:
                        m.face(a, b, d); m.face(b, c, d)
    e = 2.0 ** rng.randint(-40, 40)
    A = A.mapped(lambda p: tuple(c * e for c in p))
    B = B.mapped(lambda p: tuple(c * e for c in p))
    return A, B, "exact"


def k_rot_hinge(rng):
    A = curved_patch(rng, 4) if rng.random() < 0.6 else closed_base(rng)
    if rng.random() < 0.5:
        a, b, _ = rng.choice(A.f)
        piv, ax = A.v[a], vsub(A.v[b], A.v[a])
    else:
        piv, ax = rng.choice(A.v), rand_unit(rng)
    R = axis_rot(ax, rng.choice((1, -1)) * E(rng, -10, -1))
    B = A.mapped(lambda p: vadd(mat_apply(R, vsub(p, piv)), piv))
    if rng.random() < 0.5:
        B = B.shuffled(rng)
    return A, B, "sim"


def k_scaled_copy(rng):
    A = rng.choice((curved_patch(rng, 4), closed_base(rng), Mesh()))
    if not A.f:
        octa_sphere(A, rng.randint(0, 1))
    c = rng.choice((rng.choice(A.v), (0.5, 0.5, 0.5), (0.0, 0.0, 0.0), (U(rng, -1, 2), U(rng, -1, 2), U(rng, -1, 2))))
    f = 1 + rng.choice((1, -1)) * E(rng, -9, -1)
    B = A.mapped(lambda p: vadd(c, vmul(vsub(p, c), f)))
    return A, B, "any"


# --- near-coincident, far from the origin --------------------------------------------------------
def k_coinc_noise_far(rng):
    A = rng.choice((curved_patch(rng, 5), closed_base(rng)))
    amp = E(rng, -9, -3)
    p_move = rng.choice((1.0, 0.5, 0.2))

    def jitter(p):
        if rng.random() < p_move:
            return vadd(p, vmul(rand_unit(rng), amp * rng.random()))
        return p
    B = A.mapped(jitter)
    if rng.random() < 0.3:
        B = with_dups(B, rng, rng.randint(1, 3))
    return A, B, "far"


def k_coinc_retess_far(rng):
    R = E(rng, 1, 5)  # gently curved: chord error ~ 1/(8R)
    kind = rng.randrange(2)

    def surf(x, y):
        if kind == 0:
            return (x, y, math.sqrt(max(R * R - x * x - y * y, 0.0)) - R)
        return (R * math.sin(x / R), y, R * math.cos(x / R) - R)
    A = Mesh()
    grid(A, rng.randint(1, 5), rng.randint(1, 5), -0.5, -0.5, 1, 1, None, "rand", rng, fn=lambda p: surf(p[0], p[1]))
    B = Mesh()
    grid(B, rng.randint(1, 5), rng.randint(1, 5), -0.5, -0.5, 1, 1, None, "rand", rng, fn=lambda p: surf(p[0], p[1]))
    return A, B, "far"


def k_f32_far(rng):
    A = rng.choice((curved_patch(rng, 4), closed_base(rng)))
    size = bbox_diag([A])
    R = quat_rot(rng)
    s = E(rng, -3, 3)
    d = rand_unit(rng) if rng.random() < 0.7 else rng.choice(((1.0, 0.0, 0.0), (0.0, 0.0, -1.0), vunit((1, 1, 1))))
    off = vmul(d, s * size * E(rng, 3, 5.5))
    A = A.mapped(lambda p: vadd(vmul(mat_apply(R, p), s), off))
    B = A.mapped(lambda p: tuple(f32(c) for c in p))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "done"


def k_snap_far(rng):
    A = rng.choice((curved_patch(rng, 4), closed_base(rng)))
    size = bbox_diag([A])
    A = A.mapped(far_transform(rng, size))
    size_w = bbox_diag([A])
    g = size_w * E(rng, -9, -4)
    B = A.mapped(lambda p: tuple(round(c / g) * g for c in p))
    if rng.random() < 0.5:
        A, B = B, A
    return A, B, "done"


def k_dup_offset_far(rng):
    A = Mesh()
    grid(A, rng.randint(1, 4), rng.randint(1, 3), 0, 0, 1, 1, rng.choice((None, smooth_fn(rng, 0.1))), "rand", rng)
    A = with_dups(A, rng, rng.randint(1, 4))
    mag = E(rng, -9, -3)
    dmode = rng.randrange(3)
    d = (0.0, 0.0, 1.0) if dmode == 0 else (vunit((1.0, U(rng, -1, 1), 0.0)) if dmode == 1 else rand_unit(rng))
    B = A.mapped(lambda p: vadd(p, vmul(d, mag)))
    if rng.random() < 0.4:
        B = with_dups(B, rng, rng.randint(1, 3))
    return A, B, "far"


KINDS = [
    ("coplanar_retri", k_coplanar_retri), ("tilted_grid", k_tilted_grid), ("sliver_strip", k_sliver_strip),
    ("perp_stand", k_perp_stand), ("boolean_cross", k_boolean_cross), ("shared_edge_hinge", k_shared_edge_hinge),
    ("zero_area", k_zero_area), ("dup_faces", k_dup_faces), ("t_junction", k_t_junction),
    ("vertex_touch", k_vertex_touch), ("cyl_lod", k_cyl_lod), ("cone_fan", k_cone_fan),
    ("sphere_lod", k_sphere_lod), ("seam_strip", k_seam_strip), ("regular_ties", k_regular_ties),
    ("voxel_stairs", k_voxel_stairs), ("mirror", k_mirror), ("terrain_plateau", k_terrain_plateau),
    ("f32_copy", k_f32_copy), ("grid_snap", k_grid_snap), ("huge_tiny", k_huge_tiny),
    ("collinear_line", k_collinear_line), ("cocircular", k_cocircular), ("point_like", k_point_like),
    ("integer_coords", k_integer_coords), ("pow2_coords", k_pow2_coords), ("rot_hinge", k_rot_hinge),
    ("scaled_copy", k_scaled_copy),
    ("coinc_noise_far", k_coinc_noise_far), ("coinc_retess_far", k_coinc_retess_far), ("f32_far", k_f32_far),
    ("snap_far", k_snap_far), ("dup_offset_far", k_dup_offset_far),
]


# ------------------------------------------------------------------------------------------------
# Placement
# ------------------------------------------------------------------------------------------------
def bbox_diag(ms):
    pts = [p for m in ms for f in m.f for i in f for p in [m.v[i]]]
    if not pts:
        return 1.0
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    d = math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3)))
    return d if d > 0 else max(1e-300, max(abs(c) for c in lo + hi) or 1.0)


def far_transform(rng, size):
    R = quat_rot(rng) if rng.random() < 0.8 else signed_perm(rng)
    s = E(rng, -3, 3)
    d = rand_unit(rng) if rng.random() < 0.7 else rng.choice(((1.0, 0.0, 0.0), (0.0, -1.0, 0.0), vunit((1, 1, 1)), vunit((1, -1, 0))))
    off = vmul(d, s * size * E(rng, 3, 8))
    return lambda p: vadd(vmul(mat_apply(R, p), s), off)


def place(rng, A, B, policy):
    size = bbox_diag([A, B])
    if policy == "done":
        return A, B, "as built"
    if policy == "far":
        T = far_transform(rng, size)
        return A.mapped(T), B.mapped(T), "far"
    if policy == "sim":
        T = sim_transform(rng, size)
        return A.mapped(T), B.mapped(T), "similarity"
    r = rng.random()
    if policy == "exact":
        r = r * 0.4
    if r < 0.2:
        return A, B, "none"
    if r < 0.4:
        P = signed_perm(rng)
        e = 2.0 ** rng.randint(-20, 20)
        T = lambda p: vmul(mat_apply(P, p), e)
        return A.mapped(T), B.mapped(T), "permutation"
    if r < 0.5:  # rotation about one axis only
        R = axis_rot(rng.choice(((1, 0, 0), (0, 1, 0), (0, 0, 1))), U(rng, 0, 6.3))
        s = E(rng, -6, 6)
        return A.mapped(lambda p: vmul(mat_apply(R, p), s)), B.mapped(lambda p: vmul(mat_apply(R, p), s)), "axis rotation"
    T = sim_transform(rng, size)
    return A.mapped(T), B.mapped(T), "similarity"


def limit(m, rng):
    if len(m.f) > MAXT:
        keep = sorted(rng.sample(range(len(m.f)), MAXT))
        m = m.copy()
        m.f = [m.f[i] for i in keep]
    return m


def generate(seed):
    rng = random.Random(seed)
    name, fn = KINDS[seed % len(KINDS)]
    A, B, policy = fn(rng)
    A, B, _how = place(rng, A, B, policy)
    return name, limit(A, rng), limit(B, rng)


def write_obj(path, m):
    used = sorted(set(i for f in m.f for i in f))
    remap = {old: k + 1 for k, old in enumerate(used)}
    lines = []
    for i in used:
        p = m.v[i]
        if not all(math.isfinite(c) for c in p):
            raise ValueError("non-finite coordinate in " + path)
        lines.append("v %r %r %r" % (p[0] + 0.0, p[1] + 0.0, p[2] + 0.0))
    for a, b, c in m.f:
        if len({a, b, c}) != 3:
            raise ValueError("repeated index in a face in " + path)
        lines.append("f %d %d %d" % (remap[a], remap[b], remap[c]))
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: %s OUTDIR SEED_FROM SEED_TO\n kinds: %s\n" % (argv[0], " ".join(k for k, _ in KINDS)))
        return 2
    out, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for seed in range(lo, hi):
        name, A, B = generate(seed)
        if not A.f or not B.f:
            raise RuntimeError("seed %d (%s): empty mesh" % (seed, name))
        stem = os.path.join(out, "%06d_%s" % (seed, name))
        write_obj(stem + "_a.obj", A)
        write_obj(stem + "_b.obj", B)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
