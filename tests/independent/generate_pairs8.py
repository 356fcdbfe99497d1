#!/usr/bin/env python3
"""Eighth independent generator of degenerate triangle-mesh pairs for Hausdorff Lens (issue 8).

Written by a helper who read only the docstrings and KINDS lists of generate_pairs.py and
generate_pairs3.py .. generate_pairs7.py (not their code), to aim at configurations they do not
name or name only in passing.  Python 3 standard library only; deterministic per seed
(random.Random(seed)); every mesh has 1..60 triangles and finite coordinates ('v x y z' with
%.17g, 'f i j k' 1-based).

Usage:  python3 tests/independent/generate_pairs8.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/<seed:06d>_<kind>_a.obj and OUTDIR/<seed:06d>_<kind>_b.obj for every seed in
[SEED_FROM, SEED_TO), kind = KINDS[seed % len(KINDS)]; then
        hlens_check_pairs --pairs OUTDIR [--every-target | --thorough]
Kinds ending in "_far" are near-coincident pairs moved 1e3..1e8 sizes from the origin (the checker
then requires a certified interval no wider than 1e-9 of the diagonal); no other kind ends so.

Kinds (36):
  shared_vert_bump       one vertex set (grid or convex polygon) triangulated two ways, 1..3
                         vertices of one mesh moved 1e-14..1e-8 out of the plane
  shared_vert_bump_far   the same, near-coincident, far from the origin
  coplanar_on_edge       coplanar triangles / segments lying exactly on an edge of the other mesh
                         (the whole edge, a sub-segment, beyond its end), optionally hinged by
                         1e-12..1e-3 rad about that edge
  spoke_fan              fans with many nearly collinear spokes (angular gaps 1e-12..1e-4, spans
                         down to 1e-10) against a shifted-hub fan, a lifted hub, a tilted copy, a grid
  edge_thru_vertex       source vertices exactly on target edges (dyadic points), source edges
                         exactly through target vertices; coplanar, lifted or standing fins
  ties_around            3, 4, 5, 6 or 8 rotated copies of a source (and mirror images) around a
                         target at the axis: 3+-way ties, one copy moved 1e-15..1e-9 or none
  sandwich               a target grid exactly halfway between two parallel source layers
                         (different triangulations, gaps 1e-12..1), tie everywhere
  bisector_wedge         two source planes at +-theta (1e-10..0.6 rad) about a line in the target
                         plane (through its interior, along its edge or grid line, outside)
  parallel_gap           grids of different resolution/orientation on planes 1e-12..1e-6 apart,
                         optionally tilted by 1e-14..1e-8
  parallel_gap_far       the same, far from the origin
  rot_inplane_axis       a (flat or slightly curved) mesh against its copy rotated 1e-14..1e-6 rad
                         about an in-plane axis through a vertex, an edge, a point inside or outside
  rot_inplane_axis_far   the same, far from the origin
  f32_partial            a placed mesh against a copy with only some vertices rounded to float32
  f32_partial_far        the same, 1e3..3e4 sizes from the origin (float32 rounding of ~1e-3 of
                         the size at most, still near-coincident)
  edge_lines_cross       2..4 sources (parallel, standing or tilted) whose edge lines cross exactly
                         over a target vertex, at equal or different heights
  huge_reach             sources with one vertex 1e4..1e8 beyond a unit target (huge-aspect
                         triangles, some nearly coplanar with the target)
  needle_target          needles and caps (width 1e-12..1e-4) on grid lines, diagonals or apexes
                         at grid vertices, as targets among a fine source grid
  mixed_scale            1e6-sized triangles carrying 1e-6-sized features (at corners, on edges,
                         inside), both meshes
  mixed_scale_sim        the same under a random similarity (rotated, scaled, moved)
  edge_overlap_partial   coplanar strips whose edges overlap partially along one line, optionally
                         hinged by 1e-13..1e-5 rad
  zero_area_on_edge      zero-area triangles exactly along edges / diagonals of the other mesh,
                         point triangles at its vertices and edge midpoints, standing segments
  dup_ulp                a mesh with faces duplicated on vertices moved 1..4 ulps
  dup_ulp_far            the same, far from the origin
  corrugated             a flat grid against the same vertices moved +-1e-14..1e-8 (checkerboard
                         or random signs) and triangulated otherwise
  corrugated_far         the same, far from the origin
  saddle_quads           non-planar quads (1e-14..1e-6) split along one diagonal against the other
  saddle_quads_far       the same, far from the origin
  cap_apex_on_edge       caps whose apex lies exactly on an edge of the other mesh, or whose long
                         base passes exactly through a vertex of it
  inplane_rot_tiny       a flat mesh against its copy rotated 1e-14..1e-6 rad about its normal
  inplane_rot_tiny_far   the same, far from the origin
  bisector_edge          sources mirrored exactly in a plane that contains a target edge
  fan_hub_on_target      fans (often with nearly collinear spokes) whose hub is exactly at a target
                         vertex, edge midpoint or interior point, coplanar / standing / tilted / cone
  chain_on_edge          a zigzag strip whose vertices lie exactly on the line of a target edge
                         (some beyond its ends), at 0, pi, pi/2 or tiny angles
  step_tiny              a grid with a step of 1e-13..1e-6 (cut or sheared) against a flat grid
  decimal_plane          points of a plane z = c0 + c1 x + c2 y with decimal coefficients and
                         coordinates (not exactly coplanar) triangulated two ways
  decimal_plane_far      the same, far from the origin
Placement (unless a kind says otherwise): none, an exact one (signed axis permutation, power-of-two
scale) or a random similarity (scale 10**U(-6,6), rotation, offset up to 1e4 sizes), applied as
one function to both meshes, so exact coincidences survive rounding identically.
"""

import math
import os
import random
import struct
import sys

MAXTRI = 60


# ----------------------------------------------------------------------------- small vector helpers
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
    return mul(a, 1.0 / n)


def lu(r, lo, hi):
    """10**U(lo, hi)"""
    return 10.0 ** r.uniform(lo, hi)


def rand_dir(r):
    while True:
        v = (r.gauss(0, 1), r.gauss(0, 1), r.gauss(0, 1))
        n = norm(v)
        if n > 1e-3:
            return mul(v, 1.0 / n)


def rot_matrix(axis, ang):
    x, y, z = unit(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def mat_apply(M, p):
    return (M[0][0] * p[0] + M[0][1] * p[1] + M[0][2] * p[2],
            M[1][0] * p[0] + M[1][1] * p[1] + M[1][2] * p[2],
            M[2][0] * p[0] + M[2][1] * p[1] + M[2][2] * p[2])


def rotate_about(p, origin, axis, ang):
    M = rot_matrix(axis, ang)
    return add(origin, mat_apply(M, sub(p, origin)))


def f32(x):
    return struct.unpack('f', struct.pack('f', x))[0]


def nudge(x, k):
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


# ----------------------------------------------------------------------------- meshes
class Mesh:
    def __init__(self, v=None, f=None):
        self.v = list(v or [])
        self.f = list(f or [])

    def addv(self, p):
        self.v.append(tuple(float(c) for c in p))
        return len(self.v) - 1

    def tri(self, a, b, c):
        i = self.addv(a)
        j = self.addv(b)
        k = self.addv(c)
        self.f.append((i, j, k))

    def append(self, other):
        o = len(self.v)
        self.v.extend(other.v)
        self.f.extend((a + o, b + o, c + o) for a, b, c in other.f)
        return self

    def mapped(self, fn):
        return Mesh([fn(p) for p in self.v], self.f)

    def copy(self):
        return Mesh(self.v, self.f)


def grid_pts(nx, ny, w=1.0, h=1.0, x0=0.0, y0=0.0, z=0.0):
    """(nx+1)*(ny+1) points, index i*(ny+1)+j; w, h the cell sizes"""
    return [(x0 + i * w, y0 + j * h, z) for i in range(nx + 1) for j in range(ny + 1)]


def grid_faces(nx, ny, mode, r):
    F = []
    idx = lambda i, j: i * (ny + 1) + j
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            m = mode
            if mode == 'alt':
                m = '/' if (i + j) % 2 == 0 else '\\'
            elif mode == 'rand':
                m = r.choice('/\\')
            if m == '/':
                F += [(a, b, c), (a, c, d)]
            else:
                F += [(a, b, d), (b, c, d)]
    return F


GRID_MODES = ['/', '\\', 'alt', 'rand']


def other_mode(r, m):
    return r.choice([x for x in GRID_MODES if x != m])


def grid_mesh(r, nx, ny, mode=None, **kw):
    mode = mode or r.choice(GRID_MODES)
    return Mesh(grid_pts(nx, ny, **kw), grid_faces(nx, ny, mode, r)), mode


def poly_faces(n, mode, r):
    """triangulations of a convex polygon with vertices 0..n-1"""
    if mode == 'fan':
        k = r.randrange(n)
        return [(k, (k + i) % n, (k + i + 1) % n) for i in range(1, n - 1)]
    if mode == 'zigzag':
        s = r.randrange(n)
        lo, hi = s, s + n - 1
        F = []
        turn = 0
        while hi - lo >= 2:
            if turn == 0:
                F.append((lo % n, (lo + 1) % n, hi % n))
                lo += 1
            else:
                F.append((lo % n, (hi - 1) % n, hi % n))
                hi -= 1
            turn ^= 1
        return F
    # random recursive split
    F = []

    def rec(ids):
        if len(ids) < 3:
            return
        if len(ids) == 3:
            F.append(tuple(ids))
            return
        i = r.randrange(len(ids))
        j = (i + r.randrange(2, len(ids) - 1)) % len(ids)
        if i > j:
            i, j = j, i
        rec(ids[i:j + 1])
        rec(ids[j:] + ids[:i + 1])
    rec(list(range(n)))
    return F


def ellipse_pts(r, n, jitter=True):
    a, b = r.uniform(0.5, 1.0), r.uniform(0.3, 1.0)
    ph = r.uniform(0, 2 * math.pi)
    angs = sorted(r.uniform(0, 2 * math.pi) for _ in range(n)) if jitter else \
        [2 * math.pi * k / n for k in range(n)]
    return [(a * math.cos(t + ph), b * math.sin(t + ph), 0.0) for t in angs]


def flat_patch(r, maxn=5):
    """a flat mesh in z=0 and a second triangulation of the same vertices"""
    if r.random() < 0.55:
        nx, ny = r.randint(2, maxn), r.randint(2, maxn)
        w = 1.0 / nx
        h = r.choice([1.0 / ny, w, 0.5 / ny])
        V = grid_pts(nx, ny, w, h)
        m1 = r.choice(GRID_MODES)
        m2 = other_mode(r, m1) if r.random() < 0.85 else m1
        return V, grid_faces(nx, ny, m1, r), grid_faces(nx, ny, m2, r)
    n = r.randint(5, 16)
    V = ellipse_pts(r, n, r.random() < 0.7)
    modes = ['fan', 'zigzag', 'rand']
    return V, poly_faces(n, r.choice(modes), r), poly_faces(n, r.choice(modes), r)


# ----------------------------------------------------------------------------- placement
def bbox_size(meshes):
    pts = [p for m in meshes for p in m.v]
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    return max(norm(sub(tuple(hi), tuple(lo))), 1e-300)


def signed_perm(r):
    perm = [0, 1, 2]
    r.shuffle(perm)
    M = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        M[i][perm[i]] = r.choice([-1.0, 1.0])
    return M


def rand_rot(r):
    return rot_matrix(rand_dir(r), r.uniform(0, 2 * math.pi))


def place(r, meshes, mode='any', far_range=(3, 8)):
    """one similarity applied to all meshes. mode: any | exact | none | far | sim
    far: offset 10**U(far_range) sizes"""
    if mode == 'any':
        mode = r.choice(['none', 'exact', 'sim', 'sim'])
    if mode == 'none':
        return meshes
    size = bbox_size(meshes)
    if mode == 'exact':
        s = 2.0 ** r.randint(-20, 20)
        R = signed_perm(r)
        off = (0.0, 0.0, 0.0)
        if r.random() < 0.4:
            k = math.floor(math.log2(s * size)) + r.randint(0, 6)
            off = tuple(float(r.randint(-4, 4)) * 2.0 ** k for _ in range(3))
    else:
        s = lu(r, -6, 6)
        R = r.choice([signed_perm(r), rand_rot(r), rand_rot(r)])
        if mode == 'far':
            off = mul(rand_dir(r), s * size * lu(r, *far_range))
        else:
            off = r.choice([(0.0, 0.0, 0.0), mul(rand_dir(r), s * size * lu(r, 0, 4))])
    return [m.mapped(lambda p: add(off, mul(mat_apply(R, p), s))) for m in meshes]


# ----------------------------------------------------------------------------- kinds
def k_shared_vert_bump(r, far=False):
    V, FA, FB = flat_patch(r)
    VA, VB = list(V), list(V)
    target = r.choice(['B', 'B', 'A', 'both'])
    for _ in range(r.randint(1, 3)):
        i = r.randrange(len(V))
        for which in ('A', 'B'):
            if target in (which, 'both'):
                L = VA if which == 'A' else VB
                dz = r.choice([-1, 1]) * lu(r, -14, -8)
                p = L[i]
                if r.random() < 0.25:  # also a tiny in-plane move
                    p = (p[0] + r.choice([-1, 1]) * lu(r, -14, -8), p[1], p[2])
                L[i] = (p[0], p[1], p[2] + dz)
    A, B = Mesh(VA, FA), Mesh(VB, FB)
    return place(r, [A, B], 'far' if far else 'any')


def k_coplanar_on_edge(r):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    A, _ = grid_mesh(r, nx, ny)
    f = r.choice(A.f)
    e = r.randrange(3)
    P, Q = A.v[f[e]], A.v[f[(e + 1) % 3]]
    d = sub(Q, P)
    n = (-d[1], d[0], 0.0)
    B = Mesh()
    ts = [-0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5]
    for _ in range(r.randint(1, 4)):
        c = r.choice(['full', 'sub', 'zero', 'thin', 'beyond'])
        side = r.choice([-1.0, 1.0])
        pt = lambda t: add(P, mul(d, t))
        if c == 'full':
            B.tri(P, Q, add(pt(0.5), mul(n, side * r.choice([0.5, 0.25, 1.0]))))
        elif c == 'sub':
            t1, t2 = sorted(r.sample(ts, 2))
            B.tri(pt(t1), pt(t2), add(pt(r.choice(ts)), mul(n, side * 0.5)))
        elif c == 'zero':
            t1, t2, t3 = r.sample(ts, 3)
            B.tri(pt(t1), pt(t2), pt(t3))
        elif c == 'thin':
            t1, t2 = sorted(r.sample(ts, 2))
            B.tri(pt(t1), pt(t2), add(pt(r.uniform(t1, t2)), mul(n, side * lu(r, -12, -4))))
        else:
            B.tri(pt(1.0), pt(r.choice([1.5, 2.0, 3.0])), add(pt(1.25), mul(n, side * 0.25)))
    if r.random() < 0.5:
        ang = r.choice([-1, 1]) * lu(r, -12, -3)
        B = B.mapped(lambda p: rotate_about(p, P, d, ang))
    if r.random() < 0.5:
        A, B = B, A
    return place(r, [A, B], 'any')


def spoke_angles(r):
    n = r.randint(6, 40)
    mode = r.choice(['cluster', 'narrow', 'opposite'])
    if mode == 'cluster':
        span = r.choice([2 * math.pi, math.pi, math.pi / 2])
        base = sorted(r.uniform(0, span) for _ in range(max(3, n // 3)))
        angs = []
        for b in base:
            angs.append(b)
            if r.random() < 0.6:
                angs.append(b + lu(r, -12, -4))
        full = span == 2 * math.pi
    elif mode == 'narrow':
        tot = lu(r, -10, -2)
        angs = sorted(r.uniform(0, tot) for _ in range(n))
        full = False
    else:  # spokes near angle 0 and near pi: fan covering a half plane with slivers at both ends
        k = n // 2
        angs = sorted([r.uniform(0, lu(r, -10, -3)) for _ in range(k)] +
                      [math.pi - r.uniform(0, lu(r, -10, -3)) for _ in range(k)])
        if r.random() < 0.5:
            angs.insert(k, math.pi / 2)
        full = False
    return sorted(angs)[:MAXTRI], full


def fan_mesh(hub, angs, full, radii, z_rim=0.0, plane=None):
    """plane: (u, v) in-plane unit vectors (default x, y)"""
    u, v = plane or ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    M = Mesh()
    h = M.addv(hub)
    ids = []
    for a, rad in zip(angs, radii):
        p = add(hub, add(mul(u, rad * math.cos(a)), mul(v, rad * math.sin(a))))
        p = (p[0], p[1], p[2] + z_rim)
        ids.append(M.addv(p))
    m = len(ids)
    for i in range(m - 1 + (1 if full else 0)):
        if len(M.f) >= MAXTRI:
            break
        M.f.append((h, ids[i], ids[(i + 1) % m]))
    return M


def k_spoke_fan(r):
    angs, full = spoke_angles(r)
    radii = [1.0 if r.random() < 0.5 else r.uniform(0.5, 1.0) for _ in angs]
    A = fan_mesh((0.0, 0.0, 0.0), angs, full, radii)
    c = r.choice(['shift_hub', 'lift_hub', 'tilt', 'grid', 'rot'])
    if c == 'shift_hub':
        k = r.randrange(len(angs))
        t = lu(r, -12, -2)
        hub = (t * math.cos(angs[k]), t * math.sin(angs[k]), 0.0)
        B = Mesh(list(A.v), A.f)
        B.v[0] = hub
    elif c == 'lift_hub':
        B = Mesh(list(A.v), A.f)
        B.v[0] = (0.0, 0.0, r.choice([-1, 1]) * lu(r, -12, -2))
    elif c == 'tilt':
        k = r.randrange(len(angs))
        ax = (math.cos(angs[k]), math.sin(angs[k]), 0.0)
        ang = lu(r, -12, -4)
        B = A.mapped(lambda p: rotate_about(p, (0.0, 0.0, 0.0), ax, ang))
    elif c == 'grid':
        nx, ny = r.randint(2, 5), r.randint(2, 5)
        B, _ = grid_mesh(r, nx, ny, w=2.0 / nx, h=2.0 / ny, x0=-1.0, y0=-1.0,
                         z=r.choice([0.0, 0.0, lu(r, -12, -4)]))
    else:
        ang = r.choice([-1, 1]) * lu(r, -13, -5)
        B = A.mapped(lambda p: rotate_about(p, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), ang))
    if r.random() < 0.5:
        A, B = B, A
    return place(r, [A, B], 'any')


def rand_int_tri(r, lo=0, hi=8):
    while True:
        pts = [(float(r.randint(lo, hi)), float(r.randint(lo, hi)), 0.0) for _ in range(3)]
        if abs(cross(sub(pts[1], pts[0]), sub(pts[2], pts[0]))[2]) > 0:
            return pts


def k_edge_thru_vertex(r):
    B = Mesh()
    for _ in range(r.randint(1, 4)):
        B.tri(*rand_int_tri(r))
    A = Mesh()
    for _ in range(r.randint(1, 5)):
        f = r.choice(B.f)
        e = r.randrange(3)
        P, Q = B.v[f[e]], B.v[f[(e + 1) % 3]]
        if r.random() < 0.6:  # source vertex on the target edge
            X = add(P, mul(sub(Q, P), r.randint(0, 8) / 8.0))
            c = r.choice(['coplanar', 'above', 'fin', 'below', 'cross'])
            rnd = lambda: (float(r.randint(-2, 10)), float(r.randint(-2, 10)))
            if c == 'coplanar':
                a, b = rnd(), rnd()
                A.tri(X, (a[0], a[1], 0.0), (b[0], b[1], 0.0))
            elif c == 'above':
                a, b = rnd(), rnd()
                A.tri(X, (a[0], a[1], float(r.randint(1, 4))), (b[0], b[1], float(r.randint(0, 4))))
            elif c == 'below':
                a, b = rnd(), rnd()
                A.tri(X, (a[0], a[1], -float(r.randint(1, 4))), (b[0], b[1], -float(r.randint(0, 4))))
            elif c == 'fin':
                dd = sub(Q, P)
                A.tri(X, add(X, (0.0, 0.0, 2.0)), add(X, (dd[0] * 0.5, dd[1] * 0.5, 1.0)))
            else:  # crossing the target plane at X
                h = float(r.randint(1, 3))
                a = rnd()
                A.tri(X, (a[0], a[1], h), (2 * X[0] - a[0], 2 * X[1] - a[1], -h))
        else:  # source edge exactly through a target vertex (V the midpoint)
            Vt = P
            u = (float(r.randint(-3, 3)) / 2, float(r.randint(-3, 3)) / 2, float(r.randint(-2, 2)) / 2)
            if u == (0.0, 0.0, 0.0):
                u = (1.0, 0.5, 0.0)
            w = (float(r.randint(-4, 4)), float(r.randint(-4, 4)), float(r.randint(-3, 3)))
            A.tri(add(Vt, u), sub(Vt, u), add(Vt, w))
    if r.random() < 0.5:
        A, B = B, A
    return place(r, [A, B], r.choice(['exact', 'any']))


def k_ties_around(r):
    n = r.choice([3, 4, 4, 5, 6, 8])
    B = Mesh()
    tgt = r.choice(['equi', 'grid', 'tiny', 'offaxis'])
    if tgt == 'equi':
        rr = r.uniform(0.2, 1.0)
        B.tri(*[(rr * math.cos(math.pi / 2 + 2 * math.pi * k / 3), rr * math.sin(math.pi / 2 + 2 * math.pi * k / 3), 0.0)
                for k in range(3)])
    elif tgt == 'grid':
        G, _ = grid_mesh(r, 2, 2, w=0.5, h=0.5, x0=-0.5, y0=-0.5)
        B = G
    elif tgt == 'tiny':
        e = lu(r, -9, -3)
        B.tri((0.0, 0.0, 0.0), (e, 0.0, 0.0), (0.0, e, 0.0))
    else:
        B.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.3, 0.8, 0.0))
    R = r.uniform(1.1, 3.0)
    proto = [(R + r.uniform(-0.3, 0.8), r.uniform(-0.8, 0.8), r.uniform(-1.0, 1.0)) for _ in range(3)]
    if r.random() < 0.3:  # proto parallel to the target plane
        zz = r.choice([0.0, r.uniform(0.1, 1.0)])
        proto = [(p[0], p[1], zz) for p in proto]
    A = Mesh()
    mirror = r.random() < 0.35
    for k in range(n):
        if n == 4:
            rot = [lambda p: p, lambda p: (-p[1], p[0], p[2]), lambda p: (-p[0], -p[1], p[2]),
                   lambda p: (p[1], -p[0], p[2])][k]
        else:
            c, s = math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)
            rot = lambda p, c=c, s=s: (c * p[0] - s * p[1], s * p[0] + c * p[1], p[2])
        tri = [rot(p) for p in proto]
        A.tri(*tri)
        if mirror:
            A.tri(*[(p[0], p[1], -p[2]) for p in tri])
    if r.random() < 0.4:
        j = r.randrange(len(A.v))
        A.v[j] = add(A.v[j], mul(rand_dir(r), R * lu(r, -15, -9)))
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_sandwich(r):
    nx, ny = r.randint(2, 4), r.randint(2, 3)
    B, m = grid_mesh(r, nx, ny, w=1.0 / nx, h=1.0 / ny)
    h = lu(r, -12, 0)
    h2 = h if r.random() < 0.6 else h * (1 + r.choice([-1, 1]) * lu(r, -15, -6))
    A = Mesh()
    for z in (h, -h2):
        c = r.choice(['same', 'other', 'coarse', 'shifted', 'rotated'])
        if c == 'same':
            L = Mesh([(p[0], p[1], z) for p in B.v], B.f)
        elif c == 'other':
            L = Mesh([(p[0], p[1], z) for p in B.v], grid_faces(nx, ny, other_mode(r, m), r))
        elif c == 'coarse':
            L, _ = grid_mesh(r, 1, 1, z=z)
        elif c == 'shifted':
            k = r.randint(1, 3)
            L, _ = grid_mesh(r, k, k, w=1.0 / k, h=1.0 / k, x0=r.choice([0.0, 0.25, 0.5]),
                             y0=r.choice([0.0, -0.25]), z=z)
        else:
            L, _ = grid_mesh(r, 2, 2, w=0.8, h=0.8, x0=-0.8, y0=-0.8, z=z)
            ang = r.uniform(0, math.pi)
            L = L.mapped(lambda p: rotate_about(p, (0.5, 0.5, z), (0.0, 0.0, 1.0), ang))
        A.append(L)
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_bisector_wedge(r):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    B, _ = grid_mesh(r, nx, ny, w=1.0 / nx, h=1.0 / ny)
    y0 = r.choice([0.5, 0.0, 1.0 / ny, -0.3, r.uniform(0, 1)])
    th = lu(r, -10, math.log10(0.6))
    half = r.random() < 0.4
    umin = 0.0 if half else -1.5
    A = Mesh()
    nu = r.randint(1, 4)
    ncol = r.randint(1, 3)
    up = Mesh()
    us = [umin + (1.5 - umin) * k / nu for k in range(nu + 1)]
    xs = [-0.25 + 1.5 * k / ncol for k in range(ncol + 1)]
    for i, x in enumerate(xs):
        for u in us:
            up.addv((x, y0 + u * math.cos(th), u * math.sin(th)))
    gf = grid_faces(ncol, nu, r.choice(GRID_MODES), r)
    up.f = gf
    A.append(up)
    lo = up.mapped(lambda p: (p[0], p[1], -p[2]))
    if r.random() < 0.3:  # mirrored copy triangulated otherwise
        lo.f = grid_faces(ncol, nu, r.choice(GRID_MODES), r)
    A.append(lo)
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_parallel_gap(r, far=False):
    nx, ny = r.randint(2, 5), r.randint(2, 5)
    A, _ = grid_mesh(r, nx, ny, w=1.0 / nx, h=1.0 / ny)
    mx, my = r.randint(1, 5), r.randint(1, 5)
    B, _ = grid_mesh(r, mx, my, w=1.0 / mx, h=1.0 / my)
    if r.random() < 0.4:
        ang = r.choice([r.uniform(0, math.pi), lu(r, -12, -3)])
        B = B.mapped(lambda p: rotate_about(p, (0.5, 0.5, 0.0), (0.0, 0.0, 1.0), ang))
    d = r.choice([-1, 1]) * lu(r, -12, -6)
    B = B.mapped(lambda p: (p[0], p[1], p[2] + d))
    if r.random() < 0.5:
        ax = rand_dir(r)
        ax = (ax[0], ax[1], 0.0)
        ang = lu(r, -14, -8)
        c = (r.uniform(0, 1), r.uniform(0, 1), d)
        B = B.mapped(lambda p: rotate_about(p, c, ax, ang))
    return place(r, [A, B], 'far' if far else 'any')


def curved(r, V):
    c = r.choice([0.0, 0.0, lu(r, -3, -1)])
    c2 = r.choice([0.0, lu(r, -3, -1)])
    return [(p[0], p[1], p[2] + c * (p[0] * p[0] + p[1] * p[1]) + c2 * p[0] * p[1]) for p in V]


def k_rot_inplane_axis(r, far=False):
    V, FA, FB = flat_patch(r)
    V = curved(r, V)
    A = Mesh(V, FA)
    c = r.choice(['vertex', 'edge', 'inside', 'outside'])
    if c == 'vertex':
        o = r.choice(V)
        ax = rand_dir(r)
        ax = (ax[0], ax[1], 0.0)
    elif c == 'edge':
        f = r.choice(FA)
        o, q = V[f[0]], V[f[1]]
        ax = sub(q, o)
    elif c == 'inside':
        o = (r.uniform(0.2, 0.8) * V[0][0] + 0.1, r.uniform(-0.3, 0.5), 0.0)
        ax = (math.cos(r.uniform(0, 7)), math.sin(r.uniform(0, 7)), 0.0)
    else:
        o = (3.0, r.uniform(-2, 2), 0.0)
        ax = (math.cos(r.uniform(0, 7)), math.sin(r.uniform(0, 7)), 0.0)
    if norm(ax) == 0:
        ax = (1.0, 0.0, 0.0)
    ang = r.choice([-1, 1]) * lu(r, -14, -6)
    VB = [rotate_about(p, o, ax, ang) for p in V]
    B = Mesh(VB, FB if r.random() < 0.5 else FA)
    return place(r, [A, B], 'far' if far else 'any')


def k_f32_partial(r, far=False):
    V, FA, FB = flat_patch(r)
    V = curved(r, V)
    A = Mesh(V, FA)
    # far: at most 10**4.5 sizes away, so that float32 rounding (6e-8 of the coordinates) stays
    # within ~2e-3 of the size and the pair is still near-coincident
    A, = place(r, [A], 'far' if far else 'sim', far_range=(3, 4.5))
    frac = r.choice([0.1, 0.3, 0.5, 1.0])
    VB = [tuple(f32(c) for c in p) if r.random() < frac else p for p in A.v]
    if all(a == b for a, b in zip(A.v, VB)):
        VB[0] = tuple(f32(c) for c in VB[0])
    B = Mesh(VB, FB if r.random() < 0.4 else FA)
    if r.random() < 0.2:  # A also partially rounded, other subset
        A = Mesh([tuple(f32(c) for c in p) if r.random() < 0.3 else p for p in A.v], A.f)
    return [A, B]


def k_edge_lines_cross(r):
    B = Mesh()
    P = (0.0, 0.0, 0.0)
    if r.random() < 0.6:  # fan round P
        k = r.randint(3, 6)
        rim = [(float(round(4 * math.cos(2 * math.pi * i / k + 0.3))), float(round(4 * math.sin(2 * math.pi * i / k + 0.3))), 0.0)
               for i in range(k)]
        for i in range(k):
            if rim[i] != rim[(i + 1) % k]:
                B.tri(P, rim[i], rim[(i + 1) % k])
    else:
        B.tri(P, (4.0, 1.0, 0.0), (1.0, 3.0, 0.0))
    dirs = [(1, 0), (0, 1), (1, 1), (1, -1), (2, 1), (1, 2), (-2, 1), (3, -1)]
    A = Mesh()
    hs = [1.0, 0.5, 2.0, 0.25]
    heq = r.random() < 0.5
    ns = r.randint(2, 4)
    for d in r.sample(dirs, ns):
        d3 = (float(d[0]), float(d[1]), 0.0)
        nrm = (-d3[1], d3[0], 0.0)
        h = hs[0] if heq else r.choice(hs) * r.choice([1, -1])
        t1 = r.choice([-3.0, -1.0, 0.5, 1.0, 0.0])
        t2 = t1 + r.choice([1.0, 2.0, 4.0])
        side = r.choice([1.0, -1.0])
        L = lambda t: (d3[0] * t, d3[1] * t, h)
        c = r.choice(['parallel', 'standing', 'tilted', 'vertex_above'])
        if c == 'parallel':
            A.tri(L(t1), L(t2), add(L((t1 + t2) / 2), mul(nrm, side)))
        elif c == 'standing':
            A.tri(L(t1), L(t2), add(L((t1 + t2) / 2), (0.0, 0.0, side * 2.0)))
        elif c == 'tilted':
            A.tri(L(t1), L(t2), add(L(t1), (nrm[0] * side, nrm[1] * side, 1.0)))
        else:
            A.tri(L(0.0), add(L(2.0), mul(nrm, side)), add(L(2.0), mul(nrm, -side)))
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], r.choice(['exact', 'any']))


def k_huge_reach(r):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    B, _ = grid_mesh(r, nx, ny, w=1.0 / nx, h=1.0 / ny)
    A = Mesh()
    for _ in range(r.randint(2, 6)):
        p = (r.uniform(-0.5, 1.5), r.uniform(-0.5, 1.5), r.uniform(-0.5, 0.5))
        q = (r.uniform(-0.5, 1.5), r.uniform(-0.5, 1.5), r.uniform(-0.5, 0.5))
        if r.random() < 0.3:
            q = add(p, mul(rand_dir(r), lu(r, -6, -2)))
        L = lu(r, 4, 8)
        c = r.choice(['any', 'inplane', 'grazing'])
        if c == 'any':
            far = add(p, mul(rand_dir(r), L))
        elif c == 'inplane':
            a = r.uniform(0, 2 * math.pi)
            far = (p[0] + L * math.cos(a), p[1] + L * math.sin(a), r.choice([0.0, p[2]]))
            if far[2] == 0.0:
                p = (p[0], p[1], 0.0)
                q = (q[0], q[1], r.choice([0.0, q[2]]))
        else:  # huge triangle whose plane passes within a tiny distance over the target
            a = r.uniform(0, 2 * math.pi)
            e = lu(r, -12, -6)
            p = (p[0], p[1], e)
            q = (q[0], q[1], e * r.choice([1.0, -1.0, 0.5]))
            far = (p[0] + L * math.cos(a), p[1] + L * math.sin(a), e + r.choice([-1, 1]) * L * lu(r, -14, -8))
        A.tri(p, q, far)
    if r.random() < 0.3:  # one huge-aspect target too
        a = r.uniform(0, 2 * math.pi)
        L = lu(r, 4, 8)
        B.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (L * math.cos(a), L * math.sin(a), 0.0))
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_needle_target(r):
    nx, ny = r.randint(3, 6), r.randint(3, 5)
    A, _ = grid_mesh(r, nx, ny)
    A.v = curved(r, A.v) if r.random() < 0.2 else A.v
    B = Mesh()
    for _ in range(r.randint(1, 6)):
        w = lu(r, -12, -4)
        zoff = r.choice([0.0, 0.0, lu(r, -12, -4)])
        i, j = r.randint(0, nx), r.randint(0, ny)
        G = (float(i), float(j), zoff)
        c = r.choice(['line', 'diag', 'random', 'cap_vertex', 'needle', 'vertical'])
        if c in ('line', 'diag'):
            d = (1.0, 0.0, 0.0) if c == 'line' else (1.0, 1.0, 0.0)
            if r.random() < 0.5:
                d = (d[1], d[0], 0.0) if c == 'line' else (1.0, -1.0, 0.0)
            k = r.randint(1, 3)
            Q = add(G, mul(d, k))
            n = unit((-d[1], d[0], 0.0))
            B.tri(G, Q, add(add(G, mul(d, k * r.choice([0.5, 0.25, 0.0]))), mul(n, w)))
        elif c == 'random':
            a = r.uniform(0, 2 * math.pi)
            d = (math.cos(a), math.sin(a), 0.0)
            n = (-d[1], d[0], 0.0)
            L = r.uniform(0.5, 3)
            B.tri(G, add(G, mul(d, L)), add(add(G, mul(d, L * r.uniform(0.2, 0.8))), mul(n, w)))
        elif c == 'cap_vertex':
            a = r.uniform(0, 2 * math.pi)
            d = (math.cos(a), math.sin(a), 0.0)
            n = (-d[1], d[0], 0.0)
            P0 = sub(sub(G, mul(d, r.uniform(0.5, 2))), mul(n, w))
            Q0 = sub(add(G, mul(d, r.uniform(0.5, 2))), mul(n, w))
            B.tri(P0, Q0, G)
        elif c == 'needle':
            a = r.uniform(0, 2 * math.pi)
            d = (math.cos(a), math.sin(a), 0.0)
            n = (-d[1], d[0], 0.0)
            L = r.uniform(0.5, 3)
            B.tri(G, add(G, mul(n, w)), add(G, mul(d, L)))
        else:
            L = r.uniform(0.5, 3)
            B.tri(G, add(G, (L, 0.0, 0.0)), add(G, (L * 0.5, 0.0, w)))
    if r.random() < 0.25:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_mixed_scale(r, sim=False):
    Lg = 1e6
    sm = 1e-6
    A = Mesh([(0.0, 0.0, 0.0), (Lg, 0.0, 0.0), (Lg, Lg, 0.0), (0.0, Lg, 0.0)], [(0, 1, 2), (0, 2, 3)])
    B = Mesh(list(A.v), [(0, 1, 3), (1, 2, 3)] if r.random() < 0.7 else [(0, 1, 2), (0, 2, 3)])
    spots = [(0.0, 0.0), (Lg, 0.0), (Lg / 2, 0.0), (Lg / 2, Lg / 2), (r.uniform(0, Lg), r.uniform(0, Lg)),
             (Lg / 4, Lg / 4)]
    for M in (A, B):
        for _ in range(r.randint(1, 4)):
            x, y = r.choice(spots)
            z = r.choice([0.0, sm, -sm, r.uniform(-1, 1) * sm * 1e-3])
            c = r.choice(['flat', 'up', 'cluster'])
            if c == 'flat':
                M.tri((x, y, z), (x + sm, y, z), (x, y + sm, z))
            elif c == 'up':
                M.tri((x, y, z), (x + sm, y, z), (x, y, z + sm))
            else:
                for k in range(3):
                    M.tri((x, y, z), (x + sm * math.cos(k), y + sm * math.sin(k), z),
                          (x + sm * math.cos(k + 1), y + sm * math.sin(k + 1), z + r.choice([0.0, sm])))
    if r.random() < 0.3:  # a huge sliver spanning the big quad
        A.tri((0.0, 0.0, sm), (Lg, Lg, sm), (Lg / 2, Lg / 2 + sm, sm))
    s = r.choice([1.0, 1.0, 2.0 ** -20, 1e-6])
    if s != 1.0:
        A = A.mapped(lambda p: mul(p, s))
        B = B.mapped(lambda p: mul(p, s))
    if sim:  # a random similarity (rotation not axis-aligned, scale 10**U(-6,6), offset)
        return place(r, [A, B], 'sim')
    return place(r, [A, B], r.choice(['none', 'exact']))


def k_edge_overlap_partial(r):
    def strip(breaks, sides):
        M = Mesh()
        for k in range(len(breaks) - 1):
            a, b = breaks[k], breaks[k + 1]
            s = sides[k % len(sides)]
            M.tri((a, 0.0, 0.0), (b, 0.0, 0.0), ((a + b) / 2 + r.choice([0.0, 0.5, -0.5]), s * r.choice([0.5, 1.0, 2.0]), 0.0))
        return M
    ba = sorted(set(float(r.randint(0, 16)) for _ in range(r.randint(3, 8))))
    bb = sorted(set(float(r.randint(-2, 18)) / r.choice([1, 2]) for _ in range(r.randint(3, 8))))
    if len(ba) < 2:
        ba = [0.0, 4.0]
    if len(bb) < 2:
        bb = [1.0, 6.0]
    A = strip(ba, r.choice([[1.0], [-1.0], [1.0, -1.0]]))
    B = strip(bb, r.choice([[1.0], [-1.0], [1.0, -1.0]]))
    if r.random() < 0.4:
        ang = r.choice([-1, 1]) * lu(r, -13, -5)
        B = B.mapped(lambda p: rotate_about(p, (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), ang))
    return place(r, [A, B], 'any')


def k_zero_area_on_edge(r):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    A, _ = grid_mesh(r, nx, ny)
    B = Mesh()
    for _ in range(r.randint(2, 8)):
        f = r.choice(A.f)
        e = r.randrange(3)
        P, Q = A.v[f[e]], A.v[f[(e + 1) % 3]]
        M = mul(add(P, Q), 0.5)
        d = sub(Q, P)
        c = r.choice(['seg', 'subseg', 'rep', 'point_v', 'point_m', 'beyond', 'perp', 'stand'])
        if c == 'seg':
            B.tri(P, Q, M)
        elif c == 'subseg':
            B.tri(add(P, mul(d, 0.25)), add(P, mul(d, 0.75)), M)
        elif c == 'rep':
            B.tri(P, P, Q)
        elif c == 'point_v':
            B.tri(P, P, P)
        elif c == 'point_m':
            B.tri(M, M, M)
        elif c == 'beyond':
            B.tri(add(P, mul(d, -1.0)), add(P, mul(d, 2.0)), M)
        elif c == 'perp':
            n = (-d[1], d[0], 0.0)
            B.tri(add(M, mul(n, 0.5)), sub(M, mul(n, 0.5)), M)
        else:
            h = r.choice([0.5, 1.0, 2.0 ** -30])
            B.tri(P, add(P, (0.0, 0.0, h)), add(P, (0.0, 0.0, h / 2)))
    if r.random() < 0.6:
        B.tri(*rand_int_tri(r, 0, max(nx, ny)))
    if r.random() < 0.4:
        A, B = B, A
    return place(r, [A, B], r.choice(['exact', 'any']))


def k_dup_ulp(r, far=False):
    V, FA, FB = flat_patch(r, 4)
    V = curved(r, V)
    A = Mesh(V, FA)
    B = Mesh(V, FB if r.random() < 0.5 else FA)
    A, B = place(r, [A, B], 'far' if far else 'any')

    def dupl(M):
        M = M.copy()
        for _ in range(r.randint(1, 4)):
            if len(M.f) >= MAXTRI:
                break
            f = r.choice(M.f)
            ids = list(f)
            k = r.randrange(3)
            p = list(M.v[ids[k]])
            ax = r.randrange(3)
            p[ax] = nudge(p[ax], r.choice([-4, -2, -1, 1, 2, 3]))
            M.v.append(tuple(p))
            ids[k] = len(M.v) - 1
            if r.random() < 0.3:
                ids = ids[::-1]
            M.f.append(tuple(ids))
        return M
    A = dupl(A)
    if r.random() < 0.4:
        B = dupl(B)
    return [A, B]


def k_corrugated(r, far=False):
    nx, ny = r.randint(2, 5), r.randint(2, 5)
    m1 = r.choice(GRID_MODES)
    V = grid_pts(nx, ny, 1.0 / nx, 1.0 / ny)
    A = Mesh(V, grid_faces(nx, ny, m1, r))
    a = lu(r, -14, -8)
    pat = r.choice(['checker', 'random', 'row'])
    VB = []
    for i in range(nx + 1):
        for j in range(ny + 1):
            s = (-1) ** (i + j) if pat == 'checker' else ((-1) ** i if pat == 'row' else r.choice([-1, 1, 0]))
            p = V[i * (ny + 1) + j]
            VB.append((p[0], p[1], s * a))
    B = Mesh(VB, grid_faces(nx, ny, other_mode(r, m1) if r.random() < 0.8 else m1, r))
    return place(r, [A, B], 'far' if far else 'any')


def k_saddle_quads(r, far=False):
    nx, ny = r.randint(1, 5), r.randint(1, 5)
    V = grid_pts(nx, ny, 1.0 / nx, 1.0 / ny)
    a = lu(r, -14, -6)
    V = [(p[0], p[1], a * r.uniform(-1, 1)) for p in V]
    pa = r.choice([('/', '\\'), ('alt', 'rand'), ('\\', '/')])
    if pa[0] == 'alt':
        FA = grid_faces(nx, ny, 'alt', r)
        # B: the opposite diagonal in every cell
        FB = []
        idx = lambda i, j: i * (ny + 1) + j
        for i in range(nx):
            for j in range(ny):
                q = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1))
                if (i + j) % 2 == 1:
                    FB += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
                else:
                    FB += [(q[0], q[1], q[3]), (q[1], q[2], q[3])]
    else:
        FA = grid_faces(nx, ny, pa[0], r)
        FB = grid_faces(nx, ny, pa[1], r)
    return place(r, [Mesh(V, FA), Mesh(V, FB)], 'far' if far else 'any')


def k_cap_apex_on_edge(r):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    A, _ = grid_mesh(r, nx, ny)
    B = Mesh()
    for _ in range(r.randint(1, 5)):
        if r.random() < 0.6:
            f = r.choice(A.f)
            e = r.randrange(3)
            P, Q = A.v[f[e]], A.v[f[(e + 1) % 3]]
            X = add(P, mul(sub(Q, P), r.choice([0.25, 0.5, 0.75, 0.125])))
        else:
            X = r.choice(A.v)
        w = lu(r, -12, -3)
        c = r.choice(['apex', 'apex', 'base_thru'])
        a = r.choice([0.0, math.pi / 4, math.pi / 2, r.uniform(0, math.pi)])
        d = (math.cos(a), math.sin(a), 0.0) if a not in (0.0, math.pi / 2) else \
            ((1.0, 0.0, 0.0) if a == 0.0 else (0.0, 1.0, 0.0))
        if a == math.pi / 4:
            d = (1.0, 1.0, 0.0)
        n = (-d[1], d[0], 0.0)
        lift = r.choice([0.0, 0.0, 0.5, lu(r, -12, -4)])
        L1, L2 = r.uniform(0.3, 2.0), r.uniform(0.3, 2.0)
        if c == 'apex':
            base = sub(X, mul(n, w))
            B.tri(X, add(sub(base, mul(d, L1)), (0, 0, lift)), add(add(base, mul(d, L2)), (0, 0, lift)))
        else:  # a vertex of A exactly on B's long base, exact dyadic d
            G = r.choice(A.v)
            l1, l2 = float(r.randint(1, 4)) / 2, float(r.randint(1, 4)) / 2
            B.tri(sub(G, mul(d, l1)), add(G, mul(d, l2)), add(add(G, mul(d, (l2 - l1) / 2)), add(mul(n, w), (0, 0, lift))))
    if r.random() < 0.4:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_inplane_rot_tiny(r, far=False):
    V, FA, FB = flat_patch(r)
    A = Mesh(V, FA)
    c = r.choice(['centroid', 'vertex', 'outside'])
    o = (0.3, 0.2, 0.0) if c == 'centroid' else (r.choice(V) if c == 'vertex' else (5.0, -3.0, 0.0))
    ang = r.choice([-1, 1]) * lu(r, -14, -6)
    VB = [rotate_about(p, o, (0.0, 0.0, 1.0), ang) for p in V]
    if r.random() < 0.3:
        lz = r.choice([-1, 1]) * lu(r, -13, -7)
        VB = [(p[0], p[1], p[2] + lz) for p in VB]
    B = Mesh(VB, FB if r.random() < 0.5 else FA)
    return place(r, [A, B], 'far' if far else 'any')


def k_bisector_edge(r):
    B = Mesh()
    a, b = float(r.randint(-2, 0)), float(r.randint(1, 4))
    phi = r.choice([0.0, 0.0, r.uniform(0, math.pi)])
    c, s = math.cos(phi), math.sin(phi)
    for side in r.choice([[1.0], [-1.0], [1.0, -1.0]]):
        for _ in range(r.randint(1, 2)):
            t = (r.uniform(a, b), side * r.uniform(0.3, 2.0))
            B.tri((a, 0.0, 0.0), (b, 0.0, 0.0), (t[0], c * t[1], s * t[1]))
    A = Mesh()
    for _ in range(r.randint(1, 3)):
        S = [(r.uniform(-3, 5), r.uniform(0.1, 3.0) * r.choice([1, 1, 0.01]), r.uniform(-2, 2)) for _ in range(3)]
        if r.random() < 0.3:  # touching the mirror plane
            S[0] = (S[0][0], 0.0, S[0][2])
        A.tri(*S)
        M = [(p[0], -p[1], p[2]) for p in S]
        if r.random() < 0.25:
            k = r.randrange(3)
            M[k] = add(M[k], mul(rand_dir(r), lu(r, -15, -10)))
        A.tri(*M)
    if r.random() < 0.3:  # a source in the mirror plane itself
        A.tri((r.uniform(-2, 4), 0.0, 0.5), (r.uniform(-2, 4), 0.0, 1.5), (r.uniform(-2, 4), 0.0, r.uniform(-2, 2)))
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_fan_hub_on_target(r):
    nx, ny = r.randint(2, 4), r.randint(2, 4)
    B, _ = grid_mesh(r, nx, ny)
    c = r.choice(['vertex', 'edge', 'face'])
    if c == 'vertex':
        H = r.choice(B.v)
    elif c == 'edge':
        f = r.choice(B.f)
        H = mul(add(B.v[f[0]], B.v[f[1]]), 0.5)
    else:
        f = r.choice(B.f)
        H = mul(add(add(B.v[f[0]], B.v[f[1]]), mul(B.v[f[2]], 2.0)), 0.25)
    angs, full = spoke_angles(r) if r.random() < 0.7 else ([2 * math.pi * k / 8 for k in range(8)], True)
    angs = angs[:30]
    radii = [r.uniform(0.5, 2.0) for _ in angs]
    p = r.choice(['coplanar', 'standing', 'tilted', 'tiny_tilt', 'cone'])
    zr = 0.0
    if p == 'coplanar':
        pl = None
    elif p == 'standing':
        a = r.choice([0.0, math.pi / 2, r.uniform(0, math.pi)])
        pl = ((math.cos(a), math.sin(a), 0.0), (0.0, 0.0, 1.0))
    elif p in ('tilted', 'tiny_tilt'):
        t = r.uniform(0.1, 1.4) if p == 'tilted' else lu(r, -12, -4)
        pl = ((1.0, 0.0, 0.0), (0.0, math.cos(t), math.sin(t)))
    else:
        pl = None
        zr = r.choice([-1, 1]) * lu(r, -12, 0)
    A = fan_mesh(H, angs, full, radii, zr, pl)
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_chain_on_edge(r):
    B = Mesh()
    ex = 8.0
    for side in r.choice([[1.0], [-1.0], [1.0, -1.0]]):
        B.tri((0.0, 0.0, 0.0), (ex, 0.0, 0.0), (float(r.randint(0, 8)), side * float(r.randint(1, 4)), 0.0))
    phi = r.choice([0.0, math.pi, math.pi / 2, lu(r, -12, -4), math.pi - lu(r, -12, -4),
                    math.pi / 2 + r.choice([-1, 1]) * lu(r, -12, -4), r.uniform(0, math.pi)])
    if phi == math.pi / 2:
        up = (0.0, 0.0, 1.0)
    elif phi == 0.0:
        up = (0.0, 1.0, 0.0)
    elif phi == math.pi:
        up = (0.0, -1.0, 0.0)
    else:
        up = (0.0, math.cos(phi), math.sin(phi))
    xs = sorted(set(float(r.randint(-4, 24)) / 2 for _ in range(r.randint(3, 12))))
    if len(xs) < 2:
        xs = [1.0, 3.0]
    h = r.choice([1.0, 0.5, lu(r, -8, 0)])
    A = Mesh()
    bot = [A.addv((x, 0.0, 0.0)) for x in xs]
    top = [A.addv(add((x + 0.25, 0.0, 0.0), mul(up, h))) for x in xs]
    for k in range(len(xs) - 1):
        A.f.append((bot[k], bot[k + 1], top[k]))
        A.f.append((bot[k + 1], top[k + 1], top[k]))
    if r.random() < 0.3:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_step_tiny(r):
    nx, ny = r.randint(2, 5), r.randint(2, 5)
    xs = r.randint(1, nx - 1)
    e = r.choice([-1, 1]) * lu(r, -13, -6)
    m = r.choice(GRID_MODES)
    c = r.choice(['cut', 'shear'])
    A = Mesh()
    if c == 'cut':
        L, _ = grid_mesh(r, xs, ny, m, w=1.0 / nx, h=1.0 / ny)
        R, _ = grid_mesh(r, nx - xs, ny, m, w=1.0 / nx, h=1.0 / ny, x0=xs / nx, z=e)
        A.append(L).append(R)
    else:
        V = grid_pts(nx, ny, 1.0 / nx, 1.0 / ny)
        V = [(p[0], p[1], e if p[0] > (xs - 0.5) / nx else 0.0) for p in V]
        A = Mesh(V, grid_faces(nx, ny, m, r))
    d = r.choice(['flat', 'flat_other', 'other_step'])
    if d == 'flat':
        B, _ = grid_mesh(r, nx, ny, other_mode(r, m), w=1.0 / nx, h=1.0 / ny)
    elif d == 'flat_other':
        k = r.randint(1, 4)
        B, _ = grid_mesh(r, k, k, w=1.0 / k, h=1.0 / k)
    else:
        V = grid_pts(nx, ny, 1.0 / nx, 1.0 / ny)
        xs2 = r.randint(1, nx - 1)
        e2 = e * r.choice([1.0, -1.0, 0.5, 1 + 1e-9])
        V = [(p[0], p[1], e2 if p[0] > (xs2 - 0.5) / nx else 0.0) for p in V]
        B = Mesh(V, grid_faces(nx, ny, other_mode(r, m), r))
    if r.random() < 0.4:
        A, B = B, A
    return place(r, [A, B], 'any')


def k_decimal_plane(r, far=False):
    c0 = r.randint(-20, 20) / 10.0
    c1 = r.randint(-30, 30) / 10.0
    c2 = r.randint(-30, 30) / 100.0

    def pts(nx, ny, dx, dy, x0, y0):
        return [(round(x0 + i * dx, 3), round(y0 + j * dy, 3)) for i in range(nx + 1) for j in range(ny + 1)]

    def mk(nx, ny, dx, dy, x0, y0, mode):
        V = [(x, y, c0 + c1 * x + c2 * y) for x, y in pts(nx, ny, dx, dy, x0, y0)]
        return Mesh(V, grid_faces(nx, ny, mode, r))
    nx, ny = r.randint(2, 5), r.randint(2, 5)
    m = r.choice(GRID_MODES)
    A = mk(nx, ny, 0.1, 0.1, 0.1, 0.3, m)
    if r.random() < 0.5:
        B = mk(nx, ny, 0.1, 0.1, 0.1, 0.3, other_mode(r, m))
    else:
        mx, my = r.randint(1, 5), r.randint(1, 5)
        B = mk(mx, my, r.choice([0.1, 0.3, 0.07]), r.choice([0.1, 0.2, 0.03]), r.choice([0.1, 0.2, 0.15]),
               r.choice([0.3, 0.4, 0.33]), r.choice(GRID_MODES))
    if far:
        return place(r, [A, B], 'far')
    return place(r, [A, B], r.choice(['none', 'none', 'any']))


KINDS = [
    ('shared_vert_bump', k_shared_vert_bump),
    ('shared_vert_bump_far', lambda r: k_shared_vert_bump(r, True)),
    ('coplanar_on_edge', k_coplanar_on_edge),
    ('spoke_fan', k_spoke_fan),
    ('edge_thru_vertex', k_edge_thru_vertex),
    ('ties_around', k_ties_around),
    ('sandwich', k_sandwich),
    ('bisector_wedge', k_bisector_wedge),
    ('parallel_gap', k_parallel_gap),
    ('parallel_gap_far', lambda r: k_parallel_gap(r, True)),
    ('rot_inplane_axis', k_rot_inplane_axis),
    ('rot_inplane_axis_far', lambda r: k_rot_inplane_axis(r, True)),
    ('f32_partial', k_f32_partial),
    ('f32_partial_far', lambda r: k_f32_partial(r, True)),
    ('edge_lines_cross', k_edge_lines_cross),
    ('huge_reach', k_huge_reach),
    ('needle_target', k_needle_target),
    ('mixed_scale', k_mixed_scale),
    ('mixed_scale_sim', lambda r: k_mixed_scale(r, True)),
    ('edge_overlap_partial', k_edge_overlap_partial),
    ('zero_area_on_edge', k_zero_area_on_edge),
    ('dup_ulp', k_dup_ulp),
    ('dup_ulp_far', lambda r: k_dup_ulp(r, True)),
    ('corrugated', k_corrugated),
    ('corrugated_far', lambda r: k_corrugated(r, True)),
    ('saddle_quads', k_saddle_quads),
    ('saddle_quads_far', lambda r: k_saddle_quads(r, True)),
    ('cap_apex_on_edge', k_cap_apex_on_edge),
    ('inplane_rot_tiny', k_inplane_rot_tiny),
    ('inplane_rot_tiny_far', lambda r: k_inplane_rot_tiny(r, True)),
    ('bisector_edge', k_bisector_edge),
    ('fan_hub_on_target', k_fan_hub_on_target),
    ('chain_on_edge', k_chain_on_edge),
    ('step_tiny', k_step_tiny),
    ('decimal_plane', k_decimal_plane),
    ('decimal_plane_far', lambda r: k_decimal_plane(r, True)),
]


def generate(seed):
    name, fn = KINDS[seed % len(KINDS)]
    r = random.Random(seed)
    A, B = fn(r)
    for M in (A, B):
        if not (1 <= len(M.f) <= MAXTRI):
            raise RuntimeError("seed %d (%s): %d triangles" % (seed, name, len(M.f)))
        for p in M.v:
            if not all(math.isfinite(c) for c in p):
                raise RuntimeError("seed %d (%s): non-finite coordinate" % (seed, name))
    return name, A, B


def write_obj(path, M, comment):
    used = sorted({i for t in M.f for i in t})
    new = {old: k + 1 for k, old in enumerate(used)}
    out = ["# " + comment]
    for i in used:
        p = M.v[i]
        out.append("v %.17g %.17g %.17g" % (p[0], p[1], p[2]))
    for a, b, c in M.f:
        out.append("f %d %d %d" % (new[a], new[b], new[c]))
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: %s OUTDIR SEED_FROM SEED_TO\nkinds (%d): %s\n"
                         % (argv[0], len(KINDS), " ".join(k for k, _ in KINDS)))
        return 2
    out, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(out, exist_ok=True)
    for seed in range(lo, hi):
        name, A, B = generate(seed)
        stem = os.path.join(out, "%06d_%s" % (seed, name))
        write_obj(stem + "_a.obj", A, "generate_pairs8.py seed %d kind %s mesh A" % (seed, name))
        write_obj(stem + "_b.obj", B, "generate_pairs8.py seed %d kind %s mesh B" % (seed, name))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
