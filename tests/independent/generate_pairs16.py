#!/usr/bin/env python3
"""generate_pairs16.py -- independent test-input generator for Hausdorff Lens (gen16).

Written BLIND: without reading the tool's sources (core/), its tests (tests/) or its docs (docs/);
only the README's description of the file formats and the command line was consulted.

Synopsis:
    python3 generate_pairs16.py OUTDIR FROM TO

For every integer seed s in [FROM, TO) writes OUTDIR/NNNNNN_KIND_a.obj and OUTDIR/NNNNNN_KIND_b.obj
(NNNNNN = s zero-padded to 6 digits, KIND = KINDS[s % len(KINDS)]).  All randomness comes from
random.Random(s), so the output depends only on s.  A KIND ending in "_far" lies far from the origin
relative to its size (1e3..1e7 pair sizes away).

Format: plain OBJ.  First line '# gen16 seed=S kind=K mesh=a|b <parameters>', then 'v x y z' lines
(coordinates written with repr(float), so they read back as the exact doubles), then 'f i j k' lines
(1-based).  Every mesh has 1..200 triangles (mostly <= 60), finite coordinates, valid indices, no
unused vertices and at most 30 triangles around any vertex (counted by index and by identical
coordinates); a draw that breaks the valence/size limits is redrawn from the same random stream.
Zero-area triangles (repeated index, repeated coordinates, collinear corners) occur in some kinds.

Placements (applied to both meshes of a pair alike): identity; exact dyadic transforms (axis
permutation, sign flips, power-of-two scale, dyadic translation -- exact ties stay exact); random
rotation plus translation.

Kinds:
  torus_res          torus at two (u,v) resolutions, second one optionally phase-shifted
  ellipsoid_res      UV ellipsoid with poles vs a rotated icosphere (or UV with poles on another axis)
  capsule_res        capsule (cylinder + hemispheres, pole vertices on the axis) at two resolutions
  superquadric       superellipsoid at two resolutions, or two close exponents at one resolution
  loop_subdiv        Loop subdivision (1-2 levels) vs its control polyhedron (or level k vs k+1)
  midpoint_displace  dyadic control polyhedron vs its 4:1 midpoint split with some midpoints displaced
  laplacian_smooth   noisy grid / noisy icosphere vs a Laplacian- or Taubin-smoothed copy
  qem_decimate       closed bumpy mesh vs a QEM edge-collapse decimation (new vertices off the input)
  normal_offset      surface vs copy moved along vertex normals by 1e-12..1e-3 of its size
  edge_flip          bumpy (sometimes nearly flat) surface vs the same with a few edges flipped
  cad_chamfer        extruded convex polygon / long thin rectangle, sharp vs chamfered, fan caps
  fillet_strip       L-shaped bracket with a fillet of long thin strips at two resolutions / sharp
  revolve_axis       revolved profile with vertices on the axis (poles, pinch) at two samplings
  helix_ramp         helicoid ramp (inner edge sometimes on the axis) at two resolutions / shifted
  folded_paper       developable strip folded along slanted creases vs other angles / triangulation
  gear_extrude       extruded star (gear) polygon, centre-fan caps vs ear-clipped caps, tiny twist
  stacked_planes     pencil of plates through one line at 1e-9..1e-3 rad, or a tilted plate stack
  verts_on_edges     dyadic polyhedron vs its corner-cut copy (vertices exactly on its edges)
  corners_on_planes  dyadic surface vs triangles whose corners lie exactly on its planes/edges/vertices
  mirror_plane       mesh vs its mirror image across a plane that contains some of its faces
  cap_needle         good mesh with caps/needles of aspect 1e3..1e9, zero-area fillers, repeated-index faces vs clean
  equidistant_curves dyadic layouts where 2+ source features tie along whole curves / areas
  quad_diag          twisted bilinear quad grid, one diagonal vs the other / centre 4-splits
  cross_solids       two interpenetrating closed solids (surfaces cross along curves)
  remesh_patch       smooth height patch remeshed twice: jittered rows vs hexagonal rows
  hole_fill          grid surface vs the same with a hole cut and refilled (fan/centre/ear)
  torus_far          torus_res placed 1e3..1e7 sizes from the origin
  qem_far            qem_decimate placed far from the origin
  offset_far         normal_offset placed far from the origin
  helix_far          helix_ramp placed far from the origin
"""
import math
import os
import random
import sys

# ----------------------------------------------------------------------------- vectors


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vmul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def vlen(a):
    return math.sqrt(vdot(a, a))


def vnorm(a):
    n = vlen(a)
    if n == 0.0:
        return (0.0, 0.0, 1.0)
    return (a[0] / n, a[1] / n, a[2] / n)


def vlerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t)


def mat_apply(M, p):
    return (M[0][0] * p[0] + M[0][1] * p[1] + M[0][2] * p[2],
            M[1][0] * p[0] + M[1][1] * p[1] + M[1][2] * p[2],
            M[2][0] * p[0] + M[2][1] * p[1] + M[2][2] * p[2])


def mat_mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def rot_axis(axis, ang):
    x, y, z = vnorm(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1.0 - c
    return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
            [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
            [z * x * C - y * s, z * y * C + x * s, c + z * z * C]]


def rand_rot(rng):
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a = math.sqrt(1 - u1)
    b = math.sqrt(u1)
    x, y = a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2)
    z, w = b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def rand_unit(rng):
    while True:
        p = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        n = vlen(p)
        if 0.1 < n <= 1.0:
            return vmul(p, 1.0 / n)


def loguni(rng, lo, hi):
    """10**U(lo, hi)"""
    return 10.0 ** rng.uniform(lo, hi)


def fmt(x):
    if isinstance(x, float):
        return '%.6g' % x
    return str(x)


# ----------------------------------------------------------------------------- meshes


class Mesh(object):
    def __init__(self, V=None, F=None):
        self.V = [tuple(float(c) for c in v) for v in (V or [])]
        self.F = [tuple(int(i) for i in f) for f in (F or [])]

    def add_v(self, p):
        self.V.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.V) - 1

    def add_f(self, a, b, c):
        self.F.append((a, b, c))

    def copy(self):
        return Mesh(list(self.V), list(self.F))

    def append(self, other):
        off = len(self.V)
        self.V.extend(other.V)
        self.F.extend((a + off, b + off, c + off) for (a, b, c) in other.F)
        return self

    def mapped(self, fn):
        return Mesh([fn(v) for v in self.V], list(self.F))

    def tri(self, f):
        return self.V[f[0]], self.V[f[1]], self.V[f[2]]


def concat(*ms):
    out = Mesh()
    for m in ms:
        out.append(m)
    return out


def weld(m, drop_degen=True):
    key = {}
    remap = []
    V = []
    for v in m.V:
        k = (v[0] + 0.0, v[1] + 0.0, v[2] + 0.0)
        if k not in key:
            key[k] = len(V)
            V.append(v)
        remap.append(key[k])
    F = []
    for f in m.F:
        g = (remap[f[0]], remap[f[1]], remap[f[2]])
        if drop_degen and (g[0] == g[1] or g[1] == g[2] or g[0] == g[2]):
            continue
        F.append(g)
    return Mesh(V, F)


def compact(m):
    used = {}
    V = []
    F = []
    for f in m.F:
        g = []
        for i in f:
            if i not in used:
                used[i] = len(V)
                V.append(m.V[i])
            g.append(used[i])
        F.append(tuple(g))
    return Mesh(V, F)


def bbox(ms):
    pts = [v for m in ms for v in m.V]
    lo = tuple(min(p[i] for p in pts) for i in range(3))
    hi = tuple(max(p[i] for p in pts) for i in range(3))
    return lo, hi


def size_of(ms):
    lo, hi = bbox(ms)
    return vlen(vsub(hi, lo))


def face_normal(m, f):
    a, b, c = m.tri(f)
    return vcross(vsub(b, a), vsub(c, a))


def vertex_normals(m):
    N = [(0.0, 0.0, 0.0)] * len(m.V)
    for f in m.F:
        n = face_normal(m, f)
        for i in f:
            N[i] = vadd(N[i], n)
    return [vnorm(n) for n in N]


def neighbours(m):
    nb = [set() for _ in m.V]
    for (a, b, c) in m.F:
        nb[a].update((b, c))
        nb[b].update((a, c))
        nb[c].update((a, b))
    for i in range(len(nb)):
        nb[i].discard(i)
    return nb


def edge_faces(m):
    ef = {}
    for fi, (a, b, c) in enumerate(m.F):
        for x, y in ((a, b), (b, c), (c, a)):
            ef.setdefault((min(x, y), max(x, y)), []).append(fi)
    return ef


def quad(F, a, b, c, d, diag):
    """quad a-b-c-d (cyclic); diag 0: a-c, 1: b-d"""
    if diag == 0:
        F.append((a, b, c))
        F.append((a, c, d))
    else:
        F.append((a, b, d))
        F.append((b, c, d))


def pick_diag(mode, i, j, rng):
    if mode == 'same':
        return 0
    if mode == 'other':
        return 1
    if mode == 'alt':
        return (i + j) % 2
    if mode == 'alt2':
        return (i + j + 1) % 2
    return rng.randrange(2)


def grid_mesh(f, nu, nv, wrap_u=False, wrap_v=False, diag='same', rng=None):
    cu = nu if wrap_u else nu + 1
    cv = nv if wrap_v else nv + 1
    V = []
    idx = {}
    for i in range(cu):
        for j in range(cv):
            idx[(i, j)] = len(V)
            V.append(f(i / float(nu), j / float(nv)))
    F = []
    for i in range(nu):
        for j in range(nv):
            i1 = (i + 1) % cu if wrap_u else i + 1
            j1 = (j + 1) % cv if wrap_v else j + 1
            quad(F, idx[(i, j)], idx[(i1, j)], idx[(i1, j1)], idx[(i, j1)], pick_diag(diag, i, j, rng))
    return weld(Mesh(V, F))


def revolve(profile, n, phase=0.0, diag='same', rng=None):
    """profile: list of (r, z); r == 0 gives one vertex on the z axis."""
    V = []
    rings = []
    for (r, z) in profile:
        if r == 0.0:
            rings.append([len(V)] * n)
            V.append((0.0, 0.0, z))
        else:
            ring = []
            for i in range(n):
                th = 2.0 * math.pi * (i + phase) / n
                ring.append(len(V))
                V.append((r * math.cos(th), r * math.sin(th), z))
            rings.append(ring)
    F = []
    for k in range(len(rings) - 1):
        for i in range(n):
            a, b = rings[k][i], rings[k][(i + 1) % n]
            c, d = rings[k + 1][(i + 1) % n], rings[k + 1][i]
            quad(F, a, b, c, d, pick_diag(diag, i, k, rng))
    return weld(Mesh(V, F))


def cross2(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def ear_clip(poly, start=0):
    """triangulate a simple 2D polygon; returns index triples"""
    n = len(poly)
    area = sum(poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1] for i in range(n))
    idx = list(range(n))
    if area < 0:
        idx.reverse()
    s = start % n
    idx = idx[s:] + idx[:s]
    tris = []
    while len(idx) > 3:
        found = False
        m = len(idx)
        for k in range(m):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % m]
            a, b, c = poly[i0], poly[i1], poly[i2]
            if cross2(a, b, c) <= 0:
                continue
            ok = True
            for j in idx:
                if j in (i0, i1, i2):
                    continue
                p = poly[j]
                if cross2(a, b, p) >= 0 and cross2(b, c, p) >= 0 and cross2(c, a, p) >= 0:
                    ok = False
                    break
            if ok:
                tris.append((i0, i1, i2))
                idx.pop(k)
                found = True
                break
        if not found:
            tris.append((idx[-1], idx[0], idx[1]))
            idx.pop(0)
    tris.append((idx[0], idx[1], idx[2]))
    return tris


def strip_rows(L, U, X):
    """triangulate between two x-monotone rows of vertex indices"""
    i = j = 0
    T = []
    while i < len(L) - 1 or j < len(U) - 1:
        if i == len(L) - 1:
            adv_l = False
        elif j == len(U) - 1:
            adv_l = True
        else:
            adv_l = X(L[i + 1]) <= X(U[j + 1])
        if adv_l:
            T.append((L[i], L[i + 1], U[j]))
            i += 1
        else:
            T.append((L[i], U[j + 1], U[j]))
            j += 1
    return T


# ----------------------------------------------------------------------------- base solids


def box_mesh(lo, hi, diag_rng=None):
    V = []
    for z in (lo[2], hi[2]):
        for y in (lo[1], hi[1]):
            for x in (lo[0], hi[0]):
                V.append((x, y, z))
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    F = []
    for q in quads:
        quad(F, q[0], q[1], q[2], q[3], diag_rng.randrange(2) if diag_rng else 0)
    return Mesh(V, F)


def octahedron(s=1.0):
    V = [(s, 0, 0), (-s, 0, 0), (0, s, 0), (0, -s, 0), (0, 0, s), (0, 0, -s)]
    F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return Mesh(V, F)


def tetrahedron(s=1.0):
    V = [(s, s, s), (s, -s, -s), (-s, s, -s), (-s, -s, s)]
    F = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
    return Mesh(V, F)


def tri_prism(s=1.0):
    V = [(0, 0, 0), (2 * s, 0, 0), (0, 2 * s, 0), (0, 0, 2 * s), (2 * s, 0, 2 * s), (0, 2 * s, 2 * s)]
    F = [(0, 2, 1), (3, 4, 5), (0, 1, 4), (0, 4, 3), (1, 2, 5), (1, 5, 4), (2, 0, 3), (2, 3, 5)]
    return Mesh(V, F)


def square_pyramid(s=1.0):
    V = [(-s, -s, 0), (s, -s, 0), (s, s, 0), (-s, s, 0), (0, 0, 2 * s)]
    F = [(0, 2, 1), (0, 3, 2), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
    return Mesh(V, F)


GR = (1.0 + math.sqrt(5.0)) / 2.0
ICO_V = [(-1, GR, 0), (1, GR, 0), (-1, -GR, 0), (1, -GR, 0), (0, -1, GR), (0, 1, GR), (0, -1, -GR),
         (0, 1, -GR), (GR, 0, -1), (GR, 0, 1), (-GR, 0, -1), (-GR, 0, 1)]
ICO_F = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
         (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]


def midpoint_split(m, disp=None):
    """4:1 split; disp(edge, midpoint) -> new point (default: midpoint)"""
    V = list(m.V)
    mid = {}
    F = []

    def em(a, b):
        e = (min(a, b), max(a, b))
        if e not in mid:
            p = vmul(vadd(m.V[a], m.V[b]), 0.5)
            if disp is not None:
                p = disp(e, p)
            mid[e] = len(V)
            V.append(p)
        return mid[e]
    for (a, b, c) in m.F:
        ab, bc, ca = em(a, b), em(b, c), em(c, a)
        F.extend([(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)])
    return Mesh(V, F)


def icosphere(level):
    m = Mesh([vnorm(v) for v in ICO_V], ICO_F)
    for _ in range(level):
        m = midpoint_split(m)
        m = m.mapped(vnorm)
    return m


def uv_ellipsoid(a, b, c, nu, nv, phase=0.0, diag='same', rng=None):
    def f(u, v):
        if v == 0.0:
            return (0.0, 0.0, c)
        if v == 1.0:
            return (0.0, 0.0, -c)
        th = 2 * math.pi * (u + phase / nu)
        ph = math.pi * v
        return (a * math.sin(ph) * math.cos(th), b * math.sin(ph) * math.sin(th), c * math.cos(ph))
    return grid_mesh(f, nu, nv, wrap_u=True, diag=diag, rng=rng)


def torus(R, r, nu, nv, phase_u=0.0, phase_v=0.0, diag='same', rng=None, bump=None):
    def f(u, v):
        th = 2 * math.pi * (u + phase_u / nu)
        ph = 2 * math.pi * (v + phase_v / nv)
        rr = r if bump is None else r * (1.0 + bump(th, ph))
        return ((R + rr * math.cos(ph)) * math.cos(th), (R + rr * math.cos(ph)) * math.sin(th), rr * math.sin(ph))
    return grid_mesh(f, nu, nv, wrap_u=True, wrap_v=True, diag=diag, rng=rng)


def smooth_fn(rng, amp=1.0, nb=3):
    """random smooth height function on [0,1]^2"""
    terms = []
    for _ in range(nb):
        terms.append(('g', rng.uniform(-1, 1) * amp, rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0.2, 0.6)))
    terms.append(('s', rng.uniform(-0.3, 0.3) * amp, rng.uniform(0.5, 2.5), rng.uniform(0.5, 2.5), rng.uniform(0, 6.3)))

    def f(x, y):
        z = 0.0
        for t in terms:
            if t[0] == 'g':
                z += t[1] * math.exp(-((x - t[2]) ** 2 + (y - t[3]) ** 2) / t[4] ** 2)
            else:
                z += t[1] * math.sin(t[2] * 3.0 * x + t[3] * 3.0 * y + t[4])
        return z
    return f


def height_grid(fz, n, m, diag='same', rng=None, sx=1.0, sy=1.0):
    return grid_mesh(lambda u, v: (u * sx, v * sy, fz(u, v)), n, m, diag=diag, rng=rng)


# ----------------------------------------------------------------------------- placement


def dyadic_transform(rng):
    perm = [0, 1, 2]
    rng.shuffle(perm)
    sg = [rng.choice((-1.0, 1.0)) for _ in range(3)]
    sc = 2.0 ** rng.randint(-3, 3)
    tr = [rng.randint(-16, 16) / 8.0 * sc for _ in range(3)]

    def fn(p):
        return tuple(sg[i] * p[perm[i]] * sc + tr[i] for i in range(3))
    return fn, 'dyadic(perm=%s,sign=%s,scale=%s,t=%s)' % (''.join(map(str, perm)), ''.join('+' if s > 0 else '-' for s in sg), fmt(sc), ','.join(fmt(t) for t in tr))


def rotation_transform(rng):
    M = rand_rot(rng)
    sc = loguni(rng, -1, 1)
    t = tuple(rng.uniform(-2, 2) * sc for _ in range(3))

    def fn(p):
        q = mat_apply(M, p)
        return (q[0] * sc + t[0], q[1] * sc + t[1], q[2] * sc + t[2])
    return fn, 'rot(scale=%s)' % fmt(sc)


PLACE_ANY = (0.3, 0.35, 0.35)
PLACE_EXACT = (0.45, 0.45, 0.10)


def place(rng, A, B, params, weights=PLACE_ANY):
    r = rng.random()
    if r < weights[0]:
        params.append('place=identity')
        return A, B
    if r < weights[0] + weights[1]:
        fn, desc = dyadic_transform(rng)
    else:
        fn, desc = rotation_transform(rng)
    params.append('place=' + desc)
    return A.mapped(fn), B.mapped(fn)


def far_translate(rng, A, B, params):
    size = size_of([A, B])
    e = rng.uniform(3, 7)
    dist = size * 10.0 ** e
    if rng.random() < 0.5:
        ax = rng.randrange(3)
        d = [0.0, 0.0, 0.0]
        d[ax] = rng.choice((-1.0, 1.0))
        if rng.random() < 0.5:   # power-of-two distance along an axis
            dist = 2.0 ** round(math.log(dist, 2))
        dname = 'axis%d' % ax
    else:
        d = rand_unit(rng)
        dname = 'generic'
    t = vmul(d, dist)
    params.append('far=%s dir=%s' % (fmt(dist / size), dname))
    fn = (lambda p: (p[0] + t[0], p[1] + t[1], p[2] + t[2]))
    return A.mapped(fn), B.mapped(fn)


def maybe_swap(rng, A, B, params):
    if rng.random() < 0.5:
        params.append('swapped')
        return B, A
    return A, B


# ----------------------------------------------------------------------------- kinds


def gen_torus_res(rng, params):
    R = rng.uniform(1.0, 2.0)
    r = R * rng.uniform(0.15, 0.6)
    ca = rng.choice([(6, 3), (8, 3), (7, 4), (5, 3), (8, 4), (6, 4)])
    cb = rng.choice([(10, 4), (12, 5), (9, 6), (11, 4), (12, 4), (10, 5)])
    ph = rng.choice(['0', 'half', 'rand'])
    pu = {'0': 0.0, 'half': 0.5, 'rand': rng.random()}[ph]
    pv = {'0': 0.0, 'half': 0.5, 'rand': rng.random()}[ph]
    da, db = rng.choice(['same', 'alt', 'rand']), rng.choice(['same', 'other', 'alt', 'rand'])
    A = torus(R, r, ca[0], ca[1], diag=da, rng=rng)
    B = torus(R, r, cb[0], cb[1], pu, pv, diag=db, rng=rng)
    params.extend(['R=%s r=%s' % (fmt(R), fmt(r)), 'res_a=%dx%d res_b=%dx%d phase=%s' % (ca + cb + (ph,))])
    A, B = maybe_swap(rng, A, B, params)
    return A, B


def gen_ellipsoid_res(rng, params):
    a, b, c = rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5)
    nu, nv = rng.randint(5, 10), rng.randint(3, 6)
    A = uv_ellipsoid(a, b, c, nu, nv, diag=rng.choice(['same', 'alt']), rng=rng)
    mode = rng.choice(['ico', 'ico', 'uv_axis'])
    if mode == 'ico':
        lev = rng.choice([0, 1, 1])
        M = rand_rot(rng) if rng.random() < 0.7 else [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
        B = icosphere(lev).mapped(lambda p: (lambda q: (a * q[0], b * q[1], c * q[2]))(mat_apply(M, p)))
        params.append('uv=%dx%d ico=%d' % (nu, nv, lev))
    else:
        nu2, nv2 = rng.randint(5, 10), rng.randint(3, 6)
        # same ellipsoid, poles on the x axis
        B = uv_ellipsoid(c, b, a, nu2, nv2, phase=rng.random()).mapped(lambda p: (p[2], p[1], p[0]))
        params.append('uv=%dx%d uvx=%dx%d' % (nu, nv, nu2, nv2))
    params.append('abc=%s,%s,%s' % (fmt(a), fmt(b), fmt(c)))
    return maybe_swap(rng, A, B, params)


def capsule_profile(r, h, k):
    prof = [(0.0, h + r)]
    for i in range(1, k):
        ang = 0.5 * math.pi * i / k
        prof.append((r * math.sin(ang), h + r * math.cos(ang)))
    prof.append((r, h))
    prof.append((r, -h))
    for i in range(k - 1, 0, -1):
        ang = 0.5 * math.pi * i / k
        prof.append((r * math.sin(ang), -h - r * math.cos(ang)))
    prof.append((0.0, -h - r))
    return prof


def gen_capsule_res(rng, params):
    r = rng.uniform(0.2, 0.8)
    h = r * loguni(rng, -1, 1)
    na, ka = rng.randint(5, 8), rng.randint(1, 2)
    nb, kb = rng.randint(6, 12), rng.randint(2, 3)
    A = revolve(capsule_profile(r, h, ka), na)
    B = revolve(capsule_profile(r, h, kb), nb, phase=rng.choice([0.0, 0.5, rng.random()]))
    params.append('r=%s h=%s a=%dx%d b=%dx%d' % (fmt(r), fmt(h), na, ka, nb, kb))
    return maybe_swap(rng, A, B, params)


def spow(x, e):
    if abs(x) < 1e-15:
        return 0.0
    return math.copysign(abs(x) ** e, x)


def superquad(a, b, c, e1, e2, nu, nv, diag='same', rng=None):
    def f(u, v):
        if v == 0.0:
            return (0.0, 0.0, c)
        if v == 1.0:
            return (0.0, 0.0, -c)
        th = 2 * math.pi * u - math.pi
        ph = math.pi / 2 - math.pi * v
        cp, sp = math.cos(ph), math.sin(ph)
        return (a * spow(cp, e1) * spow(math.cos(th), e2), b * spow(cp, e1) * spow(math.sin(th), e2), c * spow(sp, e1))
    return grid_mesh(f, nu, nv, wrap_u=True, diag=diag, rng=rng)


def gen_superquadric(rng, params):
    a, b, c = rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5), rng.uniform(0.5, 1.5)
    e1, e2 = rng.uniform(0.25, 2.0), rng.uniform(0.25, 2.0)
    if rng.random() < 0.6:
        ra = (rng.choice([4, 6, 8]), rng.randint(3, 5))
        rb = (rng.choice([8, 10, 12]), rng.randint(4, 7))
        A = superquad(a, b, c, e1, e2, ra[0], ra[1], diag='alt')
        B = superquad(a, b, c, e1, e2, rb[0], rb[1], diag=rng.choice(['same', 'alt']))
        params.append('e=%s,%s res_a=%dx%d res_b=%dx%d' % (fmt(e1), fmt(e2), ra[0], ra[1], rb[0], rb[1]))
    else:
        res = (rng.choice([6, 8, 10]), rng.randint(4, 6))
        d = loguni(rng, -6, -1)
        A = superquad(a, b, c, e1, e2, res[0], res[1])
        B = superquad(a, b, c, e1 * (1 + d), e2 * (1 - d), res[0], res[1])
        params.append('e=%s,%s rel_de=%s res=%dx%d' % (fmt(e1), fmt(e2), fmt(d), res[0], res[1]))
    params.append('abc=%s,%s,%s' % (fmt(a), fmt(b), fmt(c)))
    return maybe_swap(rng, A, B, params)


def loop_subdivide(m):
    V, F = m.V, m.F
    opp = {}
    for (a, b, c) in F:
        for x, y, z in ((a, b, c), (b, c, a), (c, a, b)):
            opp.setdefault((min(x, y), max(x, y)), []).append(z)
    nb = neighbours(m)
    bnb = [[] for _ in V]
    for (x, y), o in opp.items():
        if len(o) == 1:
            bnb[x].append(y)
            bnb[y].append(x)
    NV = []
    for i, v in enumerate(V):
        if len(bnb[i]) == 2:
            p = vadd(vmul(v, 0.75), vmul(vadd(V[bnb[i][0]], V[bnb[i][1]]), 0.125))
        elif bnb[i]:
            p = v
        else:
            n = len(nb[i])
            beta = (0.625 - (0.375 + 0.25 * math.cos(2 * math.pi / n)) ** 2) / n
            s = (0.0, 0.0, 0.0)
            for j in nb[i]:
                s = vadd(s, V[j])
            p = vadd(vmul(v, 1 - n * beta), vmul(s, beta))
        NV.append(p)
    em = {}
    for e in sorted(opp):
        o = opp[e]
        a, b = V[e[0]], V[e[1]]
        if len(o) == 2:
            p = vadd(vmul(vadd(a, b), 0.375), vmul(vadd(V[o[0]], V[o[1]]), 0.125))
        else:
            p = vmul(vadd(a, b), 0.5)
        em[e] = len(NV)
        NV.append(p)
    NF = []
    for (a, b, c) in F:
        ab, bc, ca = em[(min(a, b), max(a, b))], em[(min(b, c), max(b, c))], em[(min(c, a), max(c, a))]
        NF.extend([(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)])
    return Mesh(NV, NF)


def control_mesh(rng, params):
    name = rng.choice(['tetra', 'octa', 'cube', 'prism', 'ico', 'pyramid'])
    if name == 'tetra':
        m = tetrahedron()
    elif name == 'octa':
        m = octahedron()
    elif name == 'cube':
        m = box_mesh((-1, -1, -1), (1, 1, 1), rng)
    elif name == 'prism':
        m = tri_prism()
    elif name == 'pyramid':
        m = square_pyramid()
    else:
        m = Mesh(ICO_V, ICO_F)
    if rng.random() < 0.6:   # dyadic perturbation (multiples of 1/16)
        m = m.mapped(lambda p: tuple(c + rng.randint(-4, 4) / 16.0 for c in p))
    params.append('control=%s' % name)
    return m


def gen_loop_subdiv(rng, params):
    C = control_mesh(rng, params)
    levels = []
    m = C
    meshes = [C]
    while len(m.F) * 4 <= 200 and len(levels) < 2:
        m = loop_subdivide(m)
        meshes.append(m)
        levels.append(len(m.F))
    if len(meshes) >= 3 and rng.random() < 0.4:
        A, B = meshes[1], meshes[2]
        params.append('levels=1vs2')
    else:
        k = rng.randint(1, len(meshes) - 1)
        A, B = meshes[0], meshes[k]
        params.append('levels=0vs%d' % k)
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_midpoint_displace(rng, params):
    C = control_mesh(rng, params)
    size = size_of([C])
    hmax = size * loguni(rng, -4, -1)
    pzero = rng.choice([0.0, 0.3, 0.7])
    ef = edge_faces(C)
    nrm = {}
    for e, fs in ef.items():
        n = (0.0, 0.0, 0.0)
        for fi in fs:
            n = vadd(n, vnorm(face_normal(C, C.F[fi])))
        nrm[e] = vnorm(n)

    def disp(e, p):
        if rng.random() < pzero:
            return p
        return vadd(p, vmul(nrm[e], hmax * rng.uniform(-1, 1)))
    B = midpoint_split(C, disp)
    if len(B.F) * 4 <= 200 and rng.random() < 0.3:
        B = midpoint_split(B)
        params.append('levels=2')
    params.append('hmax=%s pzero=%s' % (fmt(hmax), fmt(pzero)))
    A, B = place(rng, C, B, params, PLACE_EXACT)
    return maybe_swap(rng, A, B, params)


def laplace(m, lam, iters, fixed=None, mu=None):
    nb = neighbours(m)
    V = list(m.V)
    for it in range(iters):
        for fac in ((lam,) if mu is None else (lam, mu)):
            NV = []
            for i, v in enumerate(V):
                if (fixed and i in fixed) or not nb[i]:
                    NV.append(v)
                    continue
                s = (0.0, 0.0, 0.0)
                for j in nb[i]:
                    s = vadd(s, V[j])
                c = vmul(s, 1.0 / len(nb[i]))
                NV.append(vadd(v, vmul(vsub(c, v), fac)))
            V = NV
    return Mesh(V, m.F)


def boundary_vertices(m):
    ef = edge_faces(m)
    bv = set()
    for e, fs in ef.items():
        if len(fs) == 1:
            bv.update(e)
    return bv


def gen_laplacian_smooth(rng, params):
    if rng.random() < 0.6:
        n = rng.randint(4, 6)
        amp = loguni(rng, -2, -0.3)
        fz = smooth_fn(rng, 0.3)
        A = height_grid(lambda u, v: fz(u, v) + amp * rng.uniform(-1, 1), n, n, diag=rng.choice(['same', 'alt', 'rand']), rng=rng)
        params.append('base=grid%d amp=%s' % (n, fmt(amp)))
    else:
        amp = loguni(rng, -2, -0.7)
        A = icosphere(1).mapped(lambda p: vmul(p, 1.0 + amp * rng.uniform(-1, 1)))
        params.append('base=ico1 amp=%s' % fmt(amp))
    fixed = boundary_vertices(A) if rng.random() < 0.5 else None
    iters = rng.choice([1, 2, 3, 5, 10])
    if rng.random() < 0.3:
        B = laplace(A, 0.5, iters, fixed, mu=-0.53)
        params.append('taubin iters=%d' % iters)
    else:
        lam = rng.choice([0.5, 0.25, 1.0])
        B = laplace(A, lam, iters, fixed)
        params.append('lambda=%s iters=%d' % (fmt(lam), iters))
    params.append('fixed_boundary=%d' % (fixed is not None))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


# --- QEM decimation


def plane_quadric(a, b, c):
    n = vcross(vsub(b, a), vsub(c, a))
    ln = vlen(n)
    if ln == 0.0:
        return [0.0] * 10
    n = vmul(n, 1.0 / ln)
    d = -vdot(n, a)
    p = (n[0], n[1], n[2], d)
    return [p[i] * p[j] for i in range(4) for j in range(i, 4)]


def q_add(q, r):
    return [x + y for x, y in zip(q, r)]


def q_eval(q, v):
    x, y, z = v
    p = (x, y, z, 1.0)
    k = 0
    s = 0.0
    for i in range(4):
        for j in range(i, 4):
            s += q[k] * p[i] * p[j] * (1.0 if i == j else 2.0)
            k += 1
    return s


def q_opt(q):
    # q indices: 0:aa 1:ab 2:ac 3:ad 4:bb 5:bc 6:bd 7:cc 8:cd 9:dd
    A = [[q[0], q[1], q[2]], [q[1], q[4], q[5]], [q[2], q[5], q[7]]]
    b = [-q[3], -q[6], -q[8]]
    det = (A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0])
           + A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]))
    scale = max(abs(x) for x in (q[0], q[4], q[7])) or 1.0
    if abs(det) < 1e-9 * scale ** 3:
        return None
    res = []
    for col in range(3):
        M = [row[:] for row in A]
        for r in range(3):
            M[r][col] = b[r]
        d = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0])
             + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]))
        res.append(d / det)
    return tuple(res)


def qem_decimate(m, target, policy, rng):
    V = list(m.V)
    faces = [list(f) for f in m.F]
    alive = [True] * len(faces)
    Q = [[0.0] * 10 for _ in V]
    for f in faces:
        q = plane_quadric(V[f[0]], V[f[1]], V[f[2]])
        for i in f:
            Q[i] = q_add(Q[i], q)
    nalive = len(faces)
    while nalive > target:
        vf = {}
        edges = set()
        for fi, f in enumerate(faces):
            if not alive[fi]:
                continue
            for i in f:
                vf.setdefault(i, []).append(fi)
            for x, y in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
                edges.add((min(x, y), max(x, y)))
        nb = {}
        for i, fl in vf.items():
            s = set()
            for fi in fl:
                s.update(faces[fi])
            s.discard(i)
            nb[i] = s
        cands = []
        for (u, v) in sorted(edges):
            q = q_add(Q[u], Q[v])
            if policy == 'opt':
                p = q_opt(q)
                if p is None or vlen(vsub(p, vmul(vadd(V[u], V[v]), 0.5))) > 2 * vlen(vsub(V[u], V[v])):
                    p = min((V[u], V[v], vmul(vadd(V[u], V[v]), 0.5)), key=lambda x: q_eval(q, x))
            elif policy == 'mid':
                p = vmul(vadd(V[u], V[v]), 0.5)
            elif policy == 'rand':
                p = vlerp(V[u], V[v], rng.uniform(0.1, 0.9))
            else:
                p = min((V[u], V[v]), key=lambda x: q_eval(q, x))
            cands.append((q_eval(q, p), u, v, p))
        cands.sort(key=lambda c: c[0])
        done = False
        for cost, u, v, p in cands:
            if len(nb[u] & nb[v]) != 2:
                continue
            ok = True
            for w in (u, v):
                for fi in vf[w]:
                    f = faces[fi]
                    if u in f and v in f:
                        continue
                    old = [V[i] for i in f]
                    new = [p if i in (u, v) else V[i] for i in f]
                    n0 = vcross(vsub(old[1], old[0]), vsub(old[2], old[0]))
                    n1 = vcross(vsub(new[1], new[0]), vsub(new[2], new[0]))
                    if vdot(n0, n1) <= 0.2 * vlen(n0) * vlen(n1) or vlen(n1) == 0.0:
                        ok = False
                        break
                if not ok:
                    break
            if not ok:
                continue
            V[u] = p
            Q[u] = q_add(Q[u], Q[v])
            for fi in vf[v]:
                f = faces[fi]
                if u in f:
                    alive[fi] = False
                    nalive -= 1
                else:
                    faces[fi] = [u if i == v else i for i in f]
            done = True
            break
        if not done:
            break
    return compact(Mesh(V, [tuple(f) for fi, f in enumerate(faces) if alive[fi]]))


def bumpy_closed(rng, params):
    kind = rng.choice(['torus', 'ico', 'uv'])
    amp = loguni(rng, -2, -0.7)
    k1, k2, ph = rng.randint(1, 4), rng.randint(1, 4), rng.uniform(0, 6.3)
    if kind == 'torus':
        m = torus(1.0, 0.4, 10, 5, diag='alt', bump=lambda th, phi: amp * math.sin(k1 * th + ph) * math.cos(k2 * phi))
    elif kind == 'ico':
        m = icosphere(1).mapped(lambda p: vmul(p, 1 + amp * math.sin(k1 * 2 * p[0] + ph) * math.cos(k2 * 2 * p[1])))
    else:
        m = uv_ellipsoid(1.0, 0.8, 0.6, 10, 6, diag='alt').mapped(
            lambda p: vmul(p, 1 + amp * math.sin(k1 * 2 * p[2] + ph) * math.cos(k2 * 2 * p[0])))
    params.append('base=%s bump=%s' % (kind, fmt(amp)))
    return m


def gen_qem_decimate(rng, params):
    A = bumpy_closed(rng, params)
    frac = rng.uniform(0.25, 0.6)
    policy = rng.choice(['opt', 'opt', 'opt', 'mid', 'rand', 'end'])
    B = qem_decimate(A, max(12, int(len(A.F) * frac)), policy, rng)
    params.append('policy=%s faces=%d->%d' % (policy, len(A.F), len(B.F)))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_normal_offset(rng, params):
    base = rng.choice(['grid', 'torus', 'ico', 'sphere_uv'])
    if base == 'grid':
        n = rng.randint(4, 5)
        A = height_grid(smooth_fn(rng, 0.4), n, n, diag='alt')
    elif base == 'torus':
        A = torus(1.0, rng.uniform(0.2, 0.5), 8, 4, diag='alt')
    elif base == 'ico':
        A = icosphere(rng.choice([0, 1]))
    else:
        A = uv_ellipsoid(1.0, 1.0, 1.0, 8, 5)
    size = size_of([A])
    eps = size * loguni(rng, -12, -3) * rng.choice((-1.0, 1.0))
    mode = rng.choice(['uniform', 'uniform', 'random', 'partial'])
    N = vertex_normals(A)
    V = []
    for i, v in enumerate(A.V):
        if mode == 'uniform':
            s = eps
        elif mode == 'random':
            s = eps * rng.random()
        else:
            s = eps if rng.random() < 0.5 else 0.0
        V.append(vadd(v, vmul(N[i], s)))
    B = Mesh(V, A.F)
    if rng.random() < 0.1:   # also re-triangulate the offset copy a little
        flip_random_edges(B, rng, 3)
        params.append('flipped=3')
    params.append('base=%s eps=%s mode=%s' % (base, fmt(eps), mode))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def flip_random_edges(m, rng, k):
    nflip = 0
    for _ in range(20 * k):
        if nflip >= k:
            break
        ef = edge_faces(m)
        nb = neighbours(m)
        interior = [e for e, fs in sorted(ef.items()) if len(fs) == 2]
        if not interior:
            break
        e = rng.choice(interior)
        f1, f2 = ef[e]
        a = [i for i in m.F[f1] if i not in e]
        b = [i for i in m.F[f2] if i not in e]
        if len(a) != 1 or len(b) != 1 or a[0] == b[0] or b[0] in nb[a[0]]:
            continue
        a, b = a[0], b[0]
        u, v = e
        m.F[f1] = (a, b, u)
        m.F[f2] = (b, a, v)
        nflip += 1
    return nflip


def gen_edge_flip(rng, params):
    if rng.random() < 0.6:
        n = rng.randint(3, 5)
        amp = loguni(rng, -7, 0) if rng.random() < 0.4 else rng.uniform(0.2, 1.0)
        fz = smooth_fn(rng, 1.0)
        A = height_grid(lambda u, v: amp * fz(u, v), n, n, diag=rng.choice(['same', 'alt']))
        params.append('base=grid%d amp=%s' % (n, fmt(amp)))
    else:
        A = icosphere(rng.choice([0, 1])).mapped(lambda p: vmul(p, 1 + 0.1 * rng.uniform(-1, 1)))
        params.append('base=ico')
    B = A.copy()
    k = flip_random_edges(B, rng, rng.randint(1, 6))
    params.append('flips=%d' % k)
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


# --- CAD-like


def inset_convex(poly, c):
    n = len(poly)
    lines = []
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        dx, dy = q[0] - p[0], q[1] - p[1]
        L = math.hypot(dx, dy)
        nx, ny = -dy / L, dx / L
        lines.append((nx, ny, nx * p[0] + ny * p[1] + c))
    out = []
    for i in range(n):
        a1, b1, c1 = lines[i - 1]
        a2, b2, c2 = lines[i]
        det = a1 * b2 - a2 * b1
        out.append(((c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det))
    return out


def layered_prism(rings, cap_a, cap_b, rng):
    """rings: list of (poly2d, z); consecutive rings with equal vertex count joined by quads"""
    m = Mesh()
    idx = []
    for poly, z in rings:
        idx.append([m.add_v((p[0], p[1], z)) for p in poly])
    n = len(rings[0][0])
    for k in range(len(rings) - 1):
        for i in range(n):
            quad(m.F, idx[k][i], idx[k][(i + 1) % n], idx[k + 1][(i + 1) % n], idx[k + 1][i], rng.randrange(2))
    for ring_i, mode in ((0, cap_a), (len(rings) - 1, cap_b)):
        poly, z = rings[ring_i]
        ids = idx[ring_i]
        if mode == 'fan_vertex':
            s = rng.randrange(n)
            for i in range(1, n - 1):
                m.add_f(ids[s], ids[(s + i) % n], ids[(s + i + 1) % n])
        elif mode == 'fan_center':
            cx = sum(p[0] for p in poly) / n
            cy = sum(p[1] for p in poly) / n
            c = m.add_v((cx, cy, z))
            for i in range(n):
                m.add_f(c, ids[i], ids[(i + 1) % n])
        elif mode == 'ear':
            for (a, b, c) in ear_clip(poly, rng.randrange(n)):
                m.add_f(ids[a], ids[b], ids[c])
    return m


def split_edges2d(poly):
    out = []
    n = len(poly)
    for i in range(n):
        p, q = poly[i], poly[(i + 1) % n]
        out.append(p)
        out.append(((p[0] + q[0]) * 0.5, (p[1] + q[1]) * 0.5))
    return out


def gen_cad_chamfer(rng, params):
    if rng.random() < 0.5:
        W = loguni(rng, -1.7, -0.3)
        poly = [(0.0, 0.0), (1.0, 0.0), (1.0, W), (0.0, W)]
        inr = W / 2
        params.append('rect W=%s' % fmt(W))
    else:
        n = rng.randint(5, 9)
        angs = sorted(2 * math.pi * (i + rng.uniform(-0.3, 0.3)) / n for i in range(n))
        poly = [(math.cos(a), math.sin(a)) for a in angs]
        inr = 0.3
        params.append('ngon n=%d' % n)
    h = rng.uniform(0.05, 0.5)
    cmax = min(inr, h) * 0.45
    c1 = cmax * loguni(rng, -3, 0)
    mode = rng.choice(['sharp', 'sharp', 'two'])
    c2 = 0.0 if mode == 'sharp' else c1 * rng.uniform(0.5, 1.5)
    c2 = min(c2, cmax)
    split = rng.random() < 0.3

    def build(c, cbot, caps):
        P = split_edges2d(poly) if split else poly
        rings = []
        if cbot > 0:
            Pi = inset_convex(poly, cbot)
            rings.append((split_edges2d(Pi) if split else Pi, 0.0))
            rings.append((P, cbot))
        else:
            rings.append((P, 0.0))
        if c > 0:
            rings.append((P, h - c))
            Pi = inset_convex(poly, c)
            rings.append((split_edges2d(Pi) if split else Pi, h))
        else:
            rings.append((P, h))
        return layered_prism(rings, caps[0], caps[1], rng)
    cb = c1 if rng.random() < 0.3 else 0.0
    capsA = (rng.choice(['fan_vertex', 'ear']), rng.choice(['fan_vertex', 'ear', 'fan_center']))
    capsB = (rng.choice(['fan_center', 'ear']), rng.choice(['fan_vertex', 'fan_center']))
    A = build(c1, cb, capsA)
    B = build(c2, cb if mode == 'two' else 0.0, capsB)
    params.append('h=%s c=%s c2=%s cbot=%s split=%d caps=%s/%s' % (fmt(h), fmt(c1), fmt(c2), fmt(cb), split, ','.join(capsA), ','.join(capsB)))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def fillet_profile(r, k, Y, Z):
    if k == 0 or r == 0.0:
        return [(Y, 0.0), (0.0, 0.0), (0.0, Z)]
    prof = [(Y, 0.0)]
    for i in range(k + 1):
        phi = 0.5 * math.pi * i / k
        if i == 0:
            prof.append((r, 0.0))
        elif i == k:
            prof.append((0.0, r))
        else:
            prof.append((r - r * math.sin(phi), r - r * math.cos(phi)))
    prof.append((0.0, Z))
    return prof


def extrude_profile(prof, L, m_len, rng, diag='rand'):
    m = Mesh()
    rows = []
    for j in range(m_len + 1):
        x = L * j / m_len
        rows.append([m.add_v((x, y, z)) for (y, z) in prof])
    for j in range(m_len):
        for i in range(len(prof) - 1):
            quad(m.F, rows[j][i], rows[j][i + 1], rows[j + 1][i + 1], rows[j + 1][i], pick_diag(diag, i, j, rng))
    return m


def gen_fillet_strip(rng, params):
    L = rng.uniform(1.0, 4.0)
    r = loguni(rng, -2.5, -0.5)
    Y, Z = rng.uniform(0.3, 1.0), rng.uniform(0.3, 1.0)
    ka = rng.randint(1, 8)
    kb = rng.choice([0, 1, 2, 3, 5, 8])
    rb = r if rng.random() < 0.7 else r * rng.uniform(0.5, 1.5)
    ma, mb = rng.randint(1, 3), rng.randint(1, 3)
    A = extrude_profile(fillet_profile(r, ka, Y, Z), L, ma, rng)
    B = extrude_profile(fillet_profile(rb, kb, Y, Z), L, mb, rng, diag=rng.choice(['same', 'alt', 'rand']))
    params.append('L=%s r=%s rb=%s k=%d/%d m=%d/%d' % (fmt(L), fmt(r), fmt(rb), ka, kb, ma, mb))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_revolve_axis(rng, params):
    typ = rng.choice(['closed', 'open', 'pinch'])
    c = [rng.uniform(-0.3, 0.3) for _ in range(3)]
    H = rng.uniform(0.5, 2.0)
    R0 = rng.uniform(0.3, 1.0)

    def r_of(t):
        base = 1.0 + c[0] * math.sin(2 * math.pi * t) + c[1] * math.cos(3 * math.pi * t) + c[2] * t
        if typ == 'closed':
            return 0.0 if t in (0.0, 1.0) else R0 * math.sin(math.pi * t) * base
        if typ == 'open':
            return 0.0 if t == 0.0 else R0 * math.sin(0.5 * math.pi * t) * base
        return 0.0 if t in (0.0, 0.5, 1.0) else R0 * abs(math.sin(2 * math.pi * t)) * base

    def profile(k):
        return [(r_of(i / float(k)), H * i / float(k)) for i in range(k + 1)]
    ka = rng.choice([4, 6])
    kb = rng.choice([4, 6, 8]) if rng.random() < 0.6 else ka
    na = rng.randint(5, 10)
    nb = rng.randint(5, 12) if kb != ka else rng.choice([na, na + 1, na + 2, 2 * na if 2 * na <= 14 else na - 1])
    phase = rng.choice([0.0, 0.0, 0.5, rng.random()])
    A = revolve(profile(ka), na, diag=rng.choice(['same', 'alt']))
    B = revolve(profile(kb), nb, phase=phase, diag=rng.choice(['same', 'alt', 'rand']), rng=rng)
    params.append('type=%s H=%s k=%d/%d n=%d/%d phase=%s' % (typ, fmt(H), ka, kb, na, nb, fmt(phase)))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def helicoid(r0, r1, pitch, turns, nt, nr, phase=0.0, dz=0.0):
    T = 2 * math.pi * turns

    def f(u, v):
        t = T * u + phase
        r = r0 + (r1 - r0) * v
        if r == 0.0:
            return (0.0, 0.0, pitch * t / (2 * math.pi) + dz)
        return (r * math.cos(t), r * math.sin(t), pitch * t / (2 * math.pi) + dz)
    return f


def gen_helix_ramp(rng, params):
    r0 = 0.0 if rng.random() < 0.4 else rng.uniform(0.1, 0.5)
    r1 = r0 + rng.uniform(0.3, 1.0)
    pitch = rng.uniform(0.2, 1.5)
    turns = rng.uniform(0.5, 2.0)
    nta = max(4, int(turns * rng.uniform(6, 12)))
    ntb = max(4, int(turns * rng.uniform(8, 16)))
    nra, nrb = rng.randint(1, 2), rng.randint(1, 3)
    mode = rng.choice(['res', 'res', 'dz', 'pitch', 'phase'])
    dz = pitch_b = 0.0
    ph = 0.0
    pb = pitch
    if mode == 'dz':
        dz = loguni(rng, -9, -2) * rng.choice((-1, 1))
        ntb, nrb = nta, nra
    elif mode == 'pitch':
        pb = pitch * (1 + loguni(rng, -9, -2))
    elif mode == 'phase':
        ph = 2 * math.pi * turns / ntb * rng.random()
    A = grid_mesh(helicoid(r0, r1, pitch, turns, nta, nra), nta, nra, diag=rng.choice(['same', 'alt']))
    fb = helicoid(r0, r1, pb, turns, ntb, nrb, phase=ph, dz=dz)
    B = grid_mesh(fb, ntb, nrb, diag=rng.choice(['same', 'other', 'alt']))
    params.append('r=%s..%s pitch=%s turns=%s res=%dx%d/%dx%d mode=%s dz=%s pb=%s ph=%s' % (
        fmt(r0), fmt(r1), fmt(pitch), fmt(turns), nta, nra, ntb, nrb, mode, fmt(dz), fmt(pb), fmt(ph)))
    return A, B


def gen_helix_ramp_placed(rng, params):
    A, B = gen_helix_ramp(rng, params)
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def folded_strip(Lx, W, creases, angles, nsub, rng, diag_mode):
    """creases: list of (x0, x1) crease from (x0,0) to (x1,W); angles: fold angle per crease"""
    # affine transform per panel: (M, t) with p -> M p + t
    Ms = [([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], (0.0, 0.0, 0.0))]
    for (x0, x1), ang in zip(creases, angles):
        M, t = Ms[-1]
        q0 = (x0, 0.0, 0.0)
        axis = (x1 - x0, W, 0.0)
        Rm = rot_axis(axis, ang)
        # p -> M (R (p - q0) + q0) + t
        M2 = mat_mul(M, Rm)
        t2 = vadd(vsub(mat_apply(M, q0), mat_apply(M2, q0)), t)
        Ms.append((M2, t2))
    lines = [(0.0, 0.0)] + list(creases) + [(Lx, Lx)]
    m = Mesh()
    cols = []
    for k, (x0, x1) in enumerate(lines):
        M, t = Ms[max(0, k - 1)] if k > 0 else Ms[0]
        if k == len(lines) - 1:
            M, t = Ms[-1]
        col = []
        for j in range(nsub + 1):
            s = j / float(nsub)
            p = (x0 + (x1 - x0) * s, W * s, 0.0)
            col.append(m.add_v(vadd(mat_apply(M, p), t)))
        cols.append(col)
    for k in range(len(cols) - 1):
        for j in range(nsub):
            quad(m.F, cols[k][j], cols[k + 1][j], cols[k + 1][j + 1], cols[k][j + 1], pick_diag(diag_mode, k, j, rng))
    return m


def gen_folded_paper(rng, params):
    Lx = rng.uniform(2.0, 6.0)
    W = rng.uniform(0.1, 1.0)
    nc = rng.randint(1, 5)
    xs = sorted(rng.uniform(0.1, 0.9) * Lx for _ in range(nc))
    gap = min([Lx] + [xs[i + 1] - xs[i] for i in range(nc - 1)] + [xs[0], Lx - xs[-1]])
    creases = []
    for x in xs:
        s = rng.uniform(-0.45, 0.45) * gap
        creases.append((x - s, x + s))
    angles = [rng.choice((-1, 1)) * rng.uniform(0.1, 2.6) for _ in range(nc)]
    mode = rng.choice(['angle', 'retri', 'unfold', 'angle'])
    A = folded_strip(Lx, W, creases, angles, 1, rng, 'same')
    if mode == 'angle':
        d = loguni(rng, -9, -2)
        ang2 = [a + d * rng.choice((-1, 1)) for a in angles]
        B = folded_strip(Lx, W, creases, ang2, 1, rng, rng.choice(['same', 'other']))
        params.append('dangle=%s' % fmt(d))
    elif mode == 'retri':
        B = folded_strip(Lx, W, creases, angles, rng.randint(2, 4), rng, rng.choice(['alt', 'rand', 'other']))
    else:
        ang2 = list(angles)
        ang2[rng.randrange(nc)] = 0.0
        B = folded_strip(Lx, W, creases, ang2, 1, rng, 'other')
    params.append('L=%s W=%s creases=%d mode=%s' % (fmt(Lx), fmt(W), nc, mode))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_gear_extrude(rng, params):
    n = rng.randint(5, 10)
    Ro = 1.0
    Ri = rng.uniform(0.5, 0.9)
    jit = rng.uniform(0.0, 0.2)
    angs = [2 * math.pi * (i + rng.uniform(-jit, jit)) / (2 * n) for i in range(2 * n)]

    def outline(rot=0.0, ro=Ro):
        return [((ro if i % 2 == 0 else Ri) * math.cos(a + rot), (ro if i % 2 == 0 else Ri) * math.sin(a + rot)) for i, a in enumerate(angs)]
    h = rng.uniform(0.05, 0.6)
    mode = rng.choice(['retri', 'twist', 'tip', 'height'])
    A = layered_prism([(outline(), 0.0), (outline(), h)], 'fan_center', 'fan_center', rng)
    d = loguni(rng, -9, -3)
    if mode == 'retri':
        B = layered_prism([(outline(), 0.0), (outline(), h)], 'ear', 'ear', rng)
    elif mode == 'twist':
        B = layered_prism([(outline(d), 0.0), (outline(d), h)], 'ear', rng.choice(['ear', 'fan_center']), rng)
    elif mode == 'tip':
        B = layered_prism([(outline(0.0, Ro * (1 + d)), 0.0), (outline(0.0, Ro * (1 + d)), h)], 'ear', 'fan_center', rng)
    else:
        B = layered_prism([(outline(), 0.0), (outline(), h * (1 + d))], 'fan_center', 'ear', rng)
    params.append('teeth=%d Ri=%s h=%s mode=%s d=%s' % (n, fmt(Ri), fmt(h), mode, fmt(d)))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def plate(corners4, nx, ny, diag, rng):
    """bilinear grid over a planar quad given by 4 corners (p00, p10, p11, p01)"""
    p00, p10, p11, p01 = corners4

    def f(u, v):
        a = vlerp(p00, p10, u)
        b = vlerp(p01, p11, u)
        return vlerp(a, b, v)
    return grid_mesh(f, nx, ny, diag=diag, rng=rng)


def gen_stacked_planes(rng, params):
    if rng.random() < 0.5:
        L = rng.uniform(1.0, 3.0)
        rho0 = 0.0 if rng.random() < 0.5 else rng.uniform(0.05, 0.5)
        rho1 = rho0 + rng.uniform(0.5, 1.5)
        delta = loguni(rng, -9, -3)
        nb_planes = rng.randint(1, 4)

        def pl(alpha, r0, r1, nx, ny, diag):
            ca, sa = math.cos(alpha), math.sin(alpha)
            P = [(0.0, r0 * ca, r0 * sa), (L, r0 * ca, r0 * sa), (L, r1 * ca, r1 * sa), (0.0, r1 * ca, r1 * sa)]
            return plate(P, nx, ny, diag, rng)
        A = pl(0.0, rho0, rho1, rng.randint(1, 3), rng.randint(1, 2), 'same')
        Bs = []
        for i in range(1, nb_planes + 1):
            alpha = i * delta * rng.uniform(1.0, 1.5) * rng.choice((-1, 1))
            if rng.random() < 0.3:
                Bs.append(pl(alpha, -rho1, -rho0 if rho0 > 0 else rho1 * 0.5, 1, 1, 'other'))
            else:
                Bs.append(pl(alpha, rho0 * rng.uniform(0.5, 1.5), rho1 * rng.uniform(0.7, 1.2), rng.randint(1, 3), 1, rng.choice(['same', 'other'])))
        B = concat(*Bs)
        params.append('pencil planes=%d delta=%s rho0=%s' % (nb_planes, fmt(delta), fmt(rho0)))
    else:
        g = loguni(rng, -6, -1)
        npl = rng.randint(3, 6)
        plates = []
        for i in range(npl):
            eps = loguni(rng, -9, -3) * rng.choice((-1, 1))
            ax = rng.uniform(0, math.pi)
            M = rot_axis((math.cos(ax), math.sin(ax), 0.0), eps)
            ox, oy = rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)
            P = [(ox, oy, 0.0), (1 + ox, oy, 0.0), (1 + ox, 1 + oy, 0.0), (ox, 1 + oy, 0.0)]
            c = (0.5 + ox, 0.5 + oy, 0.0)
            P = [vadd(mat_apply(M, vsub(p, c)), (c[0], c[1], i * g)) for p in P]
            plates.append(plate(P, rng.randint(1, 2), rng.randint(1, 2), 'same' if i % 2 == 0 else 'other', rng))
        A = concat(*plates[0::2])
        B = concat(*plates[1::2])
        params.append('stack plates=%d gap=%s' % (npl, fmt(g)))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def dyadic_polyhedron(rng, params):
    name = rng.choice(['tetra', 'cube', 'octa', 'pyramid', 'prism'])
    if name == 'tetra':
        m = Mesh([(0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)])
    elif name == 'cube':
        m = box_mesh((0, 0, 0), (4, 4, 4), rng)
    elif name == 'octa':
        m = octahedron(4.0)
    elif name == 'pyramid':
        m = square_pyramid(2.0)
    else:
        m = tri_prism(2.0)
    if rng.random() < 0.6:
        m = m.mapped(lambda p: tuple(c + rng.randint(-1, 1) for c in p))
    params.append('poly=%s' % name)
    return m


def vertex_ring(m, v):
    nxt = {}
    for (a, b, c) in m.F:
        for x, y, z in ((a, b, c), (b, c, a), (c, a, b)):
            if x == v:
                nxt[y] = z
    if not nxt:
        return None
    start = min(nxt)
    ring = [start]
    while True:
        n = nxt.get(ring[-1])
        if n is None:
            return None
        if n == start:
            break
        ring.append(n)
        if len(ring) > len(nxt):
            return None
    return ring if len(ring) == len(nxt) else None


def gen_verts_on_edges(rng, params):
    A = dyadic_polyhedron(rng, params)
    tchoices = [0.25, 0.5, 0.375, 0.125, 0.0]
    glob = rng.random() < 0.4
    tg = rng.choice(tchoices[:4])
    tv = [tg if glob else rng.choice(tchoices) for _ in A.V]
    B = Mesh()
    cp = {}

    def cut(v, w):
        if (v, w) not in cp:
            cp[(v, w)] = B.add_v(vlerp(A.V[v], A.V[w], tv[v]))
        return cp[(v, w)]
    for (a, b, c) in A.F:
        hexa = [cut(a, b), cut(b, a), cut(b, c), cut(c, b), cut(c, a), cut(a, c)]
        s = rng.randrange(6)
        hexa = hexa[s:] + hexa[:s]
        for i in range(1, 5):
            B.add_f(hexa[0], hexa[i], hexa[i + 1])
    for v in range(len(A.V)):
        if tv[v] == 0.0:
            continue
        ring = vertex_ring(A, v)
        if ring is None:
            continue
        pts = [cut(v, w) for w in ring]
        for i in range(1, len(pts) - 1):
            B.add_f(pts[0], pts[i], pts[i + 1])
    keep_degen = rng.random() < 0.3
    B = weld(B, drop_degen=True)
    if keep_degen:   # zero-area triangles along some cut edges (collinear corners)
        ef = edge_faces(B)
        es = sorted(ef)
        for _ in range(rng.randint(1, 3)):
            e = rng.choice(es)
            mid = B.add_v(vmul(vadd(B.V[e[0]], B.V[e[1]]), 0.5))
            B.add_f(e[0], e[1], mid)
    params.append('t=%s degen=%d' % ('global:' + fmt(tg) if glob else 'per_vertex', keep_degen))
    A, B = place(rng, A, B, params, PLACE_EXACT)
    return maybe_swap(rng, A, B, params)


def gen_corners_on_planes(rng, params):
    if rng.random() < 0.5:
        n = rng.randint(2, 3)
        H = [[rng.randint(0, 3) for _ in range(n + 1)] for _ in range(n + 1)]
        A = grid_mesh(lambda u, v: (u * n * 2.0, v * n * 2.0, float(H[int(round(u * n))][int(round(v * n))])), n, n, diag='rand', rng=rng)
        params.append('base=terrain%d' % n)
    else:
        A = dyadic_polyhedron(rng, params)
    B = Mesh()
    nt = rng.randint(3, 10)
    fr = [x / 4.0 for x in range(-1, 6)]
    for _ in range(nt):
        f = rng.choice(A.F)
        a, b, c = A.tri(f)
        N = vcross(vsub(b, a), vsub(c, a))
        if N == (0.0, 0.0, 0.0):
            continue

        def inplane():
            u, w = rng.choice(fr), rng.choice(fr)
            return vadd(a, vadd(vmul(vsub(b, a), u), vmul(vsub(c, a), w)))
        typ = rng.choice(['standing', 'standing', 'vertex_edge', 'lying', 'below'])
        if typ in ('standing', 'below'):
            p, q = inplane(), inplane()
            if p == q:
                q = vadd(q, vmul(vsub(b, a), 0.5))
            k = rng.choice([0.25, 0.5, 1.0]) * (1 if typ == 'standing' else -1)
            r = vadd(p if rng.random() < 0.5 else vmul(vadd(p, q), 0.5), vmul(N, k / max(1.0, 2.0 ** round(math.log(vlen(N), 2)))))
        elif typ == 'vertex_edge':
            p = a
            q = vlerp(b, c, rng.choice([0.25, 0.5, 0.75]))
            r = vadd(vlerp(a, b, rng.choice([0.5, 1.0, 1.5])), tuple(float(rng.randint(-2, 2)) for _ in range(3)))
        else:
            p, q, r = inplane(), inplane(), inplane()
        B.add_f(B.add_v(p), B.add_v(q), B.add_v(r))
    if not B.F:
        a, b, c = A.tri(A.F[0])
        B.add_f(B.add_v(a), B.add_v(vlerp(b, c, 0.5)), B.add_v(vadd(b, (1.0, 1.0, 1.0))))
    B = weld(B, drop_degen=False)
    params.append('tris=%d' % len(B.F))
    A, B = place(rng, A, B, params, PLACE_EXACT)
    return maybe_swap(rng, A, B, params)


def gen_mirror_plane(rng, params):
    typ = rng.choice(['terrain', 'dome', 'swap'])
    if typ in ('terrain', 'swap'):
        nx, ny = rng.randint(2, 5), rng.randint(2, 5)
        pz = rng.uniform(0.2, 0.6)
        hs = {}
        for i in range(nx + 1):
            for j in range(ny + 1):
                r = rng.random()
                if r < pz:
                    hs[(i, j)] = 0.0
                elif r < pz + 0.3:
                    hs[(i, j)] = rng.randint(-8, 8) / 8.0
                else:
                    hs[(i, j)] = rng.uniform(-1, 1)

        def f(u, v):
            i, j = int(round(u * nx)), int(round(v * ny))
            return (i / 4.0, j / 4.0, hs[(i, j)])
        A = grid_mesh(f, nx, ny, diag=rng.choice(['same', 'alt', 'rand']), rng=rng)
        if typ == 'terrain':
            B = A.mapped(lambda p: (p[0], p[1], -p[2]))
        else:
            # local (u, v, w) -> world (u + w, u - w, v): mirror w -> -w is the swap x <-> y
            A = A.mapped(lambda p: (p[0] + p[2], p[0] - p[2], p[1]))
            B = A.mapped(lambda p: (p[1], p[0], p[2]))
        params.append('%s %dx%d pzero=%s' % (typ, nx, ny, fmt(pz)))
    else:
        n = rng.randint(5, 12)
        k = rng.randint(1, 3)
        a, c = rng.uniform(0.5, 1.5), rng.uniform(0.2, 1.5)
        prof = [(0.0, c)] + [(a * math.sin(0.5 * math.pi * i / k), c * math.cos(0.5 * math.pi * i / k)) for i in range(1, k)] + [(a, 0.0), (0.0, 0.0)]
        A = revolve(prof, n)
        B = A.mapped(lambda p: (p[0], p[1], -p[2]))
        params.append('dome n=%d k=%d' % (n, k))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_cap_needle(rng, params):
    if rng.random() < 0.6:
        n = rng.randint(4, 5)
        fz = smooth_fn(rng, 0.4)
        A = height_grid(fz, n, n, diag='alt')
        params.append('base=grid%d' % n)
    else:
        A = icosphere(1).mapped(lambda p: vmul(p, 1.0 + 0.05 * p[0]))
        params.append('base=ico1')
    B = A.copy()
    ops = []
    for _ in range(rng.randint(1, 5)):
        ef = edge_faces(B)
        es = sorted(ef)
        e = rng.choice(es)
        fs = ef[e]
        op = rng.choice(['cap_in', 'cap_out', 'needle', 'needle', 'zero', 'repidx'])
        u, v = e
        pu, pv = B.V[u], B.V[v]
        L = vlen(vsub(pv, pu))
        f1 = fs[0]
        c = [i for i in B.F[f1] if i not in e]
        if len(c) != 1:
            continue
        c = c[0]
        asp = loguni(rng, -9, -3)
        if op == 'repidx':   # zero-area triangle with a repeated index on an existing edge
            B.add_f(u, u, v)
            ops.append('repidx')
            continue
        if op == 'needle':
            if len(fs) != 2:
                continue
            if rng.random() < 0.5:
                u, v = v, u
                pu, pv = pv, pu
            p = B.add_v(vlerp(pu, pv, asp))
            newF = []
            for fi in fs:
                f = B.F[fi]
                w = [i for i in f if i not in (u, v)][0]
                newF.append((u, p, w))
                newF.append((p, v, w))
            B.F = [f for i, f in enumerate(B.F) if i not in fs] + newF
            ops.append('needle:%s' % fmt(asp))
        else:
            t = rng.uniform(0.2, 0.8)
            base = vlerp(pu, pv, t)
            if op == 'cap_out':
                nrm = vnorm(face_normal(B, B.F[f1]))
                pt = vadd(base, vmul(nrm, L * asp * rng.choice((-1, 1))))
            elif op == 'cap_in':
                d = vsub(B.V[c], base)
                along = vnorm(vsub(pv, pu))
                perp = vnorm(vsub(d, vmul(along, vdot(d, along))))
                pt = vadd(base, vmul(perp, L * asp))
            else:
                pt = vmul(vadd(pu, pv), 0.5)
                asp = 0.0
            p = B.add_v(pt)
            B.F[f1] = (u, p, c)
            B.F.append((p, v, c))
            B.F.append((u, v, p))
            ops.append('%s:%s' % (op, fmt(asp)))
    if rng.random() < 0.3:
        A = A if rng.random() < 0.5 else A.copy()
        flip_random_edges(A, rng, 2)
        ops.append('clean_flipped')
    params.append('ops=' + ','.join(ops))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_equidistant_curves(rng, params):
    typ = rng.choice(['slab', 'skew', 'point_plane', 'roof', 'two_points', 'diamond'])
    A = Mesh()
    B = Mesh()

    def tri(m, p, q, r):
        m.add_f(m.add_v(p), m.add_v(q), m.add_v(r))

    def sq(m, z, s, rot, k=1, plane='z', off=0.0):
        # k x k grid over [-s,s]^2 in the given plane
        def f(u, v):
            x, y = -s + 2 * s * u, -s + 2 * s * v
            if rot:
                x, y = y, -x
            if plane == 'z':
                return (x, y, z)
            if plane == 'y':
                return (x, off, y + z)
            return (off, x, y + z)
        m.append(grid_mesh(f, k, k, diag=rng.choice(['same', 'other', 'alt'])))
    if typ == 'slab':
        d = rng.choice([0.25, 0.5, 1.0])
        sq(A, d, rng.choice([1.0, 2.0]), False)
        sq(A, -d, rng.choice([1.0, 1.5, 2.0]), rng.random() < 0.5)
        sq(B, 0.0, rng.choice([0.5, 1.0, 2.5]), False, rng.randint(1, 3))
        if rng.random() < 0.5:
            tri(B, (-1.0, -1.0, -0.5), (1.0, -0.5, 0.5), (0.0, 1.0, 0.25))
        params.append('d=%s' % fmt(d))
    elif typ == 'skew':
        h = rng.choice([0.25, 0.5, 1.0])
        H = rng.choice([0.5, 1.0])
        L = rng.choice([1.0, 2.0])
        tri(A, (-L, 0.0, h), (L, 0.0, h), (0.0, 0.0, h + H))
        tri(A, (0.0, -L, -h), (0.0, L, -h), (0.0, 0.0, -h - H))
        c = rng.choice([0.0, 0.0, 0.125, -0.25, 0.0625])
        sq(B, c, rng.choice([0.5, 1.0, 1.5]), False, rng.randint(1, 3))
        params.append('h=%s z=%s' % (fmt(h), fmt(c)))
    elif typ == 'point_plane':
        h = rng.choice([0.25, 0.5])
        b = rng.choice([0.125, 0.25])
        s = rng.choice([1.0, 2.0])
        sq(A, 0.0, s, False)
        ap = (0.0, 0.0, 2 * h)
        top = 2 * h + rng.choice([0.25, 0.5])
        base = [(-b, -b, top), (b, -b, top), (0.0, b, top)]
        for i in range(3):
            tri(A, ap, base[i], base[(i + 1) % 3])
        tri(A, base[0], base[2], base[1])
        y0 = rng.choice([0.0, 0.0, 0.125, 0.25])
        sq(B, 2 * h, 2 * h, False, rng.randint(1, 2), plane='y', off=y0)
        params.append('h=%s y0=%s' % (fmt(h), fmt(y0)))
    elif typ == 'roof':
        a, h, L = rng.choice([0.5, 1.0]), rng.choice([0.5, 1.0]), rng.choice([1.0, 2.0])
        for sgn in (-1.0, 1.0):
            P = [(sgn * a, -L, 0.0), (sgn * a, L, 0.0), (0.0, L, h), (0.0, -L, h)]
            A.append(plate(P, 1, rng.randint(1, 2), rng.choice(['same', 'other']), rng))
        tri(B, (0.0, -0.5 * L, -h), (0.0, 0.5 * L, -h), (0.0, 0.0, 0.5 * h))
        if rng.random() < 0.6:
            tri(B, (-a, -0.25 * L, 0.5 * h), (a, -0.25 * L, 0.5 * h), (0.0, 0.75 * L, 0.5 * h))
        params.append('a=%s h=%s L=%s' % (fmt(a), fmt(h), fmt(L)))
    elif typ == 'two_points':
        h = rng.choice([0.25, 0.5, 1.0])
        b = rng.choice([0.25, 0.5])
        for sgn in (-1.0, 1.0):
            ap = (0.0, 0.0, sgn * h)
            top = sgn * (h + b)
            base = [(-b, -b, top), (b, -b, top), (b, b, top), (-b, b, top)]
            for i in range(4):
                tri(A, ap, base[i], base[(i + 1) % 4])
        c = rng.choice([0.0, 0.0, 0.125])
        sq(B, c, rng.choice([0.5, 1.0, 2.0]), False, rng.randint(1, 3))
        params.append('h=%s z=%s' % (fmt(h), fmt(c)))
    else:
        r, h, H = rng.choice([0.5, 1.0]), rng.choice([0.25, 0.5]), rng.choice([0.5, 1.0, -0.25])
        ring = [(r, 0.0, h), (0.0, r, h), (-r, 0.0, h), (0.0, -r, h)]
        ap = (0.0, 0.0, h + H)
        for i in range(4):
            tri(A, ap, ring[i], ring[(i + 1) % 4])
        sq(B, 0.0, rng.choice([0.5, 1.0]), rng.random() < 0.5, rng.randint(1, 3))
        params.append('r=%s h=%s H=%s' % (fmt(r), fmt(h), fmt(H)))
    params.insert(0, 'layout=%s' % typ)
    A, B = weld(A, False), weld(B, False)
    A, B = place(rng, A, B, params, PLACE_EXACT)
    return maybe_swap(rng, A, B, params)


def gen_quad_diag(rng, params):
    nx, ny = rng.randint(2, 5), rng.randint(2, 5)
    tw = rng.choice([0.25, 0.5, 1.0, 2.0, 1.0 / 64])
    hs = {(i, j): rng.randint(-4, 4) / 8.0 for i in range(nx + 1) for j in range(ny + 1)}
    noise = rng.random() < 0.5

    def pt(i, j):
        x, y = i / 4.0, j / 4.0
        return (x, y, tw * (i - nx / 2.0) * (j - ny / 2.0) / 16.0 + (hs[(i, j)] if noise else 0.0))
    mode = rng.choice(['other', 'checker', 'center'])
    A = Mesh()
    B = Mesh()
    ida = {(i, j): A.add_v(pt(i, j)) for i in range(nx + 1) for j in range(ny + 1)}
    idb = {(i, j): B.add_v(pt(i, j)) for i in range(nx + 1) for j in range(ny + 1)}
    for i in range(nx):
        for j in range(ny):
            quad(A.F, ida[(i, j)], ida[(i + 1, j)], ida[(i + 1, j + 1)], ida[(i, j + 1)], 0)
            q = [idb[(i, j)], idb[(i + 1, j)], idb[(i + 1, j + 1)], idb[(i, j + 1)]]
            if mode == 'other':
                quad(B.F, q[0], q[1], q[2], q[3], 1)
            elif mode == 'checker':
                quad(B.F, q[0], q[1], q[2], q[3], (i + j) % 2)
            else:
                c = B.add_v(vmul(vadd(vadd(B.V[q[0]], B.V[q[1]]), vadd(B.V[q[2]], B.V[q[3]])), 0.25))
                for k in range(4):
                    B.add_f(q[k], q[(k + 1) % 4], c)
    params.append('grid=%dx%d twist=%s noise=%d mode=%s' % (nx, ny, fmt(tw), noise, mode))
    A, B = place(rng, A, B, params, PLACE_EXACT)
    return maybe_swap(rng, A, B, params)


def random_solid(rng):
    name = rng.choice(['box', 'octa', 'tetra', 'hexprism', 'ico1', 'torus', 'uv'])
    if name == 'box':
        m = box_mesh((-rng.uniform(0.3, 1), -rng.uniform(0.3, 1), -rng.uniform(0.3, 1)), (rng.uniform(0.3, 1), rng.uniform(0.3, 1), rng.uniform(0.3, 1)), rng)
    elif name == 'octa':
        m = octahedron(rng.uniform(0.6, 1.2))
    elif name == 'tetra':
        m = tetrahedron(rng.uniform(0.5, 1.0))
    elif name == 'hexprism':
        poly = [(math.cos(math.pi * i / 3), math.sin(math.pi * i / 3)) for i in range(6)]
        m = layered_prism([(poly, -0.5), (poly, 0.5)], 'fan_center', 'ear', rng)
    elif name == 'ico1':
        m = icosphere(1)
    elif name == 'torus':
        m = torus(0.8, 0.3, 8, 4)
    else:
        m = uv_ellipsoid(1.0, 0.7, 0.5, 8, 5)
    s = (rng.uniform(0.6, 1.3), rng.uniform(0.6, 1.3), rng.uniform(0.6, 1.3))
    M = rand_rot(rng)
    t = tuple(rng.uniform(-0.3, 0.3) for _ in range(3))
    return m.mapped(lambda p: vadd(mat_apply(M, (p[0] * s[0], p[1] * s[1], p[2] * s[2])), t)), name


def gen_cross_solids(rng, params):
    A, na = random_solid(rng)
    B, nb = random_solid(rng)
    params.append('solids=%s/%s' % (na, nb))
    A, B = place(rng, A, B, params, (0.5, 0.5, 0.0))
    return A, B


def row_mesh(rows, fz):
    """rows: list of lists of (x, y) sorted by x; returns mesh over them"""
    m = Mesh()
    ids = []
    for row in rows:
        ids.append([m.add_v((x, y, fz(x, y))) for (x, y) in row])
    for k in range(len(rows) - 1):
        m.F.extend(strip_rows(ids[k], ids[k + 1], lambda i: m.V[i][0]))
    return m


def gen_remesh_patch(rng, params):
    fz0 = smooth_fn(rng, rng.uniform(0.1, 0.6))
    fz = lambda x, y: fz0(x, y)
    na, ma = rng.randint(3, 5), rng.randint(3, 5)
    jit = rng.uniform(0.0, 0.35)
    rowsA = []
    for j in range(ma + 1):
        row = []
        for i in range(na + 1):
            x = (i + (rng.uniform(-jit, jit) if 0 < i < na else 0.0)) / na
            y = (j + (rng.uniform(-jit, jit) if 0 < j < ma else 0.0)) / ma
            row.append((x, y))
        rowsA.append(row)
    nb, mb = rng.randint(3, 5), rng.randint(3, 5)
    rowsB = []
    for j in range(mb + 1):
        y = j / float(mb)
        if j % 2 == 0:
            row = [(i / float(nb), y) for i in range(nb + 1)]
        else:
            row = [(0.0, y)] + [((i + 0.5) / nb, y) for i in range(nb)] + [(1.0, y)]
        rowsB.append(row)
    A = row_mesh(rowsA, fz)
    B = row_mesh(rowsB, fz)
    params.append('a=%dx%d jit=%s b=hex%dx%d' % (na, ma, fmt(jit), nb, mb))
    A, B = place(rng, A, B, params)
    return maybe_swap(rng, A, B, params)


def gen_hole_fill(rng, params):
    n = rng.choice([4, 5, 6, 8])
    flat = rng.random() < 0.3
    if flat:
        ax, ay = rng.randint(-4, 4) / 4.0, rng.randint(-4, 4) / 4.0
        fz = lambda u, v: ax * u + ay * v
    else:
        fz = smooth_fn(rng, 0.4)
    diag = rng.choice(['same', 'alt'])
    full = height_grid(fz, n, n, diag=diag)
    # vertex index of grid point (i, j) is i*(n+1)+j (grid_mesh order, no welding happens)
    di, dj = rng.randint(1, min(3, n - 2)), rng.randint(1, min(3, n - 2))
    i0, j0 = rng.randint(1, n - 1 - di), rng.randint(1, n - 1 - dj)
    i1, j1 = i0 + di, j0 + dj

    def vid(i, j):
        return i * (n + 1) + j
    holed = Mesh(full.V, [f for f in full.F if not all(i0 <= full.V[k][0] * n + 1e-9 and full.V[k][0] * n - 1e-9 <= i1
                                                        and j0 <= full.V[k][1] * n + 1e-9 and full.V[k][1] * n - 1e-9 <= j1 for k in f)])
    loop = [vid(i, j0) for i in range(i0, i1)] + [vid(i1, j) for j in range(j0, j1)] + \
           [vid(i, j1) for i in range(i1, i0, -1)] + [vid(i0, j) for j in range(j1, j0, -1)]
    mode = rng.choice(['center', 'corner', 'ear'])
    filled = Mesh(list(holed.V), list(holed.F))
    if mode == 'center':
        c = (0.0, 0.0, 0.0)
        for k in loop:
            c = vadd(c, filled.V[k])
        cidx = filled.add_v(vmul(c, 1.0 / len(loop)))
        for k in range(len(loop)):
            filled.add_f(cidx, loop[k], loop[(k + 1) % len(loop)])
    elif mode == 'corner':
        s = rng.randrange(len(loop))
        L = loop[s:] + loop[:s]
        for k in range(1, len(L) - 1):
            filled.add_f(L[0], L[k], L[k + 1])
    else:
        poly = [(filled.V[k][0], filled.V[k][1]) for k in loop]
        for (a, b, c) in ear_clip(poly, rng.randrange(len(loop))):
            filled.add_f(loop[a], loop[b], loop[c])
    other = rng.choice(['full', 'holed', 'coarse'])
    if other == 'full':
        A = full
    elif other == 'holed':
        A = holed
    else:
        A = height_grid(fz, max(2, n // 2), max(2, n // 2), diag='other')
    params.append('n=%d flat=%d hole=%dx%d fill=%s other=%s' % (n, flat, di, dj, mode, other))
    A, B = place(rng, A, compact(filled), params)
    return maybe_swap(rng, A, B, params)


def far_variant(gen):
    def g(rng, params):
        A, B = gen(rng, params)
        return far_translate(rng, A, B, params)
    return g


def gen_helix_far_base(rng, params):
    A, B = gen_helix_ramp(rng, params)
    if rng.random() < 0.5:
        fn, desc = rotation_transform(rng)
        A, B = A.mapped(fn), B.mapped(fn)
        params.append('place=' + desc)
    return A, B


GENERATORS = [
    ('torus_res', gen_torus_res),
    ('ellipsoid_res', gen_ellipsoid_res),
    ('capsule_res', gen_capsule_res),
    ('superquadric', gen_superquadric),
    ('loop_subdiv', gen_loop_subdiv),
    ('midpoint_displace', gen_midpoint_displace),
    ('laplacian_smooth', gen_laplacian_smooth),
    ('qem_decimate', gen_qem_decimate),
    ('normal_offset', gen_normal_offset),
    ('edge_flip', gen_edge_flip),
    ('cad_chamfer', gen_cad_chamfer),
    ('fillet_strip', gen_fillet_strip),
    ('revolve_axis', gen_revolve_axis),
    ('helix_ramp', gen_helix_ramp_placed),
    ('folded_paper', gen_folded_paper),
    ('gear_extrude', gen_gear_extrude),
    ('stacked_planes', gen_stacked_planes),
    ('verts_on_edges', gen_verts_on_edges),
    ('corners_on_planes', gen_corners_on_planes),
    ('mirror_plane', gen_mirror_plane),
    ('cap_needle', gen_cap_needle),
    ('equidistant_curves', gen_equidistant_curves),
    ('quad_diag', gen_quad_diag),
    ('cross_solids', gen_cross_solids),
    ('remesh_patch', gen_remesh_patch),
    ('hole_fill', gen_hole_fill),
    ('torus_far', far_variant(gen_torus_res)),
    ('qem_far', far_variant(gen_qem_decimate)),
    ('offset_far', far_variant(gen_normal_offset)),
    ('helix_far', far_variant(gen_helix_far_base)),
]
KINDS = [k for k, _ in GENERATORS]
GEN = dict(GENERATORS)


# ----------------------------------------------------------------------------- checks and output


def max_valence(m):
    by_idx = {}
    by_pos = {}
    for f in m.F:
        for i in set(f):
            by_idx[i] = by_idx.get(i, 0) + 1
        for p in set(m.V[i] for i in f):
            by_pos[p] = by_pos.get(p, 0) + 1
    return max(list(by_idx.values()) + list(by_pos.values()) + [0])


def acceptable(m):
    return 1 <= len(m.F) <= 200 and max_valence(m) <= 30


def validate(m, what):
    if not (1 <= len(m.F) <= 200):
        raise ValueError('%s: %d triangles' % (what, len(m.F)))
    for v in m.V:
        if len(v) != 3 or not all(isinstance(c, float) and math.isfinite(c) for c in v):
            raise ValueError('%s: bad vertex %r' % (what, v))
    used = [False] * len(m.V)
    for f in m.F:
        if len(f) != 3:
            raise ValueError('%s: bad face %r' % (what, f))
        for i in f:
            if not (0 <= i < len(m.V)):
                raise ValueError('%s: index %d out of range' % (what, i))
            used[i] = True
    if not all(used):
        raise ValueError('%s: unused vertex' % what)
    if max_valence(m) > 30:
        raise ValueError('%s: valence > 30' % what)


def make_pair(seed):
    kind = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    for attempt in range(200):
        params = []
        A, B = GEN[kind](rng, params)
        A, B = compact(A), compact(B)
        if acceptable(A) and acceptable(B):
            if attempt:
                params.append('redraws=%d' % attempt)
            break
    else:
        raise ValueError('seed %d kind %s: no acceptable draw' % (seed, kind))
    validate(A, 'seed %d mesh a' % seed)
    validate(B, 'seed %d mesh b' % seed)
    return kind, A, B, ' '.join(params)


def obj_text(m, header):
    out = [header]
    for v in m.V:
        out.append('v %s %s %s' % (repr(v[0] + 0.0 if v[0] == 0.0 else v[0]), repr(v[1] + 0.0 if v[1] == 0.0 else v[1]), repr(v[2] + 0.0 if v[2] == 0.0 else v[2])))
    for f in m.F:
        out.append('f %d %d %d' % (f[0] + 1, f[1] + 1, f[2] + 1))
    return '\n'.join(out) + '\n'


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: %s OUTDIR FROM TO\n' % argv[0])
        return 2
    outdir, lo, hi = argv[1], int(argv[2]), int(argv[3])
    if not os.path.isdir(outdir):
        os.makedirs(outdir)
    counts = []
    pairs = 0
    for s in range(lo, hi):
        kind, A, B, params = make_pair(s)
        for tag, m in (('a', A), ('b', B)):
            header = '# gen16 seed=%d kind=%s mesh=%s %s' % (s, kind, tag, params.replace('\n', ' '))
            with open(os.path.join(outdir, '%06d_%s_%s.obj' % (s, kind, tag)), 'w') as fh:
                fh.write(obj_text(m, header))
            counts.append(len(m.F))
        pairs += 1
    if counts:
        c = sorted(counts)
        print('gen16: %d pairs written to %s; triangles per mesh min/median/max = %d/%d/%d' % (pairs, outdir, c[0], c[len(c) // 2], c[-1]))
    else:
        print('gen16: 0 pairs written')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
