#!/usr/bin/env python3
"""
generate_pairs13.py -- independent generator of adversarial triangle-mesh pairs
for testing an exact (two-sided) Hausdorff-distance tool.

Usage:
    python3 generate_pairs13.py OUTDIR FROM TO

For every integer seed s in [FROM, TO) two Wavefront OBJ files are written:

    OUTDIR/NNNNNN_KIND_a.obj      OUTDIR/NNNNNN_KIND_b.obj

where NNNNNN is s zero-padded to 6 digits and KIND = KINDS[s % len(KINDS)].
All random choices come from random.Random(s), so the output depends only on
the seed.  OUTDIR is created if missing.  Each file holds one comment line,
'v x y z' lines written with repr(float) (exact round trip of doubles) and
'f i j k' lines (1-based).  Every mesh has 1..300 triangles (most pairs stay
below ~120 per mesh), only finite coordinates, valid indices and no unused
vertex; every mesh is validated before it is written (ValueError otherwise).
Zero-area faces (repeated indices, repeated coordinates, collinear triples)
are produced on purpose by several kinds.

Construction: a pair is usually built in a canonical frame (size ~1, dyadic
coordinates wherever exact ties / incidences are intended) and then mapped by
ONE common placement.  A placement is either exact (signed axis permutation,
scale 2^k with 2^k in about [1e-6, 1e6], dyadic translation -- preserves all
exact incidences), a uniformly random rotation, or a rotation 1e-12..1e-2 rad
away from a signed axis permutation, with scale 10^U(-6,6).  Ulp-level
perturbations are applied after placement with math.nextafter.  Kinds whose
name ends in "_far" are nearly coincident pairs placed 1e4..1e8 times their
size away from the origin; no other kind ends in "_far".

Kinds (index = s % len(KINDS)):
  coplanar_grids          same rectangle as grids of other resolution / diagonals / centre-cross cells
  coplanar_fan_strip      convex polygon (regular, random, rectangle with collinear boundary points)
                          as vertex fan / centre fan / strip / random-diagonal triangulation
  coplanar_tjunction      rectangle with randomly refined cells (T-junctions) vs other refinement
  coplanar_partial_overlap  coplanar patches partially overlapping (dyadic shift, in-plane rotation, triangle)
  coplanar_subdiv_tri     one triangle subdivided n x n / centroid fan / midpoint split / edge fan
  near_coplanar_tilt      planar patch vs copy tilted by 1e-15..1e-3 rad about an in-plane axis
  near_coplanar_offset    planar patch vs copy offset (wholly or partly) by 1e-15..1e-3 along the normal
  near_coplanar_ulp       placed mesh vs copy / retriangulation with coordinates nudged by a few ulps
  sliver_in_face          needles (aspect 1e3..1e15, or exactly collinear) lying inside a face
  sliver_above_face       needles 1e-15..1e-6 above/below a face, flat or tilted
  sliver_standing         low walls and spikes (aspect 1e3..1e15) standing on a face
  sliver_crossing         needles piercing a face, some at grazing angles 1e-12..1e-1
  sliver_fan              fan of slivers (angular spread 1e-12..1e-2) sharing an apex vs hull / other fan
  sliver_close_corners    slivers whose corners are 1e-12..1e-7 apart, vs welded / displaced copies
  needle_pair             pairs of needles: near-parallel skew, crossing, collinear overlapping, parallel
  wall_on_face            floor plus perpendicular walls on grid lines / diagonals, touching or hovering
  thin_plate              closed box of thickness 1e-13..1e-6 vs other triangulation / mid-surface
  fin_on_edge             fins standing on edges of a triangulated square (exact or near 90 degrees)
  hinge                   two strips sharing an edge at exact/near 0, 90, 180 deg; ulp-nudged hinge
  shared_vertex           fans touching at one vertex (exact, ulp-nudged, sharing a ray, coplanar sectors)
  degenerate_mixed        clean mesh vs copy with points, segments, repeated indices, collinear faces
  degenerate_only         meshes made only of points/segments/collinear triples vs anything
  duplicate_flip_unweld   mesh vs copy with duplicated, flipped, unwelded, shuffled faces
  subset                  mesh vs a subset of its faces (random, connected patch, single face)
  refinement              mesh vs midpoint 1-to-4 / centroid 1-to-3 / partial edge bisection refinement
  decimation              fine height field / sphere / box vs coarse version on a vertex subset
  renumbered_self         mesh vs itself renumbered / cyclically rotated / mapped by an exact symmetry
  ties_mirror             planar patch midway between mirrored patches, mirrored triangles, square frame
  ties_cube_center        symmetric objects at the centre of a cube / octahedron / box (multi-way ties)
  ties_circumcenter       triangle / square vs corner points, opposite edges, or a parallel copy
  vertex_on_feature       triangles touching a grid exactly at a vertex, edge point or face point
  edge_crossing           edges crossing edges/diagonals exactly or 1e-15..1e-4 apart, X-shaped triangles
  scale_mix               tiny (1e-6) triangles on/near faces, edges, corners of a big (1e3) mesh
  crossing_planes         two patches crossing at exact 90 deg, generic, or 1e-12..1e-1 rad angles
  folded_sheet            creased height field (slope 1e-12..1) vs flat / other creased triangulation
  closed_tetra            tetrahedron vs perturbed / subdivided / symmetric / rotated copy
  closed_box              box vs retriangulated / 90-degree-rotated / scaled / jittered / dented copy
  closed_sphere           octahedral low-poly sphere vs other level / jittered / rotated copy
  nested_solids           solid vs shrunken inner copy (gap 1e-12..1e-1, or touching one face), shells
  retri_far               far from the origin: retriangulations of the same surface
  jitter_far              far from the origin: ulp-jittered or relatively jittered copies
  tinyrot_far             far from the origin: copies rotated by 1e-14..1e-4 rad about their centre
  float32_far             far from the origin: float32-rounded copies (offset 1e4..1e5 x size)
  solid_far               far from the origin: closed solids vs perturbed / retriangulated copies
"""

import math
import os
import random
import struct
import sys

MAX_TRIS = 300

# ---------------------------------------------------------------------------
# small vector helpers (tuples of 3 floats)
# ---------------------------------------------------------------------------


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vmul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def vlen(a):
    return math.sqrt(vdot(a, a))


def vunit(a):
    n = vlen(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def lerp(a, b, t):
    """(1-t)*a + t*b; exact endpoints for t in {0, 1}."""
    u = 1.0 - t
    return (u * a[0] + t * b[0], u * a[1] + t * b[1], u * a[2] + t * b[2])


def vmid(a, b):
    return ((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5)


def P(x, y, z=0.0):
    return (float(x), float(y), float(z))


def matvec(R, p):
    return (R[0][0] * p[0] + R[0][1] * p[1] + R[0][2] * p[2],
            R[1][0] * p[0] + R[1][1] * p[1] + R[1][2] * p[2],
            R[2][0] * p[0] + R[2][1] * p[1] + R[2][2] * p[2])


def matmul(A, B):
    return tuple(tuple(sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3))
                 for i in range(3))


def rand_unit(rng):
    while True:
        v = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        n = vlen(v)
        if n > 1e-6:
            return (v[0] / n, v[1] / n, v[2] / n)


def rand_rotation(rng):
    """Uniformly random rotation matrix (Shoemake quaternion)."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1.0 - u1), math.sqrt(u1)
    w = a * math.sin(2 * math.pi * u2)
    x = a * math.cos(2 * math.pi * u2)
    y = b * math.sin(2 * math.pi * u3)
    z = b * math.cos(2 * math.pi * u3)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def axis_rotation(axis, theta):
    """Rodrigues rotation; 1-cos computed as 2 sin^2 for tiny angles."""
    x, y, z = vunit(axis)
    c, s = math.cos(theta), math.sin(theta)
    C = 2.0 * math.sin(0.5 * theta) ** 2
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def signed_perm(rng, even_signs=False):
    """Random signed permutation matrix; returns (matrix, determinant)."""
    perm = rng.sample(range(3), 3)
    signs = [rng.choice((-1.0, 1.0)) for _ in range(3)]
    if even_signs and signs[0] * signs[1] * signs[2] < 0:
        signs[rng.randrange(3)] *= -1.0
    M = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        M[i][perm[i]] = signs[i]
    inv = sum(1 for i in range(3) for j in range(i + 1, 3) if perm[i] > perm[j])
    det = (-1.0 if inv % 2 else 1.0) * signs[0] * signs[1] * signs[2]
    return tuple(tuple(r) for r in M), det


def logu(rng, lo, hi):
    return 10.0 ** rng.uniform(lo, hi)


def sgn(rng):
    return rng.choice((-1.0, 1.0))


def nudge(x, k):
    """Move x by |k| ulps (towards +inf if k > 0)."""
    d = math.inf if k > 0 else -math.inf
    for _ in range(abs(k)):
        x = math.nextafter(x, d)
    return x


def nudge_point(p, rng, kmax):
    return tuple(nudge(c, rng.randint(-kmax, kmax)) for c in p)


def to_f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


# ---------------------------------------------------------------------------
# mesh helpers: a mesh is (list of vertex tuples, list of (i, j, k) tuples)
# ---------------------------------------------------------------------------


def tri_mesh(a, b, c):
    return ([a, b, c], [(0, 1, 2)])


def merge(*ms):
    V, F = [], []
    for mv, mf in ms:
        o = len(V)
        V.extend(mv)
        F.extend((a + o, b + o, c + o) for a, b, c in mf)
    return (V, F)


def mapm(m, fn):
    return ([fn(p) for p in m[0]], list(m[1]))


def translate(m, t):
    return mapm(m, lambda p: vadd(p, t))


def flip(m):
    return (list(m[0]), [(a, c, b) for a, b, c in m[1]])


def rotate_mesh(m, R, c=(0.0, 0.0, 0.0)):
    return mapm(m, lambda p: vadd(c, matvec(R, vsub(p, c))))


def weld(m):
    """Merge vertices with bit-identical coordinates (treating -0.0 == 0.0)."""
    V, F = m
    key2i, remap, NV = {}, [], []
    for p in V:
        k = (p[0] + 0.0, p[1] + 0.0, p[2] + 0.0)
        if k not in key2i:
            key2i[k] = len(NV)
            NV.append(p)
        remap.append(key2i[k])
    return (NV, [(remap[a], remap[b], remap[c]) for a, b, c in F])


def unweld(m):
    V, F = m
    NV, NF = [], []
    for f in F:
        NF.append((len(NV), len(NV) + 1, len(NV) + 2))
        NV.extend(V[i] for i in f)
    return (NV, NF)


def shuffle_mesh(m, rng, rotate=True):
    V, F = m
    n = len(V)
    perm = list(range(n))
    rng.shuffle(perm)
    NV = [None] * n
    for i in range(n):
        NV[perm[i]] = V[i]
    NF = []
    for f in F:
        g = tuple(perm[i] for i in f)
        if rotate:
            r = rng.randrange(3)
            g = g[r:] + g[:r]
        NF.append(g)
    rng.shuffle(NF)
    return (NV, NF)


def subdivide4(m, proj=None):
    V = list(m[0])
    cache = {}

    def midx(a, b):
        key = (min(a, b), max(a, b))
        if key not in cache:
            p = vmid(V[key[0]], V[key[1]])
            if proj is not None:
                p = proj(p)
            cache[key] = len(V)
            V.append(p)
        return cache[key]

    F = []
    for a, b, c in m[1]:
        ab, bc, ca = midx(a, b), midx(b, c), midx(c, a)
        F += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return (V, F)


def subdivide3(m):
    V = list(m[0])
    F = []
    for a, b, c in m[1]:
        pa, pb, pc = V[a], V[b], V[c]
        g = tuple((pa[i] + pb[i] + pc[i]) / 3.0 for i in range(3))
        V.append(g)
        gi = len(V) - 1
        F += [(a, b, gi), (b, c, gi), (c, a, gi)]
    return (V, F)


def bisect_some(m, rng, prob):
    """Split a random edge of some faces at its midpoint (creates T-junctions)."""
    V = list(m[0])
    F = []
    for f in m[1]:
        if rng.random() < prob:
            r = rng.randrange(3)
            a, b, c = f[r:] + f[:r]
            V.append(vmid(V[a], V[b]))
            mi = len(V) - 1
            F += [(a, mi, c), (mi, b, c)]
        else:
            F.append(f)
    return (V, F)


def edges_of(m):
    es = set()
    for f in m[1]:
        for k in range(3):
            a, b = f[k], f[(k + 1) % 3]
            if a != b:
                es.add((min(a, b), max(a, b)))
    return sorted(es)


def bbox(m):
    V = m[0]
    lo = tuple(min(p[i] for p in V) for i in range(3))
    hi = tuple(max(p[i] for p in V) for i in range(3))
    return lo, hi


def bbox_size(m):
    lo, hi = bbox(m)
    return max(vlen(vsub(hi, lo)), 1e-300)


def bbox_center(m):
    lo, hi = bbox(m)
    return vmid(lo, hi)


def face_normal(V, f):
    a, b, c = V[f[0]], V[f[1]], V[f[2]]
    return vcross(vsub(b, a), vsub(c, a))


def orient_outward(m, center):
    V, F = m
    NF = []
    for f in F:
        a, b, c = (V[i] for i in f)
        g = tuple((a[i] + b[i] + c[i]) / 3.0 for i in range(3))
        if vdot(face_normal(V, f), vsub(g, center)) < 0:
            f = (f[0], f[2], f[1])
        NF.append(f)
    return (list(V), NF)


# ---------------------------------------------------------------------------
# canonical shapes
# ---------------------------------------------------------------------------

DIAGS = ('a', 'b', 'alt', 'rand')
DYW = (1.0, 1.0, 0.5, 0.75, 1.5, 2.0, 1.25, 3.0)


def grid(nx, ny, W=1.0, H=1.0, diag='a', rng=None, x0=0.0, y0=0.0, z=0.0,
         zf=None, keep=None):
    """Rectangle [x0,x0+W]x[y0,y0+H] in plane z (or height field zf), CCW (+z)."""
    V = []
    for j in range(ny + 1):
        y = y0 + H * j / ny
        for i in range(nx + 1):
            x = x0 + W * i / nx
            V.append((x, y, zf(i, j, x, y) if zf else z))

    def idx(i, j):
        return j * (nx + 1) + i

    F = []
    for j in range(ny):
        for i in range(nx):
            if keep is not None and not keep(i, j):
                continue
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            if diag == 'a':
                dd = 0
            elif diag == 'b':
                dd = 1
            elif diag == 'alt':
                dd = (i + j) % 2
            else:
                dd = rng.randint(0, 1)
            if dd == 0:
                F += [(a, b, c), (a, c, d)]
            else:
                F += [(a, b, d), (b, c, d)]
    return (V, F)


def grid_cross(nx, ny, W=1.0, H=1.0):
    """Each cell split into 4 triangles around its centre."""
    V = []
    for j in range(ny + 1):
        for i in range(nx + 1):
            V.append((W * i / nx, H * j / ny, 0.0))

    def idx(i, j):
        return j * (nx + 1) + i

    F = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            V.append(vmid(V[a], V[c]))
            m = len(V) - 1
            F += [(a, b, m), (b, c, m), (c, d, m), (d, a, m)]
    return (V, F)


def tj_grid(rng, W, H, prob):
    """n x n cells on a k-times finer lattice; refined cells create T-junctions."""
    n = rng.randint(1, 4)
    k = rng.choice((2, 2, 3)) if n <= 3 else 2
    N = n * k
    ids, V, F = {}, [], []

    def vid(I, J):
        if (I, J) not in ids:
            ids[(I, J)] = len(V)
            V.append((W * I / N, H * J / N, 0.0))
        return ids[(I, J)]

    def quad(a, b, c, d):
        if rng.random() < 0.5:
            F.extend([(a, b, c), (a, c, d)])
        else:
            F.extend([(a, b, d), (b, c, d)])

    for j in range(n):
        for i in range(n):
            if rng.random() < prob:
                for bb in range(k):
                    for aa in range(k):
                        I, J = i * k + aa, j * k + bb
                        quad(vid(I, J), vid(I + 1, J), vid(I + 1, J + 1), vid(I, J + 1))
            else:
                I, J = i * k, j * k
                quad(vid(I, J), vid(I + k, J), vid(I + k, J + k), vid(I, J + k))
    return (V, F)


def rect_polygon(rng, W, H):
    """CCW rectangle boundary with extra (collinear) points at lattice positions."""
    def side_params():
        m = rng.choice((1, 2, 3, 4, 8))
        return [t / m for t in range(1, m) if rng.random() < 0.6]

    pts = [(0.0, 0.0, 0.0)]
    pts += [(W * t, 0.0, 0.0) for t in side_params()]
    pts.append((W, 0.0, 0.0))
    pts += [(W, H * t, 0.0) for t in side_params()]
    pts.append((W, H, 0.0))
    pts += [(W * (1.0 - t), H, 0.0) for t in side_params()]
    pts.append((0.0, H, 0.0))
    pts += [(0.0, H * (1.0 - t), 0.0) for t in side_params()]
    return pts


def poly_tri(Pts, rng, center, method=None, drop_flat=None):
    """Triangulate a convex CCW polygon."""
    n = len(Pts)
    V = list(Pts)
    F = []
    method = method or rng.choice(('fan', 'center', 'strip', 'random'))
    if method == 'fan':
        k = rng.randrange(n)
        F = [(k, (k + i) % n, (k + i + 1) % n) for i in range(1, n - 1)]
    elif method == 'center':
        V.append(center)
        F = [(n, i, (i + 1) % n) for i in range(n)]
    elif method == 'strip':
        r0 = rng.randrange(n)
        i, j, tog = 0, n - 1, True
        while j - i > 1:
            if tog:
                F.append(((i + r0) % n, (i + 1 + r0) % n, (j + r0) % n))
                i += 1
            else:
                F.append(((i + r0) % n, (j - 1 + r0) % n, (j + r0) % n))
                j -= 1
            tog = not tog
    else:
        def split(idx):
            if len(idx) < 3:
                return
            if len(idx) == 3:
                F.append(tuple(idx))
                return
            L = len(idx)
            a = rng.randrange(L)
            b = (a + rng.randint(2, L - 2)) % L
            if a > b:
                a, b = b, a
            split(idx[a:b + 1])
            split(idx[b:] + idx[:a + 1])
        split(list(range(n)))
    if drop_flat is None:
        drop_flat = rng.random() < 0.8
    if drop_flat:
        keep = [f for f in F if face_normal(V, f)[2] != 0.0]
        if keep:
            F = keep
    return (V, F)


def tri_subdiv(P0, P1, P2, n):
    """Triangle split into n*n triangles by barycentric lattice (CCW kept)."""
    V, idx = [], {}
    for j in range(n + 1):
        for i in range(n + 1 - j):
            w0, w1, w2 = (n - i - j) / n, i / n, j / n
            idx[(i, j)] = len(V)
            V.append(tuple(w0 * P0[k] + w1 * P1[k] + w2 * P2[k] for k in range(3)))
    F = []
    for j in range(n):
        for i in range(n - j):
            F.append((idx[(i, j)], idx[(i + 1, j)], idx[(i, j + 1)]))
            if i + j + 2 <= n:
                F.append((idx[(i + 1, j)], idx[(i + 1, j + 1)], idx[(i, j + 1)]))
    return (V, F)


def fan(apex, rim):
    V = [apex] + list(rim)
    return (V, [(0, i, i + 1) for i in range(1, len(rim))])


def box(lo, hi, n=1, diag='a', rng=None):
    """Closed box, each face an n x n grid, outward orientation, welded."""
    parts = []
    for a in range(3):
        b, c = (a + 1) % 3, (a + 2) % 3
        for s in (-1, 1):
            g = grid(n, n, 1.0, 1.0, diag, rng)

            def mp(p, a=a, b=b, c=c, s=s):
                q = [0.0, 0.0, 0.0]
                q[a] = hi[a] if s > 0 else lo[a]
                q[b] = (1.0 - p[0]) * lo[b] + p[0] * hi[b]
                q[c] = (1.0 - p[1]) * lo[c] + p[1] * hi[c]
                return tuple(q)
            face = mapm(g, mp)
            parts.append(face if s > 0 else flip(face))
    return weld(merge(*parts))


def sphere(level):
    """Octahedron (level 0) subdivided 'level' times, projected to the unit sphere."""
    V = [P(1, 0, 0), P(-1, 0, 0), P(0, 1, 0), P(0, -1, 0), P(0, 0, 1), P(0, 0, -1)]
    F = []
    for X in (0, 1):
        for Y in (2, 3):
            for Z in (4, 5):
                s = (1 if X == 0 else -1) * (1 if Y == 2 else -1) * (1 if Z == 4 else -1)
                F.append((X, Y, Z) if s > 0 else (X, Z, Y))
    m = (V, F)
    for _ in range(level):
        m = subdivide4(m, proj=vunit)
    return m


def tetra_mesh(rng, kind=None):
    kind = kind or rng.choice(('regular', 'corner', 'random'))
    if kind == 'regular':
        V = [P(1, 1, 1), P(1, -1, -1), P(-1, 1, -1), P(-1, -1, 1)]
    elif kind == 'corner':
        V = [P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(0, 0, 1)]
    else:
        while True:
            V = [tuple(rng.uniform(-1, 1) for _ in range(3)) for _ in range(4)]
            vol = vdot(vsub(V[1], V[0]), vcross(vsub(V[2], V[0]), vsub(V[3], V[0])))
            if abs(vol) > 0.05:
                break
    c = tuple(sum(p[i] for p in V) / 4.0 for i in range(3))
    return orient_outward((V, [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]), c)


def heightfield_rand(rng, nx=None, ny=None, diag=None):
    nx = nx or rng.randint(2, 7)
    ny = ny or rng.randint(2, 7)
    diag = diag or rng.choice(DIAGS)
    mode = rng.randrange(4)
    if mode == 0:
        table = {}
        for j in range(ny + 1):
            for i in range(nx + 1):
                table[(i, j)] = rng.randint(-8, 8) / 16.0

        def zf(i, j, x, y):
            return table[(i, j)]
    elif mode == 1:
        fx, fy, amp = rng.randint(1, 3), rng.randint(1, 3), rng.uniform(0.05, 0.5)

        def zf(i, j, x, y):
            return amp * math.sin(2 * math.pi * fx * x) * math.cos(2 * math.pi * fy * y)
    elif mode == 2:
        def zf(i, j, x, y):
            return (x - 0.5) ** 2 - (y - 0.5) ** 2
    else:
        cx, sl = rng.choice((0.5, 0.25, rng.random())), rng.choice((1.0, 0.5, logu(rng, -6, 0)))

        def zf(i, j, x, y):
            return abs(x - cx) * sl
    return grid(nx, ny, 1.0, 1.0, diag, rng, zf=zf)


def planar_patch(rng, W=1.0, H=1.0):
    """Some triangulation of the rectangle [0,W]x[0,H] in plane z=0."""
    r = rng.randrange(5)
    if r == 0:
        return grid(rng.randint(1, 7), rng.randint(1, 7), W, H, rng.choice(DIAGS), rng)
    if r == 1:
        return grid_cross(rng.randint(1, 5), rng.randint(1, 5), W, H)
    if r == 2:
        return tj_grid(rng, W, H, rng.uniform(0.2, 0.8))
    if r == 3:
        return poly_tri(rect_polygon(rng, W, H), rng, (W * 0.5, H * 0.5, 0.0))
    k = 2 ** rng.randint(0, 3)
    return grid(k, k, W, H, rng.choice(DIAGS), rng)


def random_polygon(rng):
    r = rng.random()
    if r < 0.4:
        n = rng.randint(4, 40)
        pts = [(math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n), 0.0) for i in range(n)]
        return pts, (0.0, 0.0, 0.0)
    if r < 0.7:
        n = rng.randint(3, 30)
        angs = sorted(set(rng.uniform(0, 2 * math.pi) for _ in range(n)))
        pts = [(math.cos(a), math.sin(a), 0.0) for a in angs]
        if len(pts) < 3:
            pts = [P(1, 0), P(-0.5, 0.75), P(-0.5, -0.75)]
        c = tuple(sum(p[i] for p in pts) / len(pts) for i in range(3))
        return pts, c
    W, H = rng.choice(DYW), rng.choice(DYW)
    return rect_polygon(rng, W, H), (W * 0.5, H * 0.5, 0.0)


def base_mesh(rng, maxf=120, closed=None):
    """A random 'ordinary' mesh in a canonical frame."""
    for _ in range(50):
        if closed is None:
            r = rng.randrange(8)
        elif closed:
            r = rng.choice((2, 3, 4))
        else:
            r = rng.choice((0, 1, 5, 6, 7))
        if r == 0:
            m = grid(rng.randint(1, 7), rng.randint(1, 7), rng.choice(DYW), rng.choice(DYW),
                     rng.choice(DIAGS), rng)
        elif r == 1:
            m = heightfield_rand(rng)
        elif r == 2:
            hi = (rng.choice(DYW), rng.choice(DYW), rng.choice(DYW))
            m = box((0.0, 0.0, 0.0), hi, rng.randint(1, 3), rng.choice(DIAGS), rng)
        elif r == 3:
            m = sphere(rng.choice((0, 1, 1, 2)))
        elif r == 4:
            m = tetra_mesh(rng)
            if rng.random() < 0.4:
                m = weld(subdivide4(m))
        elif r == 5:
            pts, c = random_polygon(rng)
            m = poly_tri(pts, rng, c)
        elif r == 6:
            Q = [tuple(rng.uniform(-1, 1) for _ in range(3)) for _ in range(3)]
            m = tri_subdiv(Q[0], Q[1], Q[2], rng.randint(1, 8))
        else:
            m = grid_cross(rng.randint(1, 5), rng.randint(1, 5), rng.choice(DYW), rng.choice(DYW))
        if len(m[1]) <= maxf:
            return m
    return tetra_mesh(rng)


def frame_mesh(rng, n, hole):
    """[-1,1]^2 as n x n cells with a central hole x hole block of cells removed."""
    lo = (n - hole) // 2
    return grid(n, n, 2.0, 2.0, rng.choice(DIAGS), rng, x0=-1.0, y0=-1.0,
                keep=lambda i, j: not (lo <= i < lo + hole and lo <= j < lo + hole))


# ---------------------------------------------------------------------------
# placement
# ---------------------------------------------------------------------------


def place(rng, mode=None, far=False, far_exp=(4.27, 7.98), size=1.0, logscale=(-6.0, 6.0)):
    """Return (f, s): a common similarity map and its scale.

    With far=True the translation has length 10^U(far_exp) * size * s; the
    lower bound 10^4.27 > sqrt(3) * 1e4 keeps the distance above 1e4 times the
    bounding-box diagonal even after rotation (the mesh must be centred)."""
    if mode is None:
        mode = rng.choice(('exact', 'exact', 'rot', 'rot', 'nearaxis'))
    lo, hi = logscale
    if mode == 'exact':
        k = rng.randint(int(math.floor(lo * 3.3219)), int(math.ceil(hi * 3.3219)))
        s = math.ldexp(1.0, k)
        M, _ = signed_perm(rng)
    else:
        if mode == 'rot':
            M = rand_rotation(rng)
        else:
            M = matmul(signed_perm(rng)[0], axis_rotation(rand_unit(rng), logu(rng, -12, -2)))
        s = 10.0 ** rng.uniform(lo, hi)
    if far:
        F = 10.0 ** rng.uniform(*far_exp) * size * s
        r = rng.random()
        if r < 0.5:
            d = rand_unit(rng)
        elif r < 0.75:
            d = [0.0, 0.0, 0.0]
            d[rng.randrange(3)] = sgn(rng)
        else:
            d = vmul((sgn(rng), sgn(rng), sgn(rng)), 1.0 / math.sqrt(3.0))
        t = vmul(d, F)
        if mode == 'exact':
            t = tuple(s * float(round(x / s)) for x in t)
    else:
        r = rng.random()
        if r < 0.4:
            t = (0.0, 0.0, 0.0)
        elif mode == 'exact':
            t = tuple(s * rng.randint(-64, 64) / 8.0 for _ in range(3))
        else:
            t = vmul(rand_unit(rng), s * 10.0 ** rng.uniform(-1, 2.5))

    def f(p):
        q = matvec(M, p)
        return (q[0] * s + t[0], q[1] * s + t[1], q[2] * s + t[2])
    return f, s


def far_center(A, B):
    """Translate a pair so that the bbox centre of A is at the origin (before a far placement)."""
    c = vmul(bbox_center(A), -1.0)
    return translate(A, c), translate(B, c)


def placed(rng, A, B, **kw):
    f, _ = place(rng, **kw)
    return mapm(A, f), mapm(B, f)


def maybe_swap(rng, A, B, prob=0.5):
    return (B, A) if rng.random() < prob else (A, B)


# ---------------------------------------------------------------------------
# kinds
# ---------------------------------------------------------------------------

KIND_LIST = []


def kind(name, desc):
    def deco(fn):
        KIND_LIST.append((name, fn, desc))
        return fn
    return deco


@kind('coplanar_grids', 'same rectangle as grids of other resolution / diagonals / centre-cross cells')
def k_coplanar_grids(rng):
    W, H = rng.choice(DYW), rng.choice(DYW)

    def one():
        r = rng.random()
        if r < 0.4:
            return grid(rng.randint(1, 7), rng.randint(1, 7), W, H, rng.choice(DIAGS), rng)
        if r < 0.7:
            return grid(2 ** rng.randint(0, 3), 2 ** rng.randint(0, 3), W, H, rng.choice(DIAGS), rng)
        return grid_cross(rng.randint(1, 5), rng.randint(1, 5), W, H)
    A, B = one(), one()
    if rng.random() < 0.25:
        B = flip(B)
    if rng.random() < 0.2:
        B = shuffle_mesh(B, rng)
    return placed(rng, A, B)


@kind('coplanar_fan_strip', 'convex polygon as vertex fan / centre fan / strip / random diagonals')
def k_coplanar_fan_strip(rng):
    pts, c = random_polygon(rng)
    A = poly_tri(pts, rng, c)
    B = poly_tri(pts, rng, c)
    return placed(rng, A, B)


@kind('coplanar_tjunction', 'rectangle with randomly refined cells (T-junctions) vs other refinement')
def k_coplanar_tjunction(rng):
    W, H = rng.choice(DYW), rng.choice(DYW)
    A = tj_grid(rng, W, H, rng.choice((0.0, 0.0, rng.uniform(0.1, 0.9))))
    B = tj_grid(rng, W, H, rng.uniform(0.15, 0.85))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('coplanar_partial_overlap', 'coplanar patches partially overlapping')
def k_coplanar_partial_overlap(rng):
    A = grid(rng.randint(1, 6), rng.randint(1, 6), 1.0, 1.0, rng.choice(DIAGS), rng)
    r = rng.random()
    if r < 0.45:
        dx, dy = rng.randint(-6, 6) / 8.0, rng.randint(-6, 6) / 8.0
        if rng.random() < 0.3:
            dy = 0.0
        B = grid(rng.randint(1, 6), rng.randint(1, 6), rng.choice(DYW), rng.choice(DYW),
                 rng.choice(DIAGS), rng, x0=dx, y0=dy)
    elif r < 0.75:
        B = grid(rng.randint(1, 6), rng.randint(1, 6), 1.0, 1.0, rng.choice(DIAGS), rng)
        ang = rng.choice((rng.uniform(0, 2 * math.pi), sgn(rng) * logu(rng, -12, -1)))
        cx, cy = rng.choice(((0.5, 0.5), (0.0, 0.0), (1.0, 0.0), (rng.random(), rng.random())))
        ca, sa = math.cos(ang), math.sin(ang)
        B = mapm(B, lambda p: (cx + ca * (p[0] - cx) - sa * (p[1] - cy),
                               cy + sa * (p[0] - cx) + ca * (p[1] - cy), 0.0))
    else:
        while True:
            Q = [(rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 1.5), 0.0) for _ in range(3)]
            if abs(face_normal(Q, (0, 1, 2))[2]) > 0.05:
                break
        if face_normal(Q, (0, 1, 2))[2] < 0:
            Q = [Q[0], Q[2], Q[1]]
        B = tri_subdiv(Q[0], Q[1], Q[2], rng.randint(1, 6))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('coplanar_subdiv_tri', 'one triangle subdivided n x n / centroid fan / midpoint split / edge fan')
def k_coplanar_subdiv_tri(rng):
    r = rng.random()
    if r < 0.4:
        a, b = rng.choice(DYW), rng.choice(DYW)
        T = (P(0, 0), P(a, 0), P(0, b))
    elif r < 0.7:
        while True:
            T = tuple((rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0) for _ in range(3))
            if abs(face_normal(T, (0, 1, 2))[2]) > 0.02:
                break
    else:
        T = tuple(tuple(rng.uniform(-1, 1) for _ in range(3)) for _ in range(3))

    def one():
        c = rng.randrange(6)
        single = tri_mesh(*T)
        if c == 0:
            return tri_subdiv(T[0], T[1], T[2], rng.randint(1, 8))
        if c == 1:
            return subdivide3(single)
        if c == 2:
            m = subdivide4(single)
            return subdivide4(m) if rng.random() < 0.5 else m
        if c == 3:
            w = [rng.randint(1, 8) for _ in range(3)]
            s = float(sum(w))
            q = tuple((w[0] * T[0][i] + w[1] * T[1][i] + w[2] * T[2][i]) / s for i in range(3))
            return ([T[0], T[1], T[2], q], [(0, 1, 3), (1, 2, 3), (2, 0, 3)])
        if c == 4:
            k = rng.randint(2, 30)
            rim = [lerp(T[1], T[2], i / k) for i in range(k + 1)]
            return fan(T[0], rim)
        return single
    return placed(rng, one(), one())


@kind('near_coplanar_tilt', 'planar patch vs copy tilted by 1e-15..1e-3 rad about an in-plane axis')
def k_near_coplanar_tilt(rng):
    W, H = rng.choice(DYW), rng.choice(DYW)
    A = planar_patch(rng, W, H)
    B = planar_patch(rng, W, H) if rng.random() < 0.6 else (list(A[0]), list(A[1]))
    theta = sgn(rng) * logu(rng, -15, -3)
    ax = rng.choice(((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), vunit((W, H, 0.0)),
                     (math.cos(rng.random() * 6.3), math.sin(rng.random() * 6.3), 0.0)))
    c = rng.choice(((0.0, 0.0, 0.0), (W * 0.5, H * 0.5, 0.0), (W * 0.5, 0.0, 0.0),
                    (rng.uniform(0, W), rng.uniform(0, H), 0.0)))
    B = rotate_mesh(B, axis_rotation(ax, theta), c)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('near_coplanar_offset', 'planar patch vs copy offset by 1e-15..1e-3 along the normal')
def k_near_coplanar_offset(rng):
    W, H = rng.choice(DYW), rng.choice(DYW)
    A = planar_patch(rng, W, H)
    B = planar_patch(rng, W, H) if rng.random() < 0.6 else (list(A[0]), list(A[1]))
    delta = sgn(rng) * logu(rng, -15, -3)
    r = rng.random()
    if r < 0.35:
        B = translate(B, (0.0, 0.0, delta))
        return placed(rng, *maybe_swap(rng, A, B))
    if r < 0.6:
        sel = [rng.random() < 0.4 for _ in B[0]]
        B = ([(p[0], p[1], p[2] + delta) if s else p for p, s in zip(B[0], sel)], B[1])
        return placed(rng, *maybe_swap(rng, A, B))
    f, s = place(rng)
    A2, B2 = mapm(A, f), mapm(B, f)
    o = f((0.0, 0.0, 0.0))
    nrm = vunit(vcross(vsub(f((1.0, 0.0, 0.0)), o), vsub(f((0.0, 1.0, 0.0)), o)))
    B2 = translate(B2, vmul(nrm, delta * s))
    return maybe_swap(rng, A2, B2)


@kind('near_coplanar_ulp', 'placed mesh vs copy / retriangulation nudged by a few ulps')
def k_near_coplanar_ulp(rng):
    if rng.random() < 0.7:
        W, H = rng.choice(DYW), rng.choice(DYW)
        A = planar_patch(rng, W, H)
        B = planar_patch(rng, W, H) if rng.random() < 0.5 else (list(A[0]), list(A[1]))
    else:
        A = base_mesh(rng)
        B = (list(A[0]), list(A[1]))
    f, _ = place(rng, mode=rng.choice(('rot', 'rot', 'nearaxis', 'exact')))
    A, B = mapm(A, f), mapm(B, f)
    kmax = rng.choice((1, 1, 2, 4))
    r = rng.random()
    if r < 0.4:
        B = mapm(B, lambda p: nudge_point(p, rng, kmax))
    elif r < 0.6:
        ax = rng.randrange(3)
        B = mapm(B, lambda p: tuple(nudge(c, rng.randint(-kmax, kmax)) if i == ax else c
                                    for i, c in enumerate(p)))
    elif r < 0.8:
        B = mapm(B, lambda p: nudge_point(p, rng, kmax) if rng.random() < 0.3 else p)
    else:
        d = rng.choice((-1, 1)) * kmax
        B = mapm(B, lambda p: tuple(nudge(c, d) for c in p))
    if rng.random() < 0.3:
        A = mapm(A, lambda p: nudge_point(p, rng, 1))
    return A, B


def floor_grid(rng):
    n = rng.choice((1, 2, 2, 3, 4, 4))
    return grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng), n


def rpt2(rng):
    if rng.random() < 0.5:
        return (rng.randint(1, 63) / 64.0, rng.randint(1, 63) / 64.0, 0.0)
    return (rng.uniform(0.02, 0.98), rng.uniform(0.02, 0.98), 0.0)


def needle_tri(rng, p, q, w, perp):
    t = rng.choice((0.5, rng.random(), rng.uniform(-0.5, 1.5), 0.0, 1.0))
    return (p, q, vadd(lerp(p, q, t), vmul(perp, w)))


def in_plane_needles(rng, n, count):
    out = []
    for _ in range(count):
        r = rng.random()
        if r < 0.5:
            p, q = rpt2(rng), rpt2(rng)
        elif r < 0.75:
            c = rng.randint(0, n) / n
            a, b = sorted((rng.random(), rng.random()))
            p, q = (a, c, 0.0), (b, c, 0.0)
            if rng.random() < 0.5:
                p, q = (c, a, 0.0), (c, b, 0.0)
        else:
            p = (rng.randint(0, n) / n, rng.randint(0, n) / n, 0.0)
            q = rpt2(rng)
        d = vsub(q, p)
        L = vlen(d)
        if L < 1e-3:
            continue
        perp = (-d[1] / L, d[0] / L, 0.0)
        w = 0.0 if rng.random() < 0.15 else L * 10.0 ** -rng.uniform(3, 15)
        out.append(needle_tri(rng, p, q, w, perp))
    if not out:
        out.append((P(0.25, 0.25), P(0.75, 0.25), P(0.5, 0.25 + 1e-9)))
    return out


@kind('sliver_in_face', 'needles (aspect 1e3..1e15 or collinear) lying inside a face')
def k_sliver_in_face(rng):
    A, n = floor_grid(rng)
    B = merge(*[tri_mesh(*t) for t in in_plane_needles(rng, n, rng.randint(1, 10))])
    if rng.random() < 0.35:
        B = merge(B, A if rng.random() < 0.5 else planar_patch(rng))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('sliver_above_face', 'needles 1e-15..1e-6 above/below a face, flat or tilted')
def k_sliver_above_face(rng):
    A, n = floor_grid(rng)
    parts = []
    for (p, q, c) in in_plane_needles(rng, n, rng.randint(1, 10)):
        h = sgn(rng) * logu(rng, -15, -6)
        r = rng.randrange(4)
        if r == 0:
            p, q, c = (p[0], p[1], h), (q[0], q[1], h), (c[0], c[1], h)
        elif r == 1:
            c = (c[0], c[1], h)
        elif r == 2:
            q = (q[0], q[1], h)
        else:
            p, q, c = (p[0], p[1], h), (q[0], q[1], -h), (c[0], c[1], h)
        parts.append(tri_mesh(p, q, c))
    B = merge(*parts)
    if rng.random() < 0.25:
        B = merge(B, A)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('sliver_standing', 'low walls and spikes (aspect 1e3..1e15) standing on a face')
def k_sliver_standing(rng):
    A, n = floor_grid(rng)
    parts = []
    for _ in range(rng.randint(1, 8)):
        r = rng.random()
        if r < 0.4:    # long low wall
            if rng.random() < 0.5:
                c = rng.randint(0, n) / n
                a, b = sorted((rng.random(), rng.random()))
                p, q = (a, c, 0.0), (b, c, 0.0)
            else:
                p, q = rpt2(rng), rpt2(rng)
            L = vlen(vsub(q, p))
            if L < 1e-3:
                continue
            Hh = sgn(rng) * L * 10.0 ** -rng.uniform(3, 15)
            m = lerp(p, q, rng.choice((0.5, rng.random())))
            parts.append(tri_mesh(p, q, (m[0], m[1], Hh)))
        else:          # spike: tiny base, tall apex
            p = rpt2(rng) if rng.random() < 0.6 else (rng.randint(0, n) / n, rng.randint(0, n) / n, 0.0)
            Hs = sgn(rng) * rng.uniform(0.05, 1.0)
            eps = abs(Hs) * 10.0 ** -rng.uniform(3, 15)
            ang = rng.random() * 2 * math.pi
            q = (p[0] + eps * math.cos(ang), p[1] + eps * math.sin(ang), 0.0)
            apex = (p[0], p[1], Hs)
            if rng.random() < 0.3:
                apex = (p[0] + rng.uniform(-0.1, 0.1), p[1], Hs)
            parts.append(tri_mesh(p, q, apex))
    if not parts:
        parts.append(tri_mesh(P(0.5, 0.5), P(0.5 + 1e-12, 0.5), P(0.5, 0.5, 0.5)))
    B = merge(*parts)
    if rng.random() < 0.3:
        B = merge(B, A)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('sliver_crossing', 'needles piercing a face, some at grazing angles')
def k_sliver_crossing(rng):
    A, n = floor_grid(rng)
    parts = []
    for _ in range(rng.randint(1, 8)):
        r = rng.random()
        if r < 0.4:
            c = rpt2(rng)
        elif r < 0.7:
            c = (rng.randint(0, n) / n, rng.randint(0, n) / n, 0.0)
        else:
            c = (rng.randint(0, 4 * n) / (4 * n), rng.randint(0, n) / n, 0.0)
        ang = rng.random() * 2 * math.pi
        if rng.random() < 0.5:
            psi = logu(rng, -12, -1)
        else:
            psi = rng.uniform(0.1, math.pi / 2)
        d = (math.cos(ang) * math.cos(psi), math.sin(ang) * math.cos(psi), math.sin(psi))
        if rng.random() < 0.2:
            d = (0.0, 0.0, 1.0)
        L = rng.uniform(0.1, 0.8)
        u = rng.choice((0.5, rng.random()))
        p, q = vsub(c, vmul(d, L * u)), vadd(c, vmul(d, L * (1 - u)))
        perp = vunit(vcross(d, rand_unit(rng)))
        w = 0.0 if rng.random() < 0.15 else L * 10.0 ** -rng.uniform(3, 15)
        parts.append(tri_mesh(*needle_tri(rng, p, q, w, perp)))
    B = merge(*parts)
    if rng.random() < 0.25:
        B = merge(B, A)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('sliver_fan', 'fan of slivers sharing an apex vs hull triangle / other fan')
def k_sliver_fan(rng):
    k = rng.randint(2, 24)
    spread = logu(rng, -12, -2)
    th0 = rng.choice((0.0, rng.uniform(0, 2 * math.pi)))
    apex = (0.0, 0.0, 0.0)

    def arc(kk):
        return [(math.cos(th0 + spread * i / kk), math.sin(th0 + spread * i / kk), 0.0)
                for i in range(kk + 1)]
    rim = arc(k)
    r = rng.random()
    if r < 0.3:
        A, B = fan(apex, rim), fan(apex, arc(rng.randint(1, 24)))
    elif r < 0.55:
        chord = [lerp(rim[0], rim[-1], i / k) for i in range(k + 1)]
        A, B = fan(apex, chord), tri_mesh(apex, rim[0], rim[-1])
    elif r < 0.75:
        A = fan(apex, rim)
        eps = logu(rng, -15, -6)
        ap2 = rng.choice(((0.0, 0.0, eps), (eps, 0.0, 0.0), (-eps, eps, 0.0)))
        B = fan(ap2, rim)
    else:
        A = fan(apex, rim)
        big = [vmul(rim[0], 2.0), vmul(rim[-1], 2.0)]
        B = tri_mesh(apex, big[0], big[1]) if rng.random() < 0.5 else \
            merge(fan(apex, rim), tri_mesh(apex, big[0], big[1]))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('sliver_close_corners', 'slivers whose corners are 1e-12..1e-7 apart vs welded/displaced copies')
def k_sliver_close_corners(rng):
    eps = logu(rng, -12, -7)
    r = rng.random()
    if r < 0.5:
        tris = []
        for _ in range(rng.randint(1, 6)):
            p = tuple(rng.uniform(-1, 1) for _ in range(3))
            q = tuple(rng.uniform(-1, 1) for _ in range(3))
            d = vsub(q, p)
            perp = vunit(vcross(d, rand_unit(rng)))
            tris.append(needle_tri(rng, p, q, vlen(d) * 10.0 ** -rng.uniform(3, 15), perp))
        A = merge(*[tri_mesh(*t) for t in tris])
        if rng.random() < 0.5:
            B = mapm(A, lambda p: vadd(p, vmul(rand_unit(rng), eps)))
        else:  # move only the apex, across the needle line
            B = merge(*[tri_mesh(p, q, vadd(c, vmul(rand_unit(rng), eps))) for p, q, c in tris])
    else:
        # chain of slivers: consecutive ones meet within eps in A, exactly in B
        m = rng.randint(2, 8)
        pts = [tuple(rng.uniform(-1, 1) for _ in range(3)) for _ in range(m + 1)]
        trisA, trisB = [], []
        for i in range(m):
            p, q = pts[i], pts[i + 1]
            d = vsub(q, p)
            perp = vunit(vcross(d, rand_unit(rng)))
            c = vadd(vmid(p, q), vmul(perp, vlen(d) * 10.0 ** -rng.uniform(3, 15)))
            trisB.append(tri_mesh(p, q, c))
            trisA.append(tri_mesh(vadd(p, vmul(rand_unit(rng), eps)) if i else p,
                                  vadd(q, vmul(rand_unit(rng), eps)), c))
        A = merge(*trisA)
        B = weld(merge(*trisB))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('needle_pair', 'needle pairs: near-parallel skew, crossing, collinear overlap, parallel')
def k_needle_pair(rng):
    pa, pb = [], []
    for idx in range(rng.randint(1, 3)):
        o = (0.0, 0.0, 2.0 * idx)
        p, q = vadd(P(0, 0), o), vadd(P(1, 0), o)
        phi = rng.choice((0.0, math.pi / 2, rng.uniform(0, math.pi)))
        perpA = (0.0, math.cos(phi), math.sin(phi))
        if phi == math.pi / 2:
            perpA = (0.0, 0.0, 1.0)
        wA = 0.0 if rng.random() < 0.2 else 10.0 ** -rng.uniform(3, 15)
        pa.append(tri_mesh(*needle_tri(rng, p, q, wA, perpA)))
        r = rng.randrange(4)
        d = 0.0 if rng.random() < 0.2 else sgn(rng) * logu(rng, -15, -3)
        if r == 0:
            al = rng.choice((0.0, logu(rng, -12, -1)))
            u = (math.cos(al), math.sin(al), 0.0)
            c = vadd((0.5, 0.0, d), o)
            b0, b1 = vsub(c, vmul(u, 0.75)), vadd(c, vmul(u, 0.75))
        elif r == 1:
            al = rng.choice((math.pi / 2, rng.uniform(0.1, math.pi / 2), logu(rng, -12, -1)))
            u = (math.cos(al), math.sin(al), 0.0)
            if al == math.pi / 2:
                u = (0.0, 1.0, 0.0)
            c = vadd((rng.choice((0.5, 0.25, rng.random())), 0.0, d), o)
            b0, b1 = vsub(c, vmul(u, 0.5)), vadd(c, vmul(u, 0.5))
        elif r == 2:
            s0 = rng.randint(-4, 4) / 8.0
            u = (1.0, 0.0, 0.0)
            b0, b1 = vadd((s0, 0.0, 0.0), o), vadd((s0 + rng.choice((1.0, 0.5, 0.25)), 0.0, 0.0), o)
        else:
            u = (1.0, 0.0, 0.0)
            sh = rng.choice(((0.0, d, 0.0), (0.0, 0.0, d), (0.0, d, d)))
            b0, b1 = vadd(p, sh), vadd(q, sh)
        perpB = rng.choice(((0.0, 0.0, 1.0), (-u[1], u[0], 0.0)))
        wB = 0.0 if rng.random() < 0.2 else 10.0 ** -rng.uniform(3, 15)
        pb.append(tri_mesh(*needle_tri(rng, b0, b1, wB, perpB)))
    return placed(rng, merge(*pa), merge(*pb))


@kind('wall_on_face', 'floor plus perpendicular walls on grid lines / diagonals')
def k_wall_on_face(rng):
    n = rng.randint(1, 5)
    A = grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng)
    walls = []
    for _ in range(rng.randint(1, 4)):
        r = rng.random()
        a, b = sorted(rng.choice((0.0, 1.0, rng.randint(0, 8) / 8.0, rng.random())) for _ in range(2))
        if b - a < 1e-3:
            a, b = 0.0, 1.0
        if r < 0.4:
            c = rng.randint(0, n) / n if rng.random() < 0.7 else rng.random()
            p, q = (c, a, 0.0), (c, b, 0.0)
        elif r < 0.7:
            c = rng.randint(0, n) / n if rng.random() < 0.7 else rng.random()
            p, q = (a, c, 0.0), (b, c, 0.0)
        else:
            p, q = (a, a, 0.0), (b, b, 0.0)
        h = rng.choice((0.5, 0.25, 1.0, logu(rng, -6, 0)))
        zb = 0.0 if rng.random() < 0.7 else sgn(rng) * logu(rng, -15, -6)
        m = rng.randint(1, 4)
        w = grid(m, 1, 1.0, 1.0, rng.choice(DIAGS), rng)
        w = mapm(w, lambda s, p=p, q=q, h=h, zb=zb: (
            (1.0 - s[0]) * p[0] + s[0] * q[0], (1.0 - s[0]) * p[1] + s[0] * q[1], zb + s[1] * h))
        walls.append(w)
    B = merge(*walls)
    r = rng.random()
    if r < 0.35:
        B = merge(B, A)
    elif r < 0.6:
        B = merge(B, planar_patch(rng))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('thin_plate', 'closed box of thickness 1e-13..1e-6 vs other triangulation / mid-surface')
def k_thin_plate(rng):
    t = math.ldexp(1.0, -rng.randint(20, 43)) if rng.random() < 0.6 else logu(rng, -13, -6)
    W, H = rng.choice(DYW), rng.choice(DYW)
    A = box((0.0, 0.0, 0.0), (W, H, t), rng.randint(1, 3), rng.choice(DIAGS), rng)
    r = rng.randrange(6)
    if r == 0:
        B = box((0.0, 0.0, 0.0), (W, H, t), rng.randint(1, 3), rng.choice(DIAGS), rng)
    elif r == 1:
        B = planar_patch(rng, W, H)
    elif r == 2:
        B = translate(planar_patch(rng, W, H), (0.0, 0.0, t))
    elif r == 3:
        B = translate(planar_patch(rng, W, H), (0.0, 0.0, t * 0.5))
    elif r == 4:
        t2 = rng.choice((t * (1 + logu(rng, -6, -1)), nudge(t, rng.randint(1, 4))))
        B = box((0.0, 0.0, 0.0), (W, H, t2), rng.randint(1, 3), rng.choice(DIAGS), rng)
    else:
        B = box((0.0, 0.0, t), (W, H, 2 * t), rng.randint(1, 2), rng.choice(DIAGS), rng)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('fin_on_edge', 'fins standing on edges of a triangulated square')
def k_fin_on_edge(rng):
    n = rng.randint(1, 4)
    A = grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng)
    es = edges_of(A)
    fins = []
    for (i, j) in rng.sample(es, min(len(es), rng.randint(1, 6))):
        p, q = A[0][i], A[0][j]
        m = lerp(p, q, rng.choice((0.5, 0.5, 0.0, 1.0, rng.random())))
        h = rng.choice((0.5, 0.25, logu(rng, -8, 0)))
        d = vsub(q, p)
        u = vunit((-d[1], d[0], 0.0))
        r = rng.random()
        if r < 0.5:
            dirv = (0.0, 0.0, 1.0)
        elif r < 0.75:
            a = math.pi / 2 + sgn(rng) * logu(rng, -15, -3)
            dirv = vadd(vmul(u, math.cos(a)), (0.0, 0.0, math.sin(a)))
        else:
            a = rng.uniform(0.05, math.pi - 0.05)
            dirv = vadd(vmul(u, math.cos(a)), (0.0, 0.0, math.sin(a)))
        fins.append(tri_mesh(p, q, vadd(m, vmul(dirv, h))))
    B = merge(*fins)
    r = rng.random()
    if r < 0.4:
        B = merge(B, A)
    elif r < 0.6:
        B = merge(B, grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('hinge', 'two strips sharing an edge at exact/near 0, 90, 180 degrees, or ulp-nudged hinge')
def k_hinge(rng):
    nA = rng.randint(1, 5)
    nB = nA if rng.random() < 0.6 else rng.randint(1, 5)
    A = grid(nA, rng.randint(1, 4), 1.0, 1.0, rng.choice(DIAGS), rng, y0=-1.0)
    Lb = rng.choice((1.0, 0.5, 2.0))
    B = grid(nB, rng.randint(1, 4), 1.0, Lb, rng.choice(DIAGS), rng)
    base = rng.choice((0.0, math.pi / 2, math.pi, -math.pi / 2))
    r = rng.random()
    if r < 0.45:
        cs = {0.0: (1.0, 0.0), math.pi / 2: (0.0, 1.0), math.pi: (-1.0, 0.0),
              -math.pi / 2: (0.0, -1.0)}[base]
    elif r < 0.85:
        a = base + sgn(rng) * logu(rng, -15, -4)
        cs = (math.cos(a), math.sin(a))
    else:
        a = rng.uniform(0, 2 * math.pi)
        cs = (math.cos(a), math.sin(a))
    c, s = cs
    B = mapm(B, lambda p: (p[0], p[1] * c, p[1] * s))
    hingeB = [i for i, p in enumerate(B[0]) if p[1] == 0.0 and p[2] == 0.0]
    f, _ = place(rng)
    A, B = mapm(A, f), mapm(B, f)
    if rng.random() < 0.3:
        k = rng.choice((1, 2, 3))
        hs = set(hingeB)
        B = ([nudge_point(p, rng, k) if i in hs else p for i, p in enumerate(B[0])], B[1])
    return maybe_swap(rng, A, B)


LATTICE_DIRS = [(2, 0), (2, 1), (1, 1), (1, 2), (0, 2), (-1, 2), (-1, 1), (-2, 1),
                (-2, 0), (-2, -1), (-1, -1), (-1, -2), (0, -2), (1, -2), (1, -1), (2, -1)]


@kind('shared_vertex', 'fans touching at one vertex (exact, ulp-nudged, shared ray, sectors)')
def k_shared_vertex(rng):
    O = (0.0, 0.0, 0.0)
    if rng.random() < 0.5:
        i0 = rng.randrange(16)
        ka = rng.randint(1, 4)
        rimA = [P(*LATTICE_DIRS[(i0 + t) % 16]) for t in range(ka + 1)]
        g = rng.choice((0, 1, 2))
        kb = rng.randint(1, 4)
        rimB = [P(*LATTICE_DIRS[(i0 + ka + g + t) % 16]) for t in range(kb + 1)]
    else:
        a0, al = rng.uniform(0, 6.28), rng.uniform(0.2, 2.0)
        ka = rng.randint(1, 5)
        rimA = [(math.cos(a0 + al * t / ka), math.sin(a0 + al * t / ka), 0.0) for t in range(ka + 1)]
        gap = rng.choice((0.0, logu(rng, -15, -3), rng.uniform(0.05, 1.0)))
        be = rng.uniform(0.2, 2.0)
        kb = rng.randint(1, 5)
        st = a0 + al + gap
        rimB = [(math.cos(st + be * t / kb), math.sin(st + be * t / kb), 0.0) for t in range(kb + 1)]
        if gap == 0.0:
            rimB[0] = rimA[-1]
    A = fan(O, rimA)
    r = rng.randrange(5)
    if r == 0:
        B = fan(O, rimB)                       # coplanar sectors
    elif r == 1:
        B = fan(O, [vmul(p, -1.0) for p in rimA])    # point reflection
    elif r == 2:
        B = fan(O, [(0.0, p[0], p[1]) for p in rimB])   # perpendicular plane
    elif r == 3:
        h = rng.choice((1.0, 0.5, logu(rng, -10, 0)))
        B = fan(O, [(p[0], p[1], h) for p in rimB])     # cone
    else:
        th = sgn(rng) * logu(rng, -12, -2)
        B = rotate_mesh(fan(O, rimA), axis_rotation((rimA[0][1], -rimA[0][0], 0.0), th))
    f, _ = place(rng)
    A, B = mapm(A, f), mapm(B, f)
    if rng.random() < 0.35:
        B = ([nudge_point(B[0][0], rng, rng.choice((1, 2, 4)))] + B[0][1:], B[1])
    return maybe_swap(rng, A, B)


def add_degenerates(m, rng, count):
    V, F = list(m[0]), list(m[1])
    F0 = list(F)
    size = bbox_size(m)
    for _ in range(count):
        a, b, c = rng.choice(F0)
        r = rng.randrange(8)
        if r == 0:
            F.append((a, a, b))
        elif r == 1:
            F.append((a, a, a))
        elif r == 2:
            V.append(vmid(V[a], V[b]))
            F.append((a, b, len(V) - 1))
        elif r == 3:
            V.append(V[a])
            F.append((a, len(V) - 1, b))
        elif r == 4:
            g = tuple((V[a][i] + V[b][i] + V[c][i]) / 3.0 for i in range(3))
            V.extend([g, g, g])
            F.append((len(V) - 3, len(V) - 2, len(V) - 1))
        elif r == 5:
            nrm = face_normal(V, (a, b, c))
            if vlen(nrm) == 0.0:
                continue
            off = vmul(vunit(nrm), size * logu(rng, -15, -5) * sgn(rng))
            V.extend([vadd(V[a], off), vadd(V[b], off)])
            F.append((len(V) - 2, len(V) - 1, len(V) - 1))
        elif r == 6:
            F.append((b, a, b))
        else:
            t = rng.choice((0.25, 0.75, rng.random()))
            V.append(lerp(V[a], V[b], t))
            F.append((len(V) - 1, a, b))
    return (V, F)


@kind('degenerate_mixed', 'clean mesh vs copy with points, segments, repeated indices, collinear faces')
def k_degenerate_mixed(rng):
    A = base_mesh(rng, maxf=100)
    r = rng.random()
    if r < 0.6:
        B = add_degenerates(A, rng, rng.randint(1, 20))
    else:
        # split faces at an edge midpoint, keeping the flat (a, b, m) face too
        V, F = list(A[0]), []
        for (a, b, c) in A[1]:
            if rng.random() < 0.3 and len(F) < 250:
                V.append(vmid(V[a], V[b]))
                mi = len(V) - 1
                F += [(a, mi, c), (mi, b, c), (a, b, mi)]
            else:
                F.append((a, b, c))
        B = (V, F)
    if rng.random() < 0.3:
        A = add_degenerates(A, rng, rng.randint(1, 5))
    return placed(rng, *maybe_swap(rng, A, B))


def rpt3(rng):
    if rng.random() < 0.5:
        return tuple(rng.randint(-16, 16) / 16.0 for _ in range(3))
    return tuple(rng.uniform(-1, 1) for _ in range(3))


def degen_mesh(rng):
    r = rng.randrange(5)
    if r == 0:
        p = rpt3(rng)
        return ([p], [(0, 0, 0)]) if rng.random() < 0.5 else ([p, p, p], [(0, 1, 2)])
    if r == 1:
        pts = [rpt3(rng) for _ in range(rng.randint(2, 20))]
        return (pts, [(i, i, i) for i in range(len(pts))])
    if r == 2:
        p, q = rpt3(rng), rpt3(rng)
        c = rng.randrange(4)
        if c == 0:
            return ([p, q], [(0, 1, 1)])
        if c == 1:
            return ([p, q], [(0, 0, 1)])
        if c == 2:
            return ([p, vmid(p, q), q], [(0, 1, 2)])
        return ([p, q, lerp(p, q, rng.choice((0.25, 2.0, -1.0, rng.random())))], [(0, 1, 2)])
    if r == 3:
        pts = [rpt3(rng) for _ in range(rng.randint(2, 12))]
        return (pts, [(i, i + 1, i + 1) for i in range(len(pts) - 1)])
    p, q = rpt3(rng), rpt3(rng)
    k = rng.randint(2, 10)
    pts = [lerp(p, q, i / k) for i in range(k + 1)]
    F = [(0, i, i + 1) for i in range(1, k)] + [(i, i + 1, i + 1) for i in range(k)]
    return (pts, F)


@kind('degenerate_only', 'meshes of only points/segments/collinear triples vs anything')
def k_degenerate_only(rng):
    A = degen_mesh(rng)
    r = rng.randrange(4)
    if r == 0:
        B = degen_mesh(rng)
    elif r == 1:
        B = tri_mesh(rpt3(rng), rpt3(rng), rpt3(rng))
    elif r == 2:
        B = translate(grid(rng.randint(1, 4), rng.randint(1, 4), 2.0, 2.0, rng.choice(DIAGS), rng),
                      (-1.0, -1.0, rng.choice((0.0, 0.5, rng.uniform(-1, 1)))))
    else:
        B = tetra_mesh(rng)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('duplicate_flip_unweld', 'mesh vs copy with duplicated, flipped, unwelded, shuffled faces')
def k_duplicate_flip_unweld(rng):
    A = base_mesh(rng, maxf=100)
    B = (list(A[0]), list(A[1]))
    ops = [o for o in ('dup', 'dupflip', 'flipsome', 'flipall', 'unweld', 'shuffle')
           if rng.random() < 0.45] or ['dup']
    for op in ops:
        V, F = B
        if op == 'dup':
            B = (V, F + rng.sample(F, min(len(F), rng.randint(1, 50))))
        elif op == 'dupflip':
            B = (V, F + [(a, c, b) for a, b, c in rng.sample(F, min(len(F), rng.randint(1, 50)))])
        elif op == 'flipsome':
            B = (V, [(a, c, b) if rng.random() < 0.5 else (a, b, c) for a, b, c in F])
        elif op == 'flipall':
            B = flip(B)
        elif op == 'unweld':
            B = unweld(B)
        else:
            B = shuffle_mesh(B, rng)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('subset', 'mesh vs a subset of its faces (random, connected patch, single face)')
def k_subset(rng):
    A = base_mesh(rng)
    V, F = A
    r = rng.random()
    if r < 0.4:
        p = rng.uniform(0.1, 0.9)
        S = [f for f in F if rng.random() < p]
    elif r < 0.8:
        c = V[rng.choice(rng.choice(F))]
        rad = rng.uniform(0.1, 1.0) * bbox_size(A)
        S = [f for f in F if min(vlen(vsub(V[i], c)) for i in f) <= rad]
    else:
        S = [rng.choice(F)]
    if not S:
        S = [F[0]]
    B = (V, S)
    if rng.random() < 0.3:
        B = shuffle_mesh(B, rng)
    if rng.random() < 0.2:
        B = unweld(B)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('refinement', 'mesh vs midpoint 1-to-4 / centroid 1-to-3 / partial edge bisection refinement')
def k_refinement(rng):
    A = base_mesh(rng, maxf=60)
    r = rng.random()
    if r < 0.4:
        B = subdivide4(A)
        if len(A[1]) <= 12 and rng.random() < 0.4:
            B = subdivide4(B)
    elif r < 0.65:
        B = subdivide3(A)
    else:
        B = bisect_some(A, rng, rng.uniform(0.2, 0.8))
        if rng.random() < 0.4:
            B = bisect_some(B, rng, 0.3)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('decimation', 'fine height field / sphere / box vs coarse version on a vertex subset')
def k_decimation(rng):
    r = rng.random()
    if r < 0.6:
        N = rng.choice((4, 6, 8))
        M = rng.choice([d for d in range(1, N) if N % d == 0])
        mode = rng.randrange(3)
        W, H = rng.choice(DYW), rng.choice(DYW)
        if mode == 0:
            tab = {(i, j): rng.randint(-8, 8) / 16.0 for j in range(N + 1) for i in range(N + 1)}
        elif mode == 1:
            fx, amp = rng.randint(1, 2), rng.uniform(0.05, 0.5)
            tab = {(i, j): amp * math.sin(2 * math.pi * fx * i / N) * math.cos(math.pi * j / N)
                   for j in range(N + 1) for i in range(N + 1)}
        else:
            tab = {(i, j): (i / N - 0.5) ** 2 + (j / N - 0.5) ** 2 * rng.choice((1.0, -1.0))
                   for j in range(N + 1) for i in range(N + 1)}
        q = N // M
        A = grid(N, N, W, H, rng.choice(DIAGS), rng, zf=lambda i, j, x, y: tab[(i, j)])
        B = grid(M, M, W, H, rng.choice(DIAGS), rng, zf=lambda i, j, x, y: tab[(i * q, j * q)])
    elif r < 0.85:
        L = rng.choice((1, 2))
        A, B = sphere(L), sphere(L - 1)
    else:
        hi = (rng.choice(DYW), rng.choice(DYW), rng.choice(DYW))
        A = box((0.0, 0.0, 0.0), hi, 3, rng.choice(DIAGS), rng)
        B = box((0.0, 0.0, 0.0), hi, 1, rng.choice(DIAGS), rng)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('renumbered_self', 'mesh vs itself renumbered / rotated vertex order / exact symmetry image')
def k_renumbered_self(rng):
    r = rng.random()
    if r < 0.5:
        A = base_mesh(rng)
        B = shuffle_mesh(A, rng)
    else:
        c = rng.randrange(3)
        if c == 0:
            A = box(P(-1, -1, -1), P(1, 1, 1), rng.randint(1, 3), rng.choice(('alt', 'rand', 'a')), rng)
            M, det = signed_perm(rng)
        elif c == 1:
            A = sphere(rng.choice((0, 1, 2)))
            M, det = signed_perm(rng)
        else:
            A = tetra_mesh(rng, 'regular')
            if rng.random() < 0.5:
                A = weld(subdivide4(A))
            M, det = signed_perm(rng, even_signs=True)
        B = mapm(A, lambda p: matvec(M, p))
        if det < 0:
            B = flip(B)
        if c == 0 and rng.random() < 0.5:
            B = box(P(-1, -1, -1), P(1, 1, 1), rng.randint(1, 3), 'rand', rng)
            B = mapm(B, lambda p: matvec(M, p))
        B = shuffle_mesh(B, rng, rotate=rng.random() < 0.8)
    return placed(rng, A, B)


@kind('ties_mirror', 'patch midway between mirrored patches / mirrored triangles / square frame')
def k_ties_mirror(rng):
    r = rng.randrange(5)
    if r == 0:
        A = planar_patch(rng)
        M = planar_patch(rng)
        h = rng.choice((0.5, 0.25, 1.0, math.ldexp(1.0, -rng.randint(3, 40))))
        B = merge(translate(M, (0.0, 0.0, h)), flip(mapm(M, lambda p: (p[0], p[1], -p[2] - h))))
    elif r == 1:
        A = planar_patch(rng)
        h, a = rng.choice((0.5, 0.25)), rng.choice((0.25, 0.5, 1.0))
        n = rng.randint(1, 4)
        M = grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng)
        B = merge(mapm(M, lambda p: (p[0], p[1], h + a * p[0])),
                  flip(mapm(M, lambda p: (p[0], p[1], -(h + a * p[0])))))
    elif r == 2:
        A = translate(mapm(planar_patch(rng), lambda p: (0.0, p[0], p[1])), (0.0, -0.5, -0.5))
        T = [(rng.randint(1, 8) / 8.0, rng.randint(-8, 8) / 8.0, rng.randint(-8, 8) / 8.0)
             for _ in range(3)]
        Tm = [(-p[0], p[1], p[2]) for p in T]
        B = merge(tri_mesh(*T), tri_mesh(Tm[0], Tm[2], Tm[1]))
    elif r == 3:
        n = rng.choice((4, 8))
        hole = rng.choice((2, n // 2)) if n == 8 else 2
        B = frame_mesh(rng, n, hole)
        rr = hole / n
        c = rng.randrange(4)
        z = rng.choice((0.0, 0.0, 0.5, math.ldexp(1.0, -rng.randint(5, 40))))
        if c == 0:
            A = ([P(0, 0, z)], [(0, 0, 0)])
        elif c == 1:
            q = rr * rng.choice((0.5, 0.25))
            A = grid(rng.randint(1, 3), rng.randint(1, 3), 2 * q, 2 * q, 'alt', x0=-q, y0=-q, z=z)
        elif c == 2:
            A = grid(2, 2, 2 * rr, 2 * rr, 'alt', x0=-rr, y0=-rr, z=z)
        else:
            A = tri_mesh(P(-rr, -rr, z), P(rr, -rr, z), P(0, rr, z))
    else:
        d = rng.choice((0.5, 1.0, 0.25))
        B = ([P(d, 0, 0), P(-d, 0, 0)], [(0, 0, 0), (1, 1, 1)])
        if rng.random() < 0.5:
            B = merge(B, ([P(0, d, 0), P(0, -d, 0)], [(0, 0, 0), (1, 1, 1)]))
        A = tri_mesh(P(0, -1, -1), P(0, 1, -1), P(0, 0, 1))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('ties_cube_center', 'symmetric objects at the centre of a cube / octahedron / box')
def k_ties_cube_center(rng):
    c = rng.randrange(3)
    if c == 0:
        B = box(P(-1, -1, -1), P(1, 1, 1), rng.randint(1, 3), rng.choice(DIAGS), rng)
    elif c == 1:
        B = sphere(0)
    else:
        a, b = rng.choice((1.0, 0.5, 2.0)), rng.choice((1.0, 0.5, 2.0, 0.75))
        B = box(P(-a, -a, -b), P(a, a, b), rng.randint(1, 2), rng.choice(DIAGS), rng)
    rr = math.ldexp(1.0, -rng.randint(1, 30))
    r = rng.randrange(7)
    if r == 0:
        A = ([P(0, 0, 0)], [(0, 0, 0)])
    elif r == 1:
        A = mapm(sphere(0), lambda p: vmul(p, rr))
    elif r == 2:
        A = box(P(-rr, -rr, -rr), P(rr, rr, rr), 1, rng.choice(DIAGS), rng)
    elif r == 3:
        A = tri_mesh(P(rr, 0, 0), P(0, rr, 0), P(0, 0, rr))
    elif r == 4:
        A = ([P(-rr, 0, 0), P(rr, 0, 0)], [(0, 1, 1)])
    elif r == 5:
        A = ([P(rng.choice((0.25, 0.5, rr)), 0, 0)], [(0, 0, 0)])
    else:
        A = grid(2, 2, 2 * rr, 2 * rr, 'alt', x0=-rr, y0=-rr)
    return placed(rng, *maybe_swap(rng, A, B, 0.3))


@kind('ties_circumcenter', 'triangle / square vs corner points, opposite edges, or parallel copy')
def k_ties_circumcenter(rng):
    a, b = rng.choice(DYW), rng.choice(DYW)
    r = rng.randrange(5)
    if r == 0:
        T = (P(0, 0), P(a, 0), P(0, b))
        A = tri_mesh(*T) if rng.random() < 0.5 else tri_subdiv(T[0], T[1], T[2], rng.randint(2, 4))
        e = rng.choice((0.0, math.ldexp(1.0, -rng.randint(4, 30))))
        if e == 0.0:
            B = ([T[0], T[1], T[2]], [(0, 0, 0), (1, 1, 1), (2, 2, 2)])
        else:
            B = merge(*[tri_mesh(p, vadd(p, (e, 0.0, 0.0)), vadd(p, (0.0, e, 0.0))) for p in T])
    elif r == 1:
        A = grid(rng.randint(1, 3), rng.randint(1, 3), a, a, rng.choice(DIAGS), rng)
        B = ([P(0, 0), P(a, 0), P(a, a), P(0, a)], [(0, 0, 0), (1, 1, 1), (2, 2, 2), (3, 3, 3)])
    elif r == 2:
        A = grid(rng.randint(1, 3), rng.randint(1, 3), a, b, rng.choice(DIAGS), rng)
        B = ([P(0, 0), P(a, 0), P(0, b), P(a, b)], [(0, 1, 1), (2, 3, 3)])
    elif r == 3:
        s3 = math.sqrt(3.0)
        T = (P(1, 0), P(-0.5, s3 / 2), P(-0.5, -s3 / 2))
        A = tri_mesh(*T)
        B = ([T[0], T[1], T[2]], [(0, 0, 0), (1, 1, 1), (2, 2, 2)])
    else:
        A = rng.choice((tri_mesh(P(0, 0), P(a, 0), P(0, b)),
                        grid(rng.randint(1, 4), rng.randint(1, 4), a, b, rng.choice(DIAGS), rng)))
        h = rng.choice((0.5, 1.0, math.ldexp(1.0, -rng.randint(2, 40))))
        B = translate(A, (0.0, 0.0, h))
        if rng.random() < 0.4:
            B = subdivide4(B)
    return placed(rng, *maybe_swap(rng, A, B, 0.3))


@kind('vertex_on_feature', 'triangles touching a grid exactly at a vertex, edge point or face point')
def k_vertex_on_feature(rng):
    n = rng.choice((1, 2, 4))
    dg = rng.choice(('a', 'b'))
    B = grid(n, n, 1.0, 1.0, dg)
    parts = []
    for _ in range(rng.randint(1, 6)):
        i, j = rng.randrange(n), rng.randrange(n)
        t = rng.randint(1, 15) / 16.0
        r = rng.randrange(4)
        if r == 0:
            c = (rng.randint(0, n) / n, rng.randint(0, n) / n, 0.0)
        elif r == 1:
            c = ((i + t) / n, j / n, 0.0) if rng.random() < 0.5 else (i / n, (j + t) / n, 0.0)
        elif r == 2:
            c = ((i + t) / n, (j + t) / n, 0.0) if dg == 'a' else ((i + 1 - t) / n, (j + t) / n, 0.0)
        else:
            c = ((i + t) / n, (j + rng.randint(1, 15) / 16.0) / n, 0.0)
        sc = math.ldexp(1.0, -rng.randint(2, 6))
        m = rng.randrange(4)
        d1 = (rng.randint(-4, 4) / 4.0 * sc, rng.randint(-4, 4) / 4.0 * sc)
        d2 = (rng.randint(-4, 4) / 4.0 * sc, rng.randint(-4, 4) / 4.0 * sc)
        if m == 0:
            h1, h2 = sc, rng.choice((sc, sc * 0.5))
        elif m == 1:
            h1, h2 = sc, -sc
        elif m == 2:
            h1, h2 = 0.0, 0.0
            d1, d2 = (sc, 0.0), (0.0, sc)
        else:
            h1, h2 = 0.0, sc
            d1 = (sc, 0.0) if r == 1 else (sc, sc) if r == 2 else d1
        parts.append(tri_mesh(c, vadd(c, (d1[0], d1[1], h1)), vadd(c, (d2[0], d2[1], h2))))
    A = merge(*parts)
    return placed(rng, *maybe_swap(rng, A, B, 0.3))


@kind('edge_crossing', 'edges crossing edges/diagonals exactly or 1e-15..1e-4 apart; X triangles')
def k_edge_crossing(rng):
    n = rng.choice((1, 1, 2))
    B = grid(n, n, 1.0, 1.0, 'a')
    parts = []
    for _ in range(rng.randint(1, 4)):
        d = 0.0 if rng.random() < 0.5 else sgn(rng) * logu(rng, -15, -4)
        r = rng.randrange(4)
        t = rng.randint(1, 7) / 8.0
        if r == 0:
            parts.append(tri_mesh(P(t, -0.5, d), P(t, 0.5, d), P(t, 0, rng.choice((1.0, -1.0, 0.5)))))
        elif r == 1:
            u = rng.choice((0.25, 0.5))
            parts.append(tri_mesh(P(0.5 + u, 0.5 - u, d), P(0.5 - u, 0.5 + u, d),
                                  P(0.5, 0.5, rng.choice((0.5, -0.5)))))
        elif r == 2:
            c = rng.choice((0.0, t, 1.0))
            parts.append(tri_mesh(P(0.25, c, -0.5), P(0.75, c, -0.5), P(0.5, c, 0.5)))
        else:
            ang = rng.uniform(0, math.pi)
            cx, cy = rng.random(), rng.random()
            u = (math.cos(ang) * 0.5, math.sin(ang) * 0.5, 0.0)
            p, q = (cx - u[0], cy - u[1], d), (cx + u[0], cy + u[1], d)
            parts.append(tri_mesh(p, q, vadd(vmid(p, q), (0.0, 0.0, logu(rng, -12, 0)))))
    A = merge(*parts)
    return placed(rng, *maybe_swap(rng, A, B, 0.3))


@kind('scale_mix', 'tiny (1e-6) triangles on/near faces, edges, corners of a big (1e3) mesh')
def k_scale_mix(rng):
    S = 1024.0
    tiny = math.ldexp(1.0, -20)
    if rng.random() < 0.5:
        n = rng.randint(1, 4)
        big = grid(n, n, S, S, rng.choice(DIAGS), rng)
    else:
        big = box(P(0, 0, 0), P(S, S, S), rng.randint(1, 2), rng.choice(DIAGS), rng)
    parts = []
    for _ in range(rng.randint(1, 5)):
        r = rng.randrange(5)
        e = tiny * rng.choice((1.0, 0.5, 4.0))
        if r == 0:
            c = (rng.randint(1, 255) / 256.0 * S, rng.randint(1, 255) / 256.0 * S, 0.0)
            parts.append(tri_mesh(c, vadd(c, (e, 0.0, 0.0)), vadd(c, (0.0, e, 0.0))))
        elif r == 1:
            c = (rng.uniform(0, S), rng.uniform(0, S), sgn(rng) * tiny * 10.0 ** -rng.uniform(0, 8))
            parts.append(tri_mesh(c, vadd(c, (e, 0.0, 0.0)), vadd(c, (0.0, e, 0.0))))
        elif r == 2:
            c = P(0, 0, 0) if rng.random() < 0.5 else P(S, 0, 0)
            parts.append(tri_mesh(c, vadd(c, (-e, 0.0, e)), vadd(c, (0.0, -e, e))))
        elif r == 3:
            c = (rng.randint(1, 255) / 256.0 * S, 0.0, 0.0)
            parts.append(tri_mesh(vadd(c, (0.0, -e, 0.0)), vadd(c, (0.0, e, 0.0)), vadd(c, (0.0, 0.0, e))))
        else:
            c = (rng.uniform(0, S), rng.uniform(0, S), rng.uniform(-1, 1) * tiny * 8)
            R = rand_rotation(rng)
            parts.append(tri_mesh(*[vadd(c, matvec(R, (e * rng.random(), e * rng.random(), 0.0)))
                                    for _ in range(3)]))
    A = merge(*parts)
    if rng.random() < 0.3:
        A = merge(A, big)
    f, _ = place(rng, logscale=(-1.5, 1.5))
    return maybe_swap(rng, mapm(A, f), mapm(big, f), 0.3)


@kind('crossing_planes', 'two patches crossing at exact 90 deg, generic or 1e-12..1e-1 rad angles')
def k_crossing_planes(rng):
    A = translate(planar_patch(rng, 2.0, 2.0), (-1.0, -1.0, 0.0))
    B = translate(planar_patch(rng, 2.0, 2.0), (-1.0, -1.0, 0.0))
    c = rng.choice((0.0, 0.5, -0.25, rng.uniform(-0.5, 0.5)))
    r = rng.randrange(3)
    if r == 0:
        B = mapm(B, lambda p: (p[0], c, p[1]))
    elif r == 1:
        th = rng.choice((logu(rng, -12, -1), rng.uniform(0.1, 1.5)))
        ct, st = math.cos(th), math.sin(th)
        B = mapm(B, lambda p: (p[0], c + p[1] * ct, p[1] * st))
    else:
        ang = rng.uniform(0, math.pi)
        th = sgn(rng) * logu(rng, -12, -1)
        B = rotate_mesh(B, axis_rotation((math.cos(ang), math.sin(ang), 0.0), th))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('folded_sheet', 'creased height field (slope 1e-12..1) vs flat / other creased triangulation')
def k_folded_sheet(rng):
    n = rng.randint(2, 7)
    slope = rng.choice((1.0, 0.5, logu(rng, -12, 0)))
    r = rng.randrange(3)
    if r == 0:
        cc = rng.choice((rng.randint(1, n - 1) / n, rng.random()))

        def h(x, y):
            return slope * abs(x - cc)
    elif r == 1:
        def h(x, y):
            return slope * abs(x - y)
    else:
        per = rng.choice((0.25, 0.5))

        def h(x, y):
            u = (x / per) % 1.0
            return slope * per * min(u, 1.0 - u)
    A = grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng, zf=lambda i, j, x, y: h(x, y))
    q = rng.randrange(3)
    if q == 0:
        B = planar_patch(rng)
    elif q == 1:
        m = rng.randint(2, 7)
        B = grid(m, m, 1.0, 1.0, rng.choice(DIAGS), rng, zf=lambda i, j, x, y: h(x, y))
    else:
        s2 = slope * (1.0 + sgn(rng) * logu(rng, -12, -2))
        B = grid(n, n, 1.0, 1.0, rng.choice(DIAGS), rng,
                 zf=lambda i, j, x, y: h(x, y) * (s2 / slope))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('closed_tetra', 'tetrahedron vs perturbed / subdivided / symmetric / rotated copy')
def k_closed_tetra(rng):
    tk = rng.choice(('regular', 'corner', 'random'))
    A = tetra_mesh(rng, tk)
    c = tuple(sum(p[i] for p in A[0]) / 4.0 for i in range(3))
    r = rng.randrange(6)
    if r == 0:
        V = list(A[0])
        k = rng.randrange(4)
        V[k] = vadd(V[k], vmul(rand_unit(rng), logu(rng, -15, -2)))
        B = (V, A[1])
    elif r == 1:
        eps = logu(rng, -15, -4)
        B = mapm(A, lambda p: vadd(p, vmul(rand_unit(rng), eps)))
    elif r == 2:
        n = rng.randint(2, 4)
        B = weld(merge(*[tri_subdiv(A[0][a], A[0][b], A[0][cc], n) for a, b, cc in A[1]]))
    elif r == 3:
        B = subdivide3(A)
    elif r == 4:
        if tk == 'regular':
            M, _ = signed_perm(rng, even_signs=True)
            B = orient_outward(mapm(A, lambda p: matvec(M, p)), c)
        else:
            eps = logu(rng, -12, -2)
            B = mapm(A, lambda p: vadd(c, vmul(vsub(p, c), 1.0 + eps)))
    else:
        B = rotate_mesh(A, axis_rotation(rand_unit(rng), logu(rng, -14, -2)), c)
    if rng.random() < 0.3:
        B = shuffle_mesh(B, rng)
    return placed(rng, *maybe_swap(rng, A, B))


@kind('closed_box', 'box vs retriangulated / 90-degree-rotated / scaled / jittered / dented copy')
def k_closed_box(rng):
    cube = rng.random() < 0.5
    if cube:
        lo, hi = P(-1, -1, -1), P(1, 1, 1)
    else:
        lo, hi = P(0, 0, 0), (rng.choice(DYW), rng.choice(DYW), rng.choice(DYW))
    A = box(lo, hi, rng.randint(1, 3), rng.choice(DIAGS), rng)
    r = rng.randrange(6)
    if r == 0:
        B = box(lo, hi, rng.randint(1, 3), rng.choice(DIAGS), rng)
    elif r == 1 and cube:
        B = box(lo, hi, rng.randint(1, 3), rng.choice(DIAGS), rng)
        B = mapm(B, lambda p: (-p[1], p[0], p[2]))
    elif r == 2:
        c = vmid(lo, hi)
        eps = sgn(rng) * logu(rng, -14, -2)
        B = mapm(A, lambda p: vadd(c, vmul(vsub(p, c), 1.0 + eps)))
    elif r == 3:
        eps = logu(rng, -14, -3)
        B = mapm(A, lambda p: vadd(p, vmul(rand_unit(rng), eps)))
    elif r == 4:
        B = box(lo, hi, rng.randint(2, 3), rng.choice(DIAGS), rng)
        V = list(B[0])
        inner = [i for i, p in enumerate(V)
                 if sum(1 for k in range(3) if p[k] in (lo[k], hi[k])) == 1]
        if inner:
            i = rng.choice(inner)
            k = [k for k in range(3) if V[i][k] in (lo[k], hi[k])][0]
            d = [0.0, 0.0, 0.0]
            d[k] = sgn(rng) * logu(rng, -14, -1)
            V[i] = vadd(V[i], tuple(d))
        B = (V, B[1])
    else:
        B = translate(box(lo, hi, rng.randint(1, 3), rng.choice(DIAGS), rng),
                      vmul(rand_unit(rng), logu(rng, -15, -3)))
    return placed(rng, *maybe_swap(rng, A, B))


@kind('closed_sphere', 'octahedral low-poly sphere vs other level / jittered / rotated copy')
def k_closed_sphere(rng):
    L = rng.choice((0, 1, 1, 2))
    A = sphere(L)
    r = rng.randrange(5)
    if r == 0:
        B = sphere(rng.choice([l for l in (0, 1, 2) if l != L]))
    elif r == 1:
        eps = logu(rng, -13, -3)
        B = mapm(A, lambda p: vmul(p, 1.0 + eps * rng.uniform(-1, 1)))
    elif r == 2:
        R = rand_rotation(rng) if rng.random() < 0.5 else \
            axis_rotation(rand_unit(rng), logu(rng, -14, -2))
        B = rotate_mesh(A, R)
    elif r == 3:
        B = mapm(A, lambda p: vmul(p, 1.0 + sgn(rng) * logu(rng, -14, -2)))
    else:
        B = shuffle_mesh(flip(A) if rng.random() < 0.5 else A, rng)
        B = subdivide4(B) if L <= 1 and rng.random() < 0.5 else B
    return placed(rng, *maybe_swap(rng, A, B))


@kind('nested_solids', 'solid vs shrunken inner copy (gap 1e-12..1e-1 or touching), shells')
def k_nested_solids(rng):
    g = rng.choice((logu(rng, -12, -1), math.ldexp(1.0, -rng.randint(3, 40))))
    if rng.random() < 0.6:
        outer = box(P(-1, -1, -1), P(1, 1, 1), rng.randint(1, 3), rng.choice(DIAGS), rng)
        if rng.random() < 0.6:
            lo2, hi2 = P(-1 + g, -1 + g, -1 + g), P(1 - g, 1 - g, 1 - g)
        else:
            lo2, hi2 = P(-1, -1 + g, -1 + g), P(1 - g, 1 - g, 1 - g)
        inner = box(lo2, hi2, rng.randint(1, 2), rng.choice(DIAGS), rng)
    else:
        L = rng.choice((0, 1, 1, 2))
        outer = sphere(L)
        inner = mapm(sphere(rng.choice((0, 1)) if L == 2 else L), lambda p: vmul(p, 1.0 - g))
    r = rng.randrange(3)
    if r == 0:
        A, B = outer, inner
    elif r == 1:
        A, B = merge(outer, flip(inner)), outer
    else:
        A, B = merge(outer, flip(inner)), inner
    return placed(rng, *maybe_swap(rng, A, B))


# ---------------------------- far kinds -------------------------------------

def retri_pair(rng):
    """Two triangulations of (nearly) the same surface."""
    r = rng.randrange(5)
    if r == 0:
        W, H = rng.choice(DYW), rng.choice(DYW)
        return planar_patch(rng, W, H), planar_patch(rng, W, H)
    if r == 1:
        A = heightfield_rand(rng, rng.randint(2, 5), rng.randint(2, 5))
        return A, (subdivide4(A) if rng.random() < 0.5 else bisect_some(A, rng, 0.5))
    if r == 2:
        hi = (rng.choice(DYW), rng.choice(DYW), rng.choice(DYW))
        return (box(P(0, 0, 0), hi, rng.randint(1, 3), rng.choice(DIAGS), rng),
                box(P(0, 0, 0), hi, rng.randint(1, 3), rng.choice(DIAGS), rng))
    if r == 3:
        A = sphere(1)
        return A, (subdivide4(A) if rng.random() < 0.5 else subdivide3(A))
    pts, c = random_polygon(rng)
    return poly_tri(pts, rng, c), poly_tri(pts, rng, c)


@kind('retri_far', 'far from the origin: retriangulations of the same surface')
def k_retri_far(rng):
    A, B = far_center(*retri_pair(rng))
    f, _ = place(rng, far=True, size=bbox_size(A))
    return maybe_swap(rng, mapm(A, f), mapm(B, f))


@kind('jitter_far', 'far from the origin: ulp-jittered or relatively jittered copies')
def k_jitter_far(rng):
    if rng.random() < 0.6:
        A = base_mesh(rng)
        B = (list(A[0]), list(A[1]))
    else:
        A, B = retri_pair(rng)
    A, B = far_center(A, B)
    size = bbox_size(A)
    f, s = place(rng, far=True, size=size)
    A, B = mapm(A, f), mapm(B, f)
    r = rng.random()
    if r < 0.6:
        k = rng.choice((1, 1, 2, 4, 16))
        B = mapm(B, lambda p: nudge_point(p, rng, k))
    else:
        eps = logu(rng, -14, -6) * size * s
        B = mapm(B, lambda p: vadd(p, vmul(rand_unit(rng), eps)))
    return maybe_swap(rng, A, B)


@kind('tinyrot_far', 'far from the origin: copies rotated by 1e-14..1e-4 rad about their centre')
def k_tinyrot_far(rng):
    if rng.random() < 0.6:
        A = base_mesh(rng)
        B = (list(A[0]), list(A[1]))
    else:
        A, B = retri_pair(rng)
    c = bbox_center(A)
    A, B = translate(A, vmul(c, -1.0)), translate(B, vmul(c, -1.0))
    ax = rand_unit(rng) if rng.random() < 0.6 else rng.choice((P(1, 0, 0), P(0, 1, 0), P(0, 0, 1)))
    B = rotate_mesh(B, axis_rotation(ax, sgn(rng) * logu(rng, -14, -4)))
    f, _ = place(rng, far=True, size=bbox_size(A))
    return maybe_swap(rng, mapm(A, f), mapm(B, f))


@kind('float32_far', 'far from the origin: float32-rounded copies (offset 1e4..1e5 x size)')
def k_float32_far(rng):
    if rng.random() < 0.6:
        A = base_mesh(rng)
        B = (list(A[0]), list(A[1]))
    else:
        A, B = retri_pair(rng)
    A, B = far_center(A, B)
    f, _ = place(rng, far=True, far_exp=(4.27, 5.0), size=bbox_size(A))
    A, B = mapm(A, f), mapm(B, f)
    B = mapm(B, lambda p: (to_f32(p[0]), to_f32(p[1]), to_f32(p[2])))
    if rng.random() < 0.2:
        A = mapm(A, lambda p: (to_f32(p[0]), to_f32(p[1]), to_f32(p[2])))
    return maybe_swap(rng, A, B)


@kind('solid_far', 'far from the origin: closed solids vs perturbed / retriangulated copies')
def k_solid_far(rng):
    A = base_mesh(rng, closed=True)
    A = translate(A, vmul(bbox_center(A), -1.0))
    size = bbox_size(A)
    c = (0.0, 0.0, 0.0)
    r = rng.randrange(4)
    if r == 0:
        eps = logu(rng, -12, -5)
        B = mapm(A, lambda p: vadd(c, vmul(vsub(p, c), 1.0 + eps * rng.uniform(-1, 1))))
    elif r == 1:
        B = subdivide4(A) if len(A[1]) <= 60 else bisect_some(A, rng, 0.5)
    elif r == 2:
        B = shuffle_mesh(A, rng)
    else:
        eps = logu(rng, -12, -5) * size
        B = mapm(A, lambda p: vadd(p, vmul(rand_unit(rng), eps)))
    f, _ = place(rng, far=True, size=size)
    return maybe_swap(rng, mapm(A, f), mapm(B, f))


KINDS = [name for name, _, _ in KIND_LIST]
KIND_FUNCS = {name: fn for name, fn, _ in KIND_LIST}
KIND_DESC = {name: desc for name, _, desc in KIND_LIST}

# ---------------------------------------------------------------------------
# validation and output
# ---------------------------------------------------------------------------


def compact(m):
    """Drop vertices that no face uses; float-ify coordinates."""
    V, F = m
    used = sorted(set(i for f in F for i in f))
    remap = {old: new for new, old in enumerate(used)}
    NV = [tuple(float(c) for c in V[i]) for i in used]
    NF = [tuple(remap[i] for i in f) for f in F]
    return (NV, NF)


def validate(m, label):
    V, F = m
    if not (1 <= len(F) <= MAX_TRIS):
        raise ValueError('%s: %d triangles (allowed 1..%d)' % (label, len(F), MAX_TRIS))
    used = set()
    for f in F:
        if len(f) != 3:
            raise ValueError('%s: non-triangle face %r' % (label, f))
        for i in f:
            if not isinstance(i, int) or i < 0 or i >= len(V):
                raise ValueError('%s: bad index %r' % (label, i))
            used.add(i)
    if len(used) != len(V):
        raise ValueError('%s: unused vertices' % label)
    for p in V:
        if len(p) != 3 or not all(isinstance(c, float) and math.isfinite(c) for c in p):
            raise ValueError('%s: bad vertex %r' % (label, p))


def write_obj(path, m, comment):
    V, F = m
    lines = ['# ' + comment]
    lines += ['v %r %r %r' % p for p in V]
    lines += ['f %d %d %d' % (a + 1, b + 1, c + 1) for a, b, c in F]
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')


def generate(seed):
    name = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    A, B = KIND_FUNCS[name](rng)
    A, B = compact(A), compact(B)
    validate(A, 'seed %d %s mesh a' % (seed, name))
    validate(B, 'seed %d %s mesh b' % (seed, name))
    return name, A, B


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: python3 generate_pairs13.py OUTDIR FROM TO\n')
        return 2
    outdir, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    for seed in range(lo, hi):
        name, A, B = generate(seed)
        for tag, m in (('a', A), ('b', B)):
            path = os.path.join(outdir, '%06d_%s_%s.obj' % (seed, name, tag))
            write_obj(path, m, 'generate_pairs13 seed=%d kind=%s mesh=%s: %s'
                      % (seed, name, tag, KIND_DESC[name]))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
