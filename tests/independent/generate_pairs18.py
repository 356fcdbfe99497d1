#!/usr/bin/env python3
"""gen18 -- seeded generator of random *degenerate* triangle-mesh pairs.

Purpose: stress inputs for a tool that computes the exact Hausdorff distance
between two triangle meshes (per triangle of one mesh, the exact partition of
that triangle by the nearest vertex / edge / face of the other mesh).
This script was written BLIND: without reading the tool's code, tests, docs
or any other generator, as an independent source of hard inputs.

SYNOPSIS
    python3 generate_pairs18.py OUTDIR FROM TO

    For every integer seed s in [FROM, TO) writes
        OUTDIR/NNNNNN_KIND_a.obj  and  OUTDIR/NNNNNN_KIND_b.obj
    (NNNNNN = s zero padded to 6 digits, KIND = KINDS[s % len(KINDS)]) and
    finally prints one summary line
        gen18: N pairs written to OUTDIR; triangles per mesh min/median/max = a/b/c
    All randomness comes from random.Random(s): a pair depends only on s.
    OUTDIR is created if missing.  Standard library only.

FORMAT (Wavefront OBJ subset)
    line 1 : '# gen18 seed=S kind=K mesh=a|b key=value ...' (the parameters)
    then   : 'v x y z' lines, every coordinate written with repr(float), so it
             reads back bit-exactly (-0.0 is normalised to 0.0)
    then   : 'f i j k' lines, 1-based vertex indices.
    Every mesh has 1..200 triangles (most <= 60), finite coordinates, valid
    indices, no unused vertices, and at most 30 triangles around any vertex
    (counted by index and by identical coordinates).  Draws that break a limit
    are redrawn from the same random stream.  Zero-area triangles (repeated
    index, repeated coordinates, collinear corners) occur on purpose.

COMMON POST-PROCESSING (recorded in the header)
    place=exact   : axis permutation + sign flips, scale 2**k, dyadic
                    translation chosen so that every coordinate stays exact
                    (keeps exact ties / exact coplanarity);
    place=generic : random rotation, log-uniform size 1e-6..1e6, translation
                    0, near, or far (up to ~1e6) from the origin;
    swapped=1     : roles of mesh a and mesh b exchanged;
    scr_a/scr_b=1 : face order shuffled, corners cyclically rotated, some
                    faces reversed, vertex order shuffled.

KINDS (one line each; "A"/"B" before the optional swap)
    coplanar_retriangulation   same rectangle triangulated two ways (flipped diagonals, refined, 2-triangle, centre fan, corner fan, 4-split)
    coplanar_partial_overlap   two coplanar grids overlapping partially (integer/half/tiny dyadic/random shifts, 45deg exact, random in-plane rotation, 1/3 cells)
    coplanar_t_junction        random quadtrees with hanging nodes vs quadtree/grid/lifted copy; big triangle vs fan through points on its edges
    tilted_grid                grid vs grid tilted by 1e-12..1e-3 rad about a centre line, shared edge, corner line or off-plane axis
    parallel_offset_planes     grids on parallel planes at tiny offsets (dyadic 2^-k or 1e-15..1e-3), same/flipped/shifted/inner/alternating-side cells
    sliver_triangles           sliver strips, sliver books and obtuse slivers (height 1e-12..1e-6 of edge) vs plate, crossing sliver, point, twin
    needle_triangles           needle fans, thin cones and needle pairs (short edge 1e-12..1e-6) vs crossing plate, offset copy, tip point, generic mesh
    fin_on_plate               vertical fins/rectangles/inverted fins standing on a plate: touching, tiny gap, penetrating, on grid lines, slightly leaning
    hinge_near_flat            two faces (or accordion strip) with dihedral pi-delta vs triangle/plate above or below the hinge, plane of the hinge, mirror copy
    hinge_near_fold            two faces with dihedral delta (nearly folded) vs triangle in the bisector, point behind the hinge, copy, other fold
    zero_area_mix              dyadic grids with injected repeated-index, repeated-coordinate, mid-edge and extended collinear triangles
    duplicated_faces           meshes with duplicated / reversed / rotated faces and duplicated vertices vs identical, offset or retriangulated copy
    near_coincident_offset     generic mesh vs copy translated / scaled / rotated by 1e-15..1e-4 of its size (before or after placement)
    jittered_copy              generic mesh vs per-vertex jittered copy (random, partial, single axis, a few ulps)
    float32_rounded_copy       mesh far from the origin vs its float32-rounded copy (also both rounded, or retriangulated and rounded)
    decimal_rounded_copy       mesh vs copy rounded to 3..17 significant digits or fixed decimals
    vertex_on_face             tetrahedra/spikes/flat triangles touching a plate exactly at face interior, edge interior or vertex, or 2^-k above/below
    edge_on_edge               exact edge contacts: crossing edges touching, collinear overlapping edges, parallel close edges, endpoint on edge, shared edge
    fan_apex_equidistant       symmetric pyramid/flat fans (square, D4 octagon, float n-gon) vs point/square/segment/triangle on the symmetry axis
    vertex_ties                outward spikes whose tips are symmetric (axes, cube corners, tetra) vs point/triangle/segment at the centre or in a symmetry plane
    between_parallel_planes    geometry exactly midway between two parallel plates, or between four walls (tilted, near-mid and grid variants)
    mirror_symmetric           dyadic mesh vs its exact mirror image (gap, touching, straddling, 180deg turn) or a symmetric mesh vs a mesh in its mirror plane
    voronoi_boundary_points    triangles lying exactly on face/edge and edge/vertex Voronoi boundary planes of a triangle (single, coplanar pair, hinge)
    bisector_plane             triangles in the exact bisector plane of two faces (Pythagorean-triple wedges, shared or separated), near-bisector too
    high_valence_fan           fans of up to 30 triangles (planar, cone, nearly flat, exact square ring) vs point above apex, rotated fan, plate, tiny triangle
    tiny_next_to_huge          a unit triangle with 1e-12..1e-4 triangles attached at a vertex, on an edge, floating or as a fan vs huge/tiny counterparts
    collinear_chain            all-zero-area meshes of collinear triangles vs crossing plate, parallel/skew/same-line chains, surface containing the line
    point_collapsed            meshes of point triangles (i,i,i or three equal vertices) on vertices/edges/faces of, or above, another mesh
    nested_solids              tetra/octa/cube/icosa vs scaled, retriangulated, dual (octa tips on cube faces), inscribed tetra, tiny rotation or shift
    cube_interior_ties         cube (or open box) vs point/segment/triangles at the centre, in the x=y plane, on the body diagonal, mid-plane grid, near a face
    same_vertices_alt_topology same vertex set (dyadic, random or saddle heights) triangulated with different diagonals
    far_tiny_generic           tiny (1e-6..1e-2) generic meshes placed 1e5..1e6 from the origin vs other/offset/jittered meshes
    interpenetrating           plates pierced by triangles through a grid vertex, along a grid line, generically, interlocked triangles, piercing tetra
    lattice_soup               random triangles on a tiny integer lattice (shared vertices, collinear and coplanar coincidences galore)
    retessellated_sphere       sphere tessellations from octa/icosa subdivisions vs each other, rotated, or radius (1+eps)
"""

import math
import os
import random
import struct
import sys

MAX_TRI = 200
MAX_VALENCE = 30
MAX_ABS = 1.0e7

# ----------------------------------------------------------------------------
# small vector helpers
# ----------------------------------------------------------------------------


def vadd(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def vsub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def vmul(s, a):
    return (s * a[0], s * a[1], s * a[2])


def vdot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def vcross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def vnorm(a):
    return math.sqrt(vdot(a, a))


def vunit(a):
    n = vnorm(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def lerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t)


def matvec(m, p):
    return (m[0][0] * p[0] + m[0][1] * p[1] + m[0][2] * p[2],
            m[1][0] * p[0] + m[1][1] * p[1] + m[1][2] * p[2],
            m[2][0] * p[0] + m[2][1] * p[1] + m[2][2] * p[2])


IDENT = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


def quat_mat(w, x, y, z):
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def rand_rot(rng):
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return quat_mat(a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
                    b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3))


def axis_rot(axis, ang):
    ax = vunit(axis)
    s = math.sin(ang / 2)
    return quat_mat(math.cos(ang / 2), ax[0] * s, ax[1] * s, ax[2] * s)


def rand_unit(rng):
    while True:
        p = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        n = vnorm(p)
        if 0.1 < n <= 1.0:
            return vmul(1.0 / n, p)


def any_perp(d):
    """A vector perpendicular to d (integer-exact if d is integer)."""
    e = (1.0, 0.0, 0.0) if abs(d[0]) <= abs(d[1]) and abs(d[0]) <= abs(d[2]) else \
        ((0.0, 1.0, 0.0) if abs(d[1]) <= abs(d[2]) else (0.0, 0.0, 1.0))
    return vcross(d, e)


def logu(rng, lo, hi):
    return 10.0 ** rng.uniform(lo, hi)


def sgn(rng):
    return rng.choice((-1.0, 1.0))


def pow2(k):
    return math.ldexp(1.0, k)


def rdy(rng, lo, hi, bits=2):
    """random dyadic number k/2**bits in [lo, hi]"""
    q = 2 ** bits
    return (math.ceil(lo * q) + rng.randint(0, int(math.floor(hi * q) - math.ceil(lo * q)))) / q


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def ulp_move(x, k):
    """move x by k ulps away from zero (k may be negative)."""
    if x == 0.0 or k == 0:
        return x
    b = struct.unpack('<Q', struct.pack('<d', abs(x)))[0] + k
    if b <= 0:
        return 0.0
    return math.copysign(struct.unpack('<d', struct.pack('<Q', b))[0], x)


# ----------------------------------------------------------------------------
# mesh container
# ----------------------------------------------------------------------------


class Mesh:
    def __init__(self):
        self.v = []
        self.f = []
        self._idx = {}

    def add_v(self, p):
        q = (float(p[0]), float(p[1]), float(p[2]))
        self.v.append(q)
        self._idx.setdefault(q, len(self.v) - 1)
        return len(self.v) - 1

    def pt(self, p):
        q = (float(p[0]), float(p[1]), float(p[2]))
        i = self._idx.get(q)
        if i is None:
            self.v.append(q)
            i = len(self.v) - 1
            self._idx[q] = i
        return i

    def add_f(self, i, j, k):
        self.f.append((i, j, k))

    def tri(self, a, b, c, shared=True):
        g = self.pt if shared else self.add_v
        self.add_f(g(a), g(b), g(c))

    def extend(self, other):
        off = len(self.v)
        for p in other.v:
            self.add_v(p)
        self.f.extend((a + off, b + off, c + off) for (a, b, c) in other.f)

    def copy(self):
        m = Mesh()
        m.v = list(self.v)
        m.f = list(self.f)
        m._idx = dict(self._idx)
        return m

    def apply(self, fn):
        self.v = [tuple(float(c) for c in fn(p)) for p in self.v]
        self._reindex()

    def _reindex(self):
        self._idx = {}
        for i, p in enumerate(self.v):
            self._idx.setdefault(p, i)

    def compact(self):
        used = sorted(set(i for f in self.f for i in f))
        remap = dict((o, n) for n, o in enumerate(used))
        self.v = [tuple(c + 0.0 for c in self.v[o]) for o in used]
        self.f = [(remap[a], remap[b], remap[c]) for (a, b, c) in self.f]
        self._reindex()

    def edges(self):
        out = []
        for (a, b, c) in self.f:
            out.extend(((a, b), (b, c), (c, a)))
        return out


def point_tri(m, p, rng):
    """a zero-area triangle collapsed to one point"""
    if rng.random() < 0.5:
        i = m.pt(p)
        m.add_f(i, i, i)
    else:
        m.add_f(m.add_v(p), m.add_v(p), m.add_v(p))


def grid(m, xs, ys, z=0.0, diag='a', rng=None, zf=None, mapf=None):
    """grid over xs x ys; z constant or zf(i, j); diag in a,b,alt,altb,rand,x."""
    def P(x, y, zz):
        return mapf((x, y, zz)) if mapf else (x, y, zz)

    def Z(i, j):
        return zf(i, j) if zf else z
    idx = [[m.pt(P(xs[i], ys[j], Z(i, j))) for j in range(len(ys))] for i in range(len(xs))]
    for i in range(len(xs) - 1):
        for j in range(len(ys) - 1):
            a, b, c, d = idx[i][j], idx[i + 1][j], idx[i + 1][j + 1], idx[i][j + 1]
            mode = diag
            if diag == 'rand':
                mode = rng.choice('ab')
            elif diag == 'alt':
                mode = 'a' if (i + j) % 2 == 0 else 'b'
            elif diag == 'altb':
                mode = 'b' if (i + j) % 2 == 0 else 'a'
            if mode == 'a':
                m.add_f(a, b, c)
                m.add_f(a, c, d)
            elif mode == 'b':
                m.add_f(a, b, d)
                m.add_f(b, c, d)
            else:
                zc = (Z(i, j) + Z(i + 1, j) + Z(i + 1, j + 1) + Z(i, j + 1)) / 4
                e = m.pt(P((xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2, zc))
                m.add_f(a, b, e)
                m.add_f(b, c, e)
                m.add_f(c, d, e)
                m.add_f(d, a, e)
    return idx


FLIP = {'a': 'b', 'b': 'a', 'alt': 'altb', 'altb': 'alt'}


def irange(a, b):
    return [float(i) for i in range(a, b + 1)]


# ----------------------------------------------------------------------------
# solids and generic bases
# ----------------------------------------------------------------------------


def solid_vf(name, rng=None):
    if name == 'tetra':
        V = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
        F = [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]
    elif name == 'octa':
        V = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
        F = [(x, y, z) for x in (0, 1) for y in (2, 3) for z in (4, 5)]
    elif name == 'cube':
        V = [((i & 1) * 2 - 1, ((i >> 1) & 1) * 2 - 1, ((i >> 2) & 1) * 2 - 1) for i in range(8)]
        F = []
        for ax in range(3):
            o = [b for b in range(3) if b != ax]
            for side in (0, 1):
                q = []
                for (u, w) in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    q.append((side << ax) | (u << o[0]) | (w << o[1]))
                if rng is not None and rng.random() < 0.5:
                    F += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
                else:
                    F += [(q[0], q[1], q[3]), (q[1], q[2], q[3])]
    elif name == 'icosa':
        g = (1 + math.sqrt(5)) / 2
        V = []
        for s1 in (-1, 1):
            for s2 in (-1, 1):
                V += [(0, s1, s2 * g), (s1, s2 * g, 0), (s2 * g, 0, s1)]
        F = []
        n = len(V)

        def adj(i, j):
            return abs(vnorm(vsub(V[i], V[j])) - 2.0) < 1e-9
        for i in range(n):
            for j in range(i + 1, n):
                for k in range(j + 1, n):
                    if adj(i, j) and adj(j, k) and adj(i, k):
                        F.append((i, j, k))
    else:
        raise ValueError(name)
    V = [tuple(float(c) for c in p) for p in V]
    F2 = []
    for (a, b, c) in F:
        nrm = vcross(vsub(V[b], V[a]), vsub(V[c], V[a]))
        F2.append((a, b, c) if vdot(nrm, V[a]) > 0 else (a, c, b))
    return V, F2


def sphere_vf(name, level):
    V, F = solid_vf(name)
    V = [vunit(p) for p in V]
    for _ in range(level):
        cache = {}
        NF = []

        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in cache:
                V.append(vunit(vadd(V[i], V[j])))
                cache[key] = len(V) - 1
            return cache[key]
        for (a, b, c) in F:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            NF += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        F = NF
    return V, F


def add_vf(m, V, F, fn=None):
    ids = [m.pt(fn(p) if fn else p) for p in V]
    for (a, b, c) in F:
        m.add_f(ids[a], ids[b], ids[c])
    return ids


def base_generic(rng, kinds=None):
    k = rng.choice(kinds or ['bumpy_grid', 'bumpy_grid', 'solid', 'fan', 'strip', 'soup'])
    m = Mesh()
    if k == 'bumpy_grid':
        n, mm = rng.randint(1, 5), rng.randint(1, 5)
        amp = logu(rng, -3, 0)
        H = dict(((i, j), amp * rng.uniform(-1, 1)) for i in range(n + 1) for j in range(mm + 1))
        grid(m, [i / n for i in range(n + 1)], [j / mm for j in range(mm + 1)],
             diag=rng.choice(['a', 'b', 'alt', 'rand']), rng=rng, zf=lambda i, j: H[(i, j)])
    elif k == 'solid':
        name = rng.choice(['tetra', 'octa', 'cube', 'icosa'])
        V, F = solid_vf(name, rng)
        if rng.random() < 0.5:
            a = logu(rng, -3, -0.5)
            V = [vadd(p, vmul(a, rand_unit(rng))) for p in V]
        add_vf(m, V, F)
        k = 'solid_' + name
    elif k == 'fan':
        n = rng.randint(3, 14)
        closed = rng.random() < 0.6
        angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
        if not closed:
            angs = [a * rng.uniform(0.2, 0.9) for a in angs]
        ring = [m.pt((math.cos(a) * rng.uniform(0.3, 1), math.sin(a) * rng.uniform(0.3, 1),
                      rng.uniform(-0.3, 0.3))) for a in angs]
        c = m.pt((0.0, 0.0, rng.uniform(-0.5, 0.5)))
        for i in range(n if closed else n - 1):
            m.add_f(c, ring[i], ring[(i + 1) % n])
        k = 'fan_closed' if closed else 'fan_open'
    elif k == 'strip':
        n = rng.randint(2, 15)
        a, b, w = rng.uniform(0, 6), rng.uniform(0, 6), logu(rng, -2, -0.5)
        prev = None
        for i in range(n + 1):
            t = i / n
            c = (t, 0.3 * math.sin(a * t), 0.2 * math.cos(b * t))
            p, q = m.pt(vadd(c, (0, -w, 0))), m.pt(vadd(c, (0, w, 0.1 * w)))
            if prev:
                m.add_f(prev[0], p, q)
                m.add_f(prev[0], q, prev[1])
            prev = (p, q)
    else:
        nt = rng.randint(1, 10)
        last = None
        for _ in range(nt):
            pts = [tuple(rng.random() for _ in range(3)) for _ in range(3)]
            if last and rng.random() < 0.4:
                pts[0] = last
            m.tri(*pts)
            last = pts[rng.randint(0, 2)]
    return k, m


# ----------------------------------------------------------------------------
# placement
# ----------------------------------------------------------------------------


def bbox(meshes):
    pts = [p for m in meshes for p in m.v]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    return lo, hi


def place_generic(rng, meshes, P, size_exp=(-6.0, 6.0), far=None, rot=None):
    lo, hi = bbox(meshes)
    c = [(lo[i] + hi[i]) * 0.5 for i in range(3)]
    ext = max(hi[i] - lo[i] for i in range(3))
    if not ext > 0:
        ext = 1.0
    size = 10.0 ** rng.uniform(*size_exp)
    s = size / ext
    if rot is None:
        rot = rng.random() < 0.85
    R = rand_rot(rng) if rot else IDENT
    if far is None:
        far = rng.choice(['origin', 'near', 'far', 'far', 'far_axis'])
    if far == 'origin':
        T = (0.0, 0.0, 0.0)
    elif far == 'near':
        T = vmul(min(size * logu(rng, -1, 1.5), 1e6), rand_unit(rng))
    elif far == 'far_axis':
        T = [0.0, 0.0, 0.0]
        T[rng.randint(0, 2)] = sgn(rng) * logu(rng, 5, 6)
        T = tuple(T)
    else:
        T = tuple(sgn(rng) * logu(rng, 3, 6) for _ in range(3))
    for m in meshes:
        m.apply(lambda p: vadd(T, vmul(s, matvec(R, vsub(p, c)))))
    P['place'] = 'generic'
    P['size'] = size
    P['rot'] = int(bool(rot))
    P['far'] = far
    P['tmax'] = max(abs(t) for t in T)


def place_exact(rng, meshes, P, exp_range=(-20, 20), far=None):
    perm = [0, 1, 2]
    rng.shuffle(perm)
    sg = [sgn(rng) for _ in range(3)]
    M = max(abs(c) for m in meshes for p in m.v for c in p)
    if M == 0:
        M = 1.0
    e = rng.randint(*exp_range)
    k = e - math.frexp(M)[1]
    s = pow2(k)
    for m in meshes:
        m.apply(lambda p: (sg[0] * s * p[perm[0]], sg[1] * s * p[perm[1]], sg[2] * s * p[perm[2]]))
    D = 1
    for m in meshes:
        for p in m.v:
            for c in p:
                den = c.as_integer_ratio()[1]
                if den > D:
                    D = den
    if far is None:
        far = rng.choice(['origin', 'near', 'far', 'far'])
    T = [0.0, 0.0, 0.0]
    if far != 'origin' and D <= 2 ** 60:
        N = max(abs(c) for m in meshes for p in m.v for c in p) * D
        for i in range(3):
            if far == 'far':
                target = sgn(rng) * logu(rng, 3, 6)
            else:
                target = sgn(rng) * M * s * logu(rng, -1, 1)
            n = int(round(target * D))
            while n != 0 and abs(n) + N >= 2 ** 53:
                n = int(n / 2)
            T[i] = n / D
        for m in meshes:
            m.apply(lambda p: (p[0] + T[0], p[1] + T[1], p[2] + T[2]))
    P['place'] = 'exact'
    P['perm'] = ''.join(str(i) for i in perm)
    P['signs'] = ''.join('+' if x > 0 else '-' for x in sg)
    P['scale'] = '2^%d' % k
    P['far'] = far
    P['tmax'] = max(abs(t) for t in T)


def place(rng, meshes, P, p_exact=0.7):
    if rng.random() < p_exact:
        place_exact(rng, meshes, P)
    else:
        place_generic(rng, meshes, P)


# ----------------------------------------------------------------------------
# kinds
# ----------------------------------------------------------------------------


def k_coplanar_retriangulation(rng):
    var = rng.choice(['flip', 'refine', 'coarse', 'centre_fan', 'random_diag',
                      'centre_split', 'corner_fan'])
    W, H = rng.randint(1, 5), rng.randint(1, 5)
    if var in ('refine', 'centre_split'):
        W, H = min(W, 3), min(H, 3)
    xs, ys = irange(0, W), irange(0, H)
    dA = rng.choice(['a', 'b', 'alt', 'altb'])
    A, B = Mesh(), Mesh()
    grid(A, xs, ys, 0.0, dA, rng)
    if var == 'flip':
        grid(B, xs, ys, 0.0, FLIP[dA], rng)
    elif var == 'refine':
        grid(B, [i / 2 for i in range(2 * W + 1)], [j / 2 for j in range(2 * H + 1)], 0.0,
             rng.choice(['a', 'b', 'alt', 'rand']), rng)
    elif var == 'coarse':
        grid(B, [0.0, float(W)], [0.0, float(H)], 0.0, rng.choice('ab'), rng)
    elif var in ('centre_fan', 'corner_fan'):
        bd = [(i, 0) for i in range(W)] + [(W, j) for j in range(H)] + \
             [(i, H) for i in range(W, 0, -1)] + [(0, j) for j in range(H, 0, -1)]
        ids = [B.pt((float(x), float(y), 0.0)) for (x, y) in bd]
        if var == 'centre_fan':
            c = B.pt((W / 2, H / 2, 0.0))
            for i in range(len(ids)):
                B.add_f(c, ids[i], ids[(i + 1) % len(ids)])
        else:
            # fan from corner (0,0) over the far boundary (long thin triangles)
            for i in range(W, len(ids) - H - 1):
                B.add_f(ids[0], ids[i], ids[i + 1])
    elif var == 'random_diag':
        grid(B, xs, ys, 0.0, 'rand', rng)
    else:
        grid(B, xs, ys, 0.0, 'x', rng)
    P = {'variant': var, 'W': W, 'H': H, 'diagA': dA}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_coplanar_partial_overlap(rng):
    var = rng.choice(['int_shift', 'half_shift', 'dyadic_tiny_shift', 'random_shift',
                      'rot45', 'random_rot', 'third_cells'])
    W, H = rng.randint(1, 4), rng.randint(1, 4)
    W2, H2 = rng.randint(1, 4), rng.randint(1, 4)
    A, B = Mesh(), Mesh()
    grid(A, irange(0, W), irange(0, H), 0.0, rng.choice(['a', 'b', 'alt', 'rand']), rng)
    dB = rng.choice(['a', 'b', 'alt', 'rand'])
    P = {'variant': var, 'W': W, 'H': H, 'W2': W2, 'H2': H2}
    if var == 'third_cells':
        W2, H2 = min(W2, 2), min(H2, 2)
        grid(B, [i / 3 for i in range(3 * W2 + 1)], [j / 3 for j in range(3 * H2 + 1)], 0.0, dB, rng)
    elif var in ('rot45', 'random_rot'):
        cx, cy = rdy(rng, 0, W, 1), rdy(rng, 0, H, 1)
        if var == 'rot45':
            def mp(p):
                return (cx + (p[0] - p[1]) / 2, cy + (p[0] + p[1]) / 2, 0.0)
        else:
            ang = rng.uniform(0, 2 * math.pi)
            ca, sa = math.cos(ang), math.sin(ang)
            P['angle'] = ang

            def mp(p):
                x, y = p[0] - W2 / 2, p[1] - H2 / 2
                return (cx + ca * x - sa * y, cy + sa * x + ca * y, 0.0)
        grid(B, irange(0, W2), irange(0, H2), 0.0, dB, rng, mapf=mp)
    else:
        if var == 'int_shift':
            dx, dy = float(rng.randint(-W2, W)), float(rng.randint(-H2, H))
        elif var == 'half_shift':
            dx, dy = rng.randint(-2 * W2, 2 * W) / 2, rng.randint(-2 * H2, 2 * H) / 2
        elif var == 'dyadic_tiny_shift':
            dx = sgn(rng) * rng.randint(1, 3) * pow2(-rng.randint(10, 50))
            dy = rng.choice([0.0, sgn(rng) * pow2(-rng.randint(10, 50))])
        else:
            dx, dy = rng.uniform(-W2, W), rng.uniform(-H2, H)
        P['dx'], P['dy'] = dx, dy
        grid(B, [dx + i for i in range(W2 + 1)], [dy + j for j in range(H2 + 1)], 0.0, dB, rng)
    place(rng, [A, B], P, 0.7)
    return P, A, B


def quadtree(m, x0, y0, size, depth, maxd, p, rng, diag):
    if depth < maxd and rng.random() < p:
        h = size / 2
        for (ox, oy) in ((0, 0), (h, 0), (0, h), (h, h)):
            quadtree(m, x0 + ox, y0 + oy, h, depth + 1, maxd, p, rng, diag)
    else:
        a, b = m.pt((x0, y0, 0.0)), m.pt((x0 + size, y0, 0.0))
        c, d = m.pt((x0 + size, y0 + size, 0.0)), m.pt((x0, y0 + size, 0.0))
        mode = rng.choice('ab') if diag == 'rand' else diag
        if mode == 'a':
            m.add_f(a, b, c)
            m.add_f(a, c, d)
        else:
            m.add_f(a, b, d)
            m.add_f(b, c, d)


def k_coplanar_t_junction(rng):
    var = rng.choice(['quadtree_vs_quadtree', 'quadtree_vs_grid', 'quadtree_lifted', 'edge_points'])
    A, B = Mesh(), Mesh()
    P = {'variant': var}
    if var == 'edge_points':
        corners = [(0.0, 0.0), (8.0, 0.0), (0.0, 8.0)]
        if rng.random() < 0.5:
            A.tri(*[(x, y, 0.0) for (x, y) in corners])
        else:
            mid = (float(rng.randint(1, 7)), 0.0, 0.0)
            A.tri((0.0, 0.0, 0.0), mid, (0.0, 8.0, 0.0))
            A.tri(mid, (8.0, 0.0, 0.0), (0.0, 8.0, 0.0))
        bd = []
        for e in range(3):
            p, q = corners[e], corners[(e + 1) % 3]
            bd.append(p)
            ts = sorted(set(rng.randint(1, 15) / 16 for _ in range(rng.randint(0, 5))))
            bd += [(p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t) for t in ts]
        ids = [B.pt((x, y, 0.0)) for (x, y) in bd]
        if rng.random() < 0.7:
            c = B.pt((rdy(rng, 1, 3, 1), rdy(rng, 1, 3, 1), 0.0))
            P['centre'] = 'interior'
            for i in range(len(ids)):
                B.add_f(c, ids[i], ids[(i + 1) % len(ids)])
        else:
            # fan from a boundary point: produces collinear zero-area triangles
            k0 = rng.randint(0, len(ids) - 1)
            P['centre'] = 'boundary'
            for i in range(len(ids)):
                if i != k0 and (i + 1) % len(ids) != k0:
                    B.add_f(ids[k0], ids[i], ids[(i + 1) % len(ids)])
    else:
        maxd = rng.randint(1, 3)
        p = rng.uniform(0.3, 0.7)
        quadtree(A, 0.0, 0.0, 4.0, 0, maxd, p, rng, rng.choice(['a', 'b', 'rand']))
        if var == 'quadtree_vs_quadtree':
            quadtree(B, 0.0, 0.0, 4.0, 0, maxd, p, rng, rng.choice(['a', 'b', 'rand']))
        elif var == 'quadtree_vs_grid':
            n = rng.choice([1, 2, 4])
            grid(B, [4.0 * i / n for i in range(n + 1)], [4.0 * i / n for i in range(n + 1)],
                 0.0, rng.choice(['a', 'b', 'alt', 'rand']), rng)
        else:
            dz = rng.choice([pow2(-rng.randint(3, 50)), logu(rng, -15, -3)]) * sgn(rng)
            P['dz'] = dz
            quadtree(B, 0.0, 0.0, 4.0, 0, maxd, p, rng, rng.choice(['a', 'b', 'rand']))
            B.apply(lambda q: (q[0], q[1], q[2] + dz))
        P['maxdepth'] = maxd
    place(rng, [A, B], P, 0.7)
    return P, A, B


def k_tilted_grid(rng):
    var = rng.choice(['centre_axis', 'edge_hinge', 'corner_axis', 'offset_axis'])
    tv = rng.choice(['same', 'flip', 'refine', 'coarse'])
    n, m = rng.randint(1, 5), rng.randint(1, 5)
    dA = rng.choice(['a', 'b', 'alt', 'altb'])
    A, B = Mesh(), Mesh()
    grid(A, irange(0, n), irange(0, m), 0.0, dA, rng)
    if tv == 'same':
        grid(B, irange(0, n), irange(0, m), 0.0, dA, rng)
    elif tv == 'flip':
        grid(B, irange(0, n), irange(0, m), 0.0, FLIP[dA], rng)
    elif tv == 'refine' and n <= 3 and m <= 3:
        grid(B, [i / 2 for i in range(2 * n + 1)], [j / 2 for j in range(2 * m + 1)], 0.0, 'rand', rng)
    else:
        tv = 'coarse'
        grid(B, [0.0, float(n)], [0.0, float(m)], 0.0, rng.choice('ab'), rng)
    theta = logu(rng, -12, -3) * sgn(rng)
    ang = rng.choice([0.0, math.pi / 2, math.pi / 4, rng.uniform(0, math.pi)])
    axis = (math.cos(ang), math.sin(ang), 0.0)
    if var == 'centre_axis':
        c = (n / 2, m / 2, 0.0)
    elif var == 'edge_hinge':
        axis, c = (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    elif var == 'corner_axis':
        c = (0.0, 0.0, 0.0)
    else:
        c = (rng.uniform(0, n), rng.uniform(0, m), sgn(rng) * logu(rng, -12, -4))
    R = axis_rot(axis, theta)
    B.apply(lambda p: vadd(c, matvec(R, vsub(p, c))))
    P = {'variant': var, 'tri': tv, 'theta': theta, 'n': n, 'm': m}
    place(rng, [A, B], P, 0.3)
    return P, A, B


def k_parallel_offset_planes(rng):
    var = rng.choice(['same_tri', 'flipped_tri', 'shifted_tri', 'inner_patch',
                      'alternating_sides', 'refined'])
    n, m = rng.randint(1, 4), rng.randint(1, 4)
    if rng.random() < 0.5:
        d = pow2(-rng.randint(2, 50))
    else:
        d = logu(rng, -15, -3) * max(n, m)
    d *= sgn(rng)
    dA = rng.choice(['a', 'b', 'alt', 'altb'])
    A, B = Mesh(), Mesh()
    grid(A, irange(0, n), irange(0, m), 0.0, dA, rng)
    if var == 'same_tri':
        grid(B, irange(0, n), irange(0, m), d, dA, rng)
    elif var == 'flipped_tri':
        grid(B, irange(0, n), irange(0, m), d, FLIP[dA], rng)
    elif var == 'shifted_tri':
        sx, sy = rng.randint(-2, 2) / 2, rng.randint(-2, 2) / 2
        grid(B, [sx + i for i in range(n + 1)], [sy + j for j in range(m + 1)], d, 'rand', rng)
    elif var == 'inner_patch':
        x0 = rdy(rng, 0, n / 2, 2)
        x1 = rdy(rng, x0 + 0.25, n, 2)
        y0 = rdy(rng, 0, m / 2, 2)
        y1 = rdy(rng, y0 + 0.25, m, 2)
        k = rng.randint(1, 3)
        grid(B, [x0 + (x1 - x0) * i / k for i in range(k + 1)],
             [y0 + (y1 - y0) * j / k for j in range(k + 1)], d, 'rand', rng)
    elif var == 'alternating_sides':
        for i in range(n):
            for j in range(m):
                zz = d * sgn(rng)
                a, b = B.add_v((i, j, zz)), B.add_v((i + 1, j, zz))
                c, e = B.add_v((i + 1, j + 1, zz)), B.add_v((i, j + 1, zz))
                B.add_f(a, b, c)
                B.add_f(a, c, e)
    else:
        n, m = min(n, 3), min(m, 3)
        grid(B, [i / 2 for i in range(2 * n + 1)], [j / 2 for j in range(2 * m + 1)], d, 'rand', rng)
    P = {'variant': var, 'offset': d, 'n': n, 'm': m}
    place(rng, [A, B], P, 0.6)
    return P, A, B


def sliver_strip(m, n, h):
    bot = [m.pt((i / n, 0.0, 0.0)) for i in range(n + 1)]
    top = [m.pt(((i + 0.5) / n, h, 0.0)) for i in range(n)]
    for i in range(n):
        m.add_f(bot[i], bot[i + 1], top[i])
        if i + 1 < n:
            m.add_f(top[i], bot[i + 1], top[i + 1])


def k_sliver_triangles(rng):
    var = rng.choice(['strip', 'book', 'obtuse_set', 'single'])
    bv = rng.choice(['plate', 'cross_sliver', 'point_above', 'twin'])
    h = logu(rng, -12, -6)
    A, B = Mesh(), Mesh()
    P = {'variant': var, 'b': bv, 'h': h}
    if var == 'strip':
        n = rng.randint(2, 20)
        sliver_strip(A, n, h)
        P['n'] = n
    elif var == 'book':
        k = rng.randint(2, 8)
        for _ in range(k):
            phi = rng.uniform(0, 2 * math.pi)
            t = rng.choice([0.5, rng.random()])
            A.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (t, h * math.cos(phi), h * math.sin(phi)))
    elif var == 'obtuse_set':
        k = rng.randint(1, 6)
        for _ in range(k):
            t = rng.choice([-2.0, -0.5, 1.5, 3.0, rng.uniform(-3, 4)])
            phi = rng.uniform(0, 2 * math.pi)
            A.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (t, h * math.cos(phi), h * math.sin(phi)),
                  shared=rng.random() < 0.5)
    else:
        t = rng.choice([0.0, 0.5, 1.0, -1.0, 2.0, rng.random()])
        A.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (t, h, 0.0))
        P['t'] = t
    g = rng.choice([0.0, logu(rng, -12, -3), h * rng.uniform(0.5, 2)]) * sgn(rng)
    P['gap'] = g
    if bv == 'plate':
        grid(B, [-0.5, 0.5, 1.5], [-0.5, 0.5], g, rng.choice(['a', 'b', 'alt']), rng)
    elif bv == 'cross_sliver':
        h2 = logu(rng, -12, -6)
        B.tri((0.5, -0.5, g), (0.5, 0.5, g), (0.5 + h2, rng.choice([0.0, rng.uniform(-.5, .5)]), g))
    elif bv == 'point_above':
        s = logu(rng, -12, -3)
        c = (rng.choice([0.5, rng.random()]), 0.0, g)
        if rng.random() < 0.5:
            point_tri(B, c, rng)
        else:
            B.tri(vadd(c, (-s, -s, 0)), vadd(c, (s, -s, 0)), vadd(c, (0, s, 0)))
    else:
        h2 = h * rng.uniform(0.25, 4)
        if var == 'strip':
            sliver_strip(B, rng.randint(2, 20), h2)
        else:
            B.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (rng.random(), h2, 0.0))
    place(rng, [A, B], P, 0.35)
    return P, A, B


def k_needle_triangles(rng):
    var = rng.choice(['fan', 'cone', 'pair'])
    bv = rng.choice(['perp_plate', 'offset_copy', 'tip_point', 'generic'])
    w = logu(rng, -12, -6)
    A, B = Mesh(), Mesh()
    P = {'variant': var, 'b': bv, 'w': w}
    O = (0.0, 0.0, 0.0)
    if var == 'fan':
        k = rng.randint(1, 12)
        for _ in range(k):
            d = rand_unit(rng)
            d = (d[0], d[1], abs(d[2]) + 0.2)
            d = vunit(d)
            u = vunit(any_perp(d))
            A.tri(O, vadd(d, vmul(w / 2, u)), vadd(d, vmul(-w / 2, u)))
    elif var == 'cone':
        n = rng.randint(3, 30)
        ring = [A.pt((w * math.cos(2 * math.pi * i / n), w * math.sin(2 * math.pi * i / n), 1.0))
                for i in range(n)]
        o = A.pt(O)
        for i in range(n):
            A.add_f(o, ring[i], ring[(i + 1) % n])
        if rng.random() < 0.4:
            c = A.pt((0.0, 0.0, 1.0))
            for i in range(n):
                A.add_f(c, ring[(i + 1) % n], ring[i])
        P['n'] = n
    else:
        phi = rng.choice([math.pi / 2, math.pi, rng.uniform(0, 2 * math.pi), logu(rng, -9, -2)])
        A.tri(O, (0.0, 0.0, 1.0), (w, 0.0, 1.0))
        A.tri(O, (0.0, 0.0, 1.0), (w * math.cos(phi), w * math.sin(phi), 1.0))
    if bv == 'perp_plate':
        zc = rng.choice([0.5, 1.0, 1.0 - w / 2, rng.random()])
        grid(B, [-1.0, 0.0, 1.0], [-1.0, 0.0, 1.0], zc, rng.choice(['a', 'b', 'alt']), rng)
    elif bv == 'offset_copy':
        off = vmul(w * logu(rng, -3, 1), rand_unit(rng))
        B = A.copy()
        B.apply(lambda p: vadd(p, off))
    elif bv == 'tip_point':
        s = w * logu(rng, -2, 2)
        c = (0.0, 0.0, 1.0 + rng.choice([0.0, s]))
        B.tri(c, vadd(c, (s, 0, s)), vadd(c, (0, s, s)))
    else:
        _, B = base_generic(rng)
    place(rng, [A, B], P, 0.3)
    return P, A, B


def k_fin_on_plate(rng):
    n = rng.randint(1, 3)
    A, B = Mesh(), Mesh()
    grid(A, irange(-n, n), irange(-n, n), 0.0, rng.choice(['a', 'b', 'alt', 'altb', 'rand']), rng)
    nf = rng.randint(1, 4)
    kinds = []
    for _ in range(nf):
        orient = rng.choice(['x', 'y', 'diag'])
        pos = rng.choice(['grid_line', 'mid', 'dyadic'])
        c = float(rng.randint(-n, n)) if pos == 'grid_line' else \
            (rng.randint(-n, n - 1) + 0.5 if pos == 'mid' else rdy(rng, -n, n, 5))
        gt = rng.choice(['touch', 'touch', 'gap', 'pen', 'float'])
        g = {'touch': 0.0, 'gap': pow2(-rng.randint(3, 50)), 'pen': -pow2(-rng.randint(3, 50)),
             'float': sgn(rng) * logu(rng, -12, -3)}[gt]
        shape = rng.choice(['tri_up', 'rect', 'tip_down'])
        u0 = rng.randint(-2 * n - 2, 2 * n) / 2
        u1 = u0 + rng.randint(1, 4) / 2
        Hh = rng.choice([0.5, 1.0, 2.0])
        lean = sgn(rng) * logu(rng, -12, -3) if rng.random() < 0.2 else 0.0
        if shape == 'tri_up':
            loc = [[(u0, 0.0, g), (u1, 0.0, g), ((u0 + u1) / 2, lean, g + Hh)]]
        elif shape == 'rect':
            loc = [[(u0, 0.0, g), (u1, 0.0, g), (u1, lean, g + Hh)],
                   [(u0, 0.0, g), (u1, lean, g + Hh), (u0, lean, g + Hh)]]
        else:
            um = rng.choice([(u0 + u1) / 2, u0])
            loc = [[(um, 0.0, g), (u1, lean, g + Hh), (u0, lean, g + Hh)]]

        def mp(q):
            u, w, z = q
            if orient == 'x':
                return (u, c + w, z)
            if orient == 'y':
                return (c + w, u, z)
            return (u + c + w, u - w, z)
        fin = Mesh()
        for t in loc:
            fin.tri(*[mp(q) for q in t])
        B.extend(fin)
        kinds.append(orient[0] + shape[0] + gt[0])
    P = {'fins': '-'.join(kinds), 'n': n}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_hinge_near_flat(rng):
    bv = rng.choice(['above_hinge', 'plate', 'below', 'on_hinge_plane', 'mirror', 'point_on_line'])
    multi = rng.random() < 0.4
    delta = logu(rng, -12, -2) * sgn(rng)
    A, B = Mesh(), Mesh()
    if multi:
        k = rng.randint(2, 6)
        zs = [0.0 if i % 2 == 0 else delta * rng.uniform(0.5, 2) for i in range(k + 1)]
        xs = [i - k / 2 for i in range(k + 1)]
        rows = [[A.pt((xs[i], y, zs[i])) for i in range(k + 1)] for y in (-1.0, 1.0)]
        for i in range(k):
            a, b, c, d = rows[0][i], rows[0][i + 1], rows[1][i + 1], rows[1][i]
            if rng.random() < 0.5:
                A.add_f(a, b, c)
                A.add_f(a, c, d)
            else:
                A.add_f(a, b, d)
                A.add_f(b, c, d)
    else:
        y1, y2 = rdy(rng, -1, 1, 2), rdy(rng, -1, 1, 2)
        e0, e1 = A.pt((0.0, -1.0, 0.0)), A.pt((0.0, 1.0, 0.0))
        w1 = A.pt((-1.0, y1, 0.0))
        w2 = A.pt((math.cos(delta), y2, math.sin(delta)))
        A.add_f(e0, e1, w1)
        A.add_f(e1, e0, w2)
    h = logu(rng, -9, 0)
    s = rng.choice([0.25, 0.5, logu(rng, -6, -1)])
    if bv in ('above_hinge', 'below'):
        z = h if bv == 'above_hinge' else -h
        B.tri((-s, -s, z), (s, -s, z), (0.0, s, z))
    elif bv == 'plate':
        grid(B, [-1.0, 0.0, 1.0], [-1.0, 0.0, 1.0], h * sgn(rng), rng.choice(['a', 'b', 'alt']), rng)
    elif bv == 'on_hinge_plane':
        B.tri((0.0, -0.5, h), (0.0, 0.5, h), (0.0, 0.0, h + rng.choice([1.0, s])))
    elif bv == 'mirror':
        B = A.copy()
        B.apply(lambda p: (p[0], p[1], -p[2]))
    else:
        point_tri(B, (0.0, rdy(rng, -1, 1, 2), h * sgn(rng)), rng)
    P = {'b': bv, 'multi': int(multi), 'delta': delta, 'h': h}
    place(rng, [A, B], P, 0.35)
    return P, A, B


def k_hinge_near_fold(rng):
    bv = rng.choice(['inside_bisector', 'beyond_edge', 'above', 'flat_copy', 'other_fold'])
    delta = logu(rng, -12, -2)
    y1, y2 = rdy(rng, -1, 1, 2), rdy(rng, -1, 1, 2)
    if rng.random() < 0.3:
        y2 = y1

    def fold(m, d, wa=1.0):
        e0, e1 = m.pt((0.0, -1.0, 0.0)), m.pt((0.0, 1.0, 0.0))
        m.add_f(e0, e1, m.pt((wa, y1, 0.0)))
        m.add_f(e1, e0, m.pt((wa * math.cos(d), y2, wa * math.sin(d))))
    A, B = Mesh(), Mesh()
    fold(A, delta)
    if bv == 'inside_bisector':
        hb = delta / 2
        r0, r1 = sorted((rng.uniform(0.05, 0.9), rng.uniform(0.05, 0.9)))
        r1 = max(r1, r0 + 0.05)
        B.tri((r0 * math.cos(hb), -0.3, r0 * math.sin(hb)), (r1 * math.cos(hb), -0.3, r1 * math.sin(hb)),
              ((r0 + r1) / 2 * math.cos(hb), 0.3, (r0 + r1) / 2 * math.sin(hb)))
    elif bv == 'beyond_edge':
        g = logu(rng, -9, 0)
        if rng.random() < 0.5:
            point_tri(B, (-g, 0.0, 0.0), rng)
        else:
            B.tri((-g, -0.5, 0.0), (-g, 0.5, 0.0), (-2 * g, 0.0, delta * g))
    elif bv == 'above':
        g = logu(rng, -12, -1)
        sd, cd = math.sin(delta), math.cos(delta)
        nrm = (-sd, 0.0, cd)
        B.tri(vadd((0.2 * cd, -0.2, 0.2 * sd), vmul(g, nrm)), vadd((0.6 * cd, -0.2, 0.6 * sd), vmul(g, nrm)),
              vadd((0.4 * cd, 0.3, 0.4 * sd), vmul(g, nrm)))
    elif bv == 'flat_copy':
        B.tri((0.0, -1.0, 0.0), (0.0, 1.0, 0.0), (1.0, y1, 0.0))
        if rng.random() < 0.5:
            B.tri((0.0, 1.0, 0.0), (0.0, -1.0, 0.0), (math.cos(delta * 2), y2, math.sin(delta * 2)))
    else:
        fold(B, delta * rng.uniform(0.25, 4), rng.choice([1.0, 0.5, 2.0]))
    P = {'b': bv, 'delta': delta}
    place(rng, [A, B], P, 0.3)
    return P, A, B


def inject_degenerate(m, rng, r):
    nf = len(m.f)
    tags = []
    for _ in range(r):
        t = rng.choice(['rep_idx', 'triple_idx', 'dup_coord', 'dup_coord_all', 'mid_edge',
                        'extended', 'quarter_points'])
        f = m.f[rng.randint(0, nf - 1)]
        i, j = rng.sample(f, 2)
        if t == 'rep_idx':
            m.add_f(*rng.choice([(i, i, j), (i, j, i), (j, i, i)]))
        elif t == 'triple_idx':
            m.add_f(i, i, i)
        elif t == 'dup_coord':
            m.add_f(i, j, m.add_v(m.v[i]))
        elif t == 'dup_coord_all':
            m.add_f(m.add_v(m.v[i]), m.add_v(m.v[i]), m.add_v(m.v[i]))
        elif t == 'mid_edge':
            m.add_f(i, m.add_v(lerp(m.v[i], m.v[j], 0.5)), j)
        elif t == 'extended':
            m.add_f(i, j, m.add_v(lerp(m.v[i], m.v[j], 2.0)))
        else:
            m.add_f(i, m.add_v(lerp(m.v[i], m.v[j], 0.25)), m.add_v(lerp(m.v[i], m.v[j], 0.75)))
        tags.append(t)
    return tags


def k_zero_area_mix(rng):
    n, m = rng.randint(1, 4), rng.randint(1, 4)
    bumpy = rng.random() < 0.5
    Z = dict(((i, j), rng.choice([0.0, 0.5, 1.0, -0.5]) if bumpy else 0.0)
             for i in range(n + 1) for j in range(m + 1))
    A, B = Mesh(), Mesh()
    grid(A, irange(0, n), irange(0, m), 0.0, rng.choice(['a', 'b', 'alt', 'rand']), rng,
         zf=lambda i, j: Z[(i, j)])
    bv = rng.choice(['same_surface', 'shifted', 'lifted'])
    dz = {'same_surface': 0.0, 'shifted': 0.0, 'lifted': rng.choice([0.25, pow2(-rng.randint(5, 50))])}[bv]
    sh = 0.5 if bv == 'shifted' else 0.0
    if bv == 'shifted':
        grid(B, [sh + i for i in range(n)], [sh + j for j in range(m)] or [0.0], dz, 'rand', rng)
        if not B.f:
            grid(B, [0.5, 1.5], [0.5, 1.5], 0.25, 'a', rng)
    else:
        grid(B, irange(0, n), irange(0, m), 0.0, 'rand', rng, zf=lambda i, j: Z[(i, j)] + dz)
    ta = inject_degenerate(A, rng, rng.randint(1, 8))
    tb = inject_degenerate(B, rng, rng.randint(1, 6)) if rng.random() < 0.5 else []
    P = {'b': bv, 'bumpy': int(bumpy), 'degA': '-'.join(ta) or 'none', 'degB': '-'.join(tb) or 'none'}
    place(rng, [A, B], P, 0.6)
    return P, A, B


def duplicate_faces(m, rng, r):
    nf = len(m.f)
    tags = []
    for _ in range(r):
        a, b, c = m.f[rng.randint(0, nf - 1)]
        t = rng.choice(['same', 'reversed', 'rotated', 'dup_verts', 'triple'])
        if t == 'same':
            m.add_f(a, b, c)
        elif t == 'reversed':
            m.add_f(b, a, c)
        elif t == 'rotated':
            m.add_f(b, c, a)
        elif t == 'dup_verts':
            m.add_f(m.add_v(m.v[a]), m.add_v(m.v[b]), m.add_v(m.v[c]))
        else:
            m.add_f(a, b, c)
            m.add_f(c, b, a)
        tags.append(t)
    return tags


def k_duplicated_faces(rng):
    base = rng.choice(['grid', 'tetra', 'octa', 'cube'])
    bv = rng.choice(['identical', 'offset', 'retri', 'duplicated_too'])
    dg = rng.choice(['a', 'b', 'alt'])
    n, m = rng.randint(1, 3), rng.randint(1, 3)
    Z = dict(((i, j), rng.choice([0.0, 0.5, 1.0])) for i in range(n + 1) for j in range(m + 1))
    cube_seed = rng.getrandbits(32)

    def build(flip=False):
        M = Mesh()
        if base == 'grid':
            grid(M, irange(0, n), irange(0, m), 0.0, FLIP[dg] if flip else dg, rng, zf=lambda i, j: Z[(i, j)])
        else:
            V, F = solid_vf(base, random.Random(cube_seed + (1 if flip else 0)))
            add_vf(M, V, F)
        return M
    A = build()
    tags = duplicate_faces(A, rng, rng.randint(1, 6))
    if bv == 'identical':
        B = build()
    elif bv == 'offset':
        B = build()
        off = rng.choice([pow2(-rng.randint(5, 50)), logu(rng, -15, -3)])
        B.apply(lambda p: (p[0], p[1], p[2] + off))
    elif bv == 'retri':
        B = build(True)
    else:
        B = build()
        duplicate_faces(B, rng, rng.randint(1, 6))
    P = {'base': base, 'b': bv, 'dups': '-'.join(tags)}
    place(rng, [A, B], P, 0.6)
    return P, A, B


def k_near_coincident_offset(rng):
    var = rng.choice(['translate_random', 'translate_axis', 'translate_z', 'scale_centroid', 'rotate_tiny'])
    when = rng.choice(['before', 'after'])
    eps = logu(rng, -15, -4)
    bk, A = base_generic(rng)
    P = {'base': bk, 'variant': var, 'eps': eps, 'when': when}

    def derive(A):
        lo, hi = bbox([A])
        size = max(hi[i] - lo[i] for i in range(3)) or 1.0
        c = tuple((lo[i] + hi[i]) / 2 for i in range(3))
        B = A.copy()
        if var == 'translate_random':
            d = vmul(eps * size, rand_unit(rng))
            B.apply(lambda p: vadd(p, d))
        elif var == 'translate_axis':
            d = [0.0, 0.0, 0.0]
            d[rng.randint(0, 2)] = eps * size * sgn(rng)
            B.apply(lambda p: vadd(p, d))
        elif var == 'translate_z':
            B.apply(lambda p: (p[0], p[1], p[2] + eps * size))
        elif var == 'scale_centroid':
            f = 1.0 + eps * sgn(rng)
            B.apply(lambda p: vadd(c, vmul(f, vsub(p, c))))
        else:
            R = axis_rot(rand_unit(rng), eps)
            B.apply(lambda p: vadd(c, matvec(R, vsub(p, c))))
        return B
    if when == 'before':
        B = derive(A)
        place_generic(rng, [A, B], P)
    else:
        place_generic(rng, [A], P)
        B = derive(A)
    return P, A, B


def k_jittered_copy(rng):
    var = rng.choice(['random', 'partial', 'single_axis', 'ulps'])
    eps = logu(rng, -15, -4)
    bk, A = base_generic(rng)
    P = {'base': bk, 'variant': var, 'eps': eps}
    place_generic(rng, [A], P)
    lo, hi = bbox([A])
    size = max(hi[i] - lo[i] for i in range(3)) or 1.0
    B = A.copy()
    ax = rng.randint(0, 2)
    frac = rng.uniform(0.1, 0.9)
    newv = []
    for p in B.v:
        if var == 'random':
            newv.append(vadd(p, vmul(eps * size * rng.random(), rand_unit(rng))))
        elif var == 'partial':
            newv.append(vadd(p, vmul(eps * size, rand_unit(rng))) if rng.random() < frac else p)
        elif var == 'single_axis':
            q = list(p)
            q[ax] += eps * size * rng.uniform(-1, 1)
            newv.append(tuple(q))
        else:
            newv.append(tuple(ulp_move(c, rng.randint(-4, 4)) for c in p))
    B.v = newv
    B._reindex()
    return P, A, B


def k_float32_rounded_copy(rng):
    var = rng.choice(['copy_f32', 'both_f32_shift', 'retri_f32', 'a_f32_b_exact'])
    P = {'variant': var}
    if var == 'retri_f32':
        n, m = rng.randint(1, 5), rng.randint(1, 5)
        amp = logu(rng, -4, 0)
        Hh = dict(((i, j), amp * rng.uniform(-1, 1)) for i in range(n + 1) for j in range(m + 1))
        dA = rng.choice(['a', 'b', 'alt', 'altb'])
        A, B = Mesh(), Mesh()
        grid(A, [i / n for i in range(n + 1)], [j / m for j in range(m + 1)], 0.0, dA, rng, zf=lambda i, j: Hh[(i, j)])
        grid(B, [i / n for i in range(n + 1)], [j / m for j in range(m + 1)], 0.0, FLIP[dA], rng, zf=lambda i, j: Hh[(i, j)])
        P['base'] = 'bumpy_grid'
        place_generic(rng, [A, B], P, size_exp=(-4, 3), far=rng.choice(['far', 'far_axis']))
        B.apply(lambda p: tuple(f32(c) for c in p))
        return P, A, B
    bk, A = base_generic(rng)
    P['base'] = bk
    place_generic(rng, [A], P, size_exp=(-4, 3), far=rng.choice(['far', 'far_axis', 'near']))
    B = A.copy()
    if var == 'copy_f32':
        B.apply(lambda p: tuple(f32(c) for c in p))
    elif var == 'both_f32_shift':
        lo, hi = bbox([A])
        size = max(hi[i] - lo[i] for i in range(3)) or 1.0
        d = vmul(size * logu(rng, -9, -3), rand_unit(rng))
        A.apply(lambda p: tuple(f32(c) for c in p))
        B.apply(lambda p: tuple(f32(c) for c in vadd(p, d)))
    else:
        A.apply(lambda p: tuple(f32(c) for c in p))
    return P, A, B


def k_decimal_rounded_copy(rng):
    var = rng.choice(['significant', 'fixed'])
    bk, A = base_generic(rng)
    P = {'base': bk, 'variant': var}
    place_generic(rng, [A], P)
    lo, hi = bbox([A])
    size = max(hi[i] - lo[i] for i in range(3)) or 1.0
    B = A.copy()
    if var == 'significant':
        d = rng.randint(3, 17)
        fmt = '%.' + str(d - 1) + 'e'
        P['digits'] = d
    else:
        k = max(0, min(17, int(math.ceil(-math.log10(size))) + rng.randint(1, 8)))
        fmt = '%.' + str(k) + 'f'
        P['decimals'] = k
    B.apply(lambda p: tuple(float(fmt % c) for c in p))
    if rng.random() < 0.3:
        A, B = B, A.copy()
        B.apply(lambda p: tuple(float(fmt % c) if rng.random() < 0.5 else c for c in p))
        P['mixed'] = 1
    return P, A, B


BARY_INT = [(1, 1, 2), (1, 2, 1), (2, 1, 1), (1, 1, 6), (1, 3, 4), (2, 3, 3), (1, 1, 14), (5, 5, 6)]
BARY_EDGE = [(1, 1, 0), (1, 3, 0), (3, 1, 0), (1, 7, 0), (5, 3, 0)]


def bary(pts, w):
    s = float(sum(w))
    return tuple(sum(pts[i][k] * w[i] for i in range(3)) / s for k in range(3))


def k_vertex_on_face(rng):
    pv = rng.choice(['tri', 'grid'])
    A, B = Mesh(), Mesh()
    if pv == 'tri':
        A.tri((0.0, 0.0, 0.0), (8.0, 0.0, 0.0), (0.0, 8.0, 0.0))
    else:
        grid(A, irange(0, 4), irange(0, 4), 0.0, rng.choice(['a', 'b', 'alt', 'rand']), rng)
    tags = []
    for _ in range(rng.randint(1, 5)):
        f = A.f[rng.randint(0, len(A.f) - 1)]
        pts = [A.v[i] for i in f]
        ct = rng.choice(['interior', 'edge', 'vertex', 'near_above', 'near_below'])
        if ct in ('interior', 'near_above', 'near_below'):
            w = list(rng.choice(BARY_INT))
            rng.shuffle(w)
            c = bary(pts, w)
            if ct != 'interior':
                c = (c[0], c[1], pow2(-rng.randint(3, 50)) * (1 if ct == 'near_above' else -1))
        elif ct == 'edge':
            w = list(rng.choice(BARY_EDGE))
            rng.shuffle(w)
            c = bary(pts, w)
        else:
            c = pts[rng.randint(0, 2)]
        shape = rng.choice(['tetra', 'spike', 'flat_tri', 'edge_down'])
        Hh = rng.choice([0.5, 1.0, 2.0])

        def off(dx, dy, dz):
            return (c[0] + dx, c[1] + dy, c[2] + dz)
        q = Mesh()
        if shape == 'tetra':
            r = rng.choice([0.5, 1.0])
            p1, p2, p3 = off(r, 0, Hh), off(-r, r, Hh), off(-r, -r, Hh)
            q.tri(c, p1, p2)
            q.tri(c, p2, p3)
            q.tri(c, p3, p1)
            q.tri(p1, p3, p2)
        elif shape == 'spike':
            q.tri(c, off(rdy(rng, -1, 1), rdy(rng, -1, 1), Hh), off(rdy(rng, -1, 1), rdy(rng, -1, 1), Hh / 2))
        elif shape == 'flat_tri':
            q.tri(c, off(rdy(rng, -2, 2), rdy(rng, -2, 2), 0.0), off(rdy(rng, -2, 2), rdy(rng, -2, 2), 0.0))
        else:
            q.tri(c, off(rdy(rng, -2, 2), rdy(rng, -2, 2), 0.0), off(rdy(rng, -1, 1), rdy(rng, -1, 1), Hh))
        B.extend(q)
        tags.append(ct + ':' + shape)
    P = {'plate': pv, 'contacts': ','.join(tags)}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_edge_on_edge(rng):
    A, B = Mesh(), Mesh()
    tags = []
    dirs = [(-2.0, 0.0), (0.0, -2.0), (-1.0, -2.0), (1.0, -2.0), (-2.0, -2.0), (2.0, 1.0)]
    for ci in range(rng.randint(1, 4)):
        ox = 16.0 * ci
        cfg = rng.choice(['cross_touch', 'collinear_overlap', 'parallel_close', 'endpoint_on_edge', 'shared_edge'])
        g = rng.choice([0.0, 0.0, pow2(-rng.randint(3, 50)), -pow2(-rng.randint(3, 50))])
        ay, az = rng.choice(dirs)
        by, bz = rng.choice(dirs)
        if cfg == 'cross_touch':
            A.tri((ox - 2, 0.0, 0.0), (ox + 2, 0.0, 0.0), (ox + rdy(rng, -1, 1), ay, az))
            B.tri((ox, -2.0, g), (ox, 2.0, g), (ox + by, rdy(rng, -1, 1), g + bz))
        elif cfg == 'collinear_overlap':
            s = rng.choice([-2.0, 0.0, 1.0, 2.0, 4.0])
            L = rng.choice([1.0, 2.0, 4.0, 6.0])
            A.tri((ox, 0.0, 0.0), (ox + 4, 0.0, 0.0), (ox + 2, ay, az))
            B.tri((ox + s, 0.0, 0.0), (ox + s + L, 0.0, 0.0), (ox + s + L / 2, by, bz))
        elif cfg == 'parallel_close':
            gg = g if g != 0.0 else sgn(rng) * logu(rng, -15, -3)
            s = rng.choice([-2.0, 0.0, 1.0, 2.0])
            side = rng.choice([(gg, 0.0), (0.0, gg), (gg, gg)])
            A.tri((ox, 0.0, 0.0), (ox + 4, 0.0, 0.0), (ox + 2, ay, az))
            B.tri((ox + s, side[0], side[1]), (ox + s + 4, side[0], side[1]), (ox + s + 2, by, bz))
        elif cfg == 'endpoint_on_edge':
            t = rng.choice([1.0, 2.0, 3.0, 0.5, 0.0])
            A.tri((ox, 0.0, 0.0), (ox + 4, 0.0, 0.0), (ox + 2, ay, az))
            B.tri((ox + t, 0.0, g), (ox + t + rdy(rng, -1, 1), -by, -bz), (ox + t + rdy(rng, -1, 1), -by / 2 + 1, -bz + 1))
        else:
            A.tri((ox, 0.0, 0.0), (ox + 4, 0.0, 0.0), (ox + 2, ay, az))
            if rng.random() < 0.5:
                B.tri((ox, 0.0, 0.0), (ox + 4, 0.0, 0.0), (ox + rdy(rng, 0, 4), by, bz))
            else:
                B.tri((ox + 4, 0.0, 0.0), (ox, 0.0, 0.0), (ox + rdy(rng, 0, 4), by, bz))
        tags.append(cfg)
    P = {'configs': '-'.join(tags)}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_fan_apex_equidistant(rng):
    ring = rng.choice(['ring4', 'ring4_diag', 'ring8', 'ring8', 'ring_n_float'])
    av = rng.choice(['point', 'square', 'axis_segment', 'axis_plane_tri', 'fan_copy'])
    a = 2.0
    if ring == 'ring4':
        pts = [(a, 0.0), (0.0, a), (-a, 0.0), (0.0, -a)]
    elif ring == 'ring4_diag':
        pts = [(a, a), (-a, a), (-a, -a), (a, -a)]
    elif ring == 'ring8':
        b = rng.choice([1.0, 2.0, 1.5, 0.5])
        pts = [(a, 0.0), (b, b), (0.0, a), (-b, b), (-a, 0.0), (-b, -b), (0.0, -a), (b, -b)]
    else:
        n = rng.randint(3, 30)
        ph = rng.choice([0.0, rng.uniform(0, 2 * math.pi)])
        pts = [(a * math.cos(ph + 2 * math.pi * i / n), a * math.sin(ph + 2 * math.pi * i / n)) for i in range(n)]
    d = rng.choice([0.0, -1.0, 1.0, -pow2(-rng.randint(3, 40)), pow2(-rng.randint(3, 40))])

    def fan(m, dd, scale=1.0, z0=0.0):
        ids = [m.pt((x * scale, y * scale, z0)) for (x, y) in pts]
        c = m.pt((0.0, 0.0, z0 + dd))
        for i in range(len(ids)):
            m.add_f(c, ids[i], ids[(i + 1) % len(ids)])
    A, B = Mesh(), Mesh()
    fan(B, d)
    h = rng.choice([1.0, 2.0, 0.5, 4.0, -1.0, pow2(-rng.randint(3, 40))])
    if av == 'point':
        point_tri(A, (0.0, 0.0, h), rng)
    elif av == 'square':
        s = rng.choice([0.25, 0.5, 1.0, 4.0])
        if rng.random() < 0.5:
            q = [(s, 0.0), (0.0, s), (-s, 0.0), (0.0, -s)]
        else:
            q = [(s, s), (-s, s), (-s, -s), (s, -s)]
        A.tri((q[0][0], q[0][1], h), (q[1][0], q[1][1], h), (q[2][0], q[2][1], h))
        A.tri((q[0][0], q[0][1], h), (q[2][0], q[2][1], h), (q[3][0], q[3][1], h))
    elif av == 'axis_segment':
        A.tri((0.0, 0.0, h), (0.0, 0.0, h + 1), (0.0, 0.0, h + rng.choice([0.5, 2.0, 1.0])))
    elif av == 'axis_plane_tri':
        s = rng.choice([0.25, 0.5, 1.0])
        A.tri((-s, 0.0, h), (s, 0.0, h), (0.0, 0.0, h + s))
    else:
        fan(A, rng.choice([0.0, 1.0, -1.0, 0.5]) if d != 0 else 1.0, rng.choice([1.0, 0.5]),
            rng.choice([0.0, 0.0, h]))
    P = {'ring': ring, 'a_var': av, 'apex': d, 'h': h}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_vertex_ties(rng):
    tips = rng.choice(['axes6', 'axes4_planar', 'cube8', 'two_opposite', 'tetra4'])
    av = rng.choice(['centre_point', 'centre_tri', 'sym_plane_tri', 'axis_segment'])
    a = 2.0
    T = {'axes6': [(a, 0, 0), (-a, 0, 0), (0, a, 0), (0, -a, 0), (0, 0, a), (0, 0, -a)],
         'axes4_planar': [(a, 0, 0), (-a, 0, 0), (0, a, 0), (0, -a, 0)],
         'cube8': [(x, y, z) for x in (-a, a) for y in (-a, a) for z in (-a, a)],
         'two_opposite': [(a, 0, 0), (-a, 0, 0)],
         'tetra4': [(a, a, a), (a, -a, -a), (-a, a, -a), (-a, -a, a)]}[tips]
    shape = rng.choice(['tri', 'pyramid'])
    A, B = Mesh(), Mesh()
    for t in T:
        t = tuple(float(c) for c in t)
        u = any_perp(t)
        v = vcross(t, u)
        m2 = max(abs(c) for c in u) or 1.0
        u = vmul(1.0 / m2, u)
        m3 = max(abs(c) for c in v) or 1.0
        v = vmul(1.0 / m3, v)
        o = vmul(2.0, t)
        if shape == 'tri':
            B.tri(t, vadd(o, u), vsub(o, u))
        else:
            p1, p2, p3 = vadd(o, u), vadd(o, v), vsub(vsub(o, u), v)
            B.tri(t, p1, p2)
            B.tri(t, p2, p3)
            B.tri(t, p3, p1)
    s = rng.choice([0.25, 0.5, pow2(-rng.randint(3, 30))])
    if av == 'centre_point':
        point_tri(A, (0.0, 0.0, 0.0), rng)
    elif av == 'centre_tri':
        A.tri((s, 0.0, 0.0), (-s, s, 0.0), (-s, -s, 0.0))
    elif av == 'sym_plane_tri':
        A.tri((0.0, -1.0, -1.0), (0.0, 1.0, -0.5), (0.0, rdy(rng, -1, 1), 1.0))
    else:
        A.tri((0.0, 0.0, -1.0), (0.0, 0.0, 1.0), (0.0, 0.0, rdy(rng, -1, 1)))
    P = {'tips': tips, 'shape': shape, 'a_var': av}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_between_parallel_planes(rng):
    bv = rng.choice(['plates', 'plates', 'walls4'])
    c = rng.choice([1.0, 2.0, 0.5, pow2(-rng.randint(3, 30))])
    n = rng.randint(1, 3)
    A, B = Mesh(), Mesh()
    P = {'b': bv, 'c': c}
    if bv == 'plates':
        grid(B, irange(-n, n), irange(-n, n), c, rng.choice(['a', 'b', 'alt']), rng)
        sh = rng.choice([0.0, 0.0, 0.5])
        grid(B, [sh + i for i in range(-n, n + 1)], [sh + i for i in range(-n, n + 1)], -c,
             rng.choice(['a', 'b', 'alt', 'x']), rng)
        av = rng.choice(['mid_tri', 'mid_grid', 'tilted_through', 'near_mid'])
        if av in ('mid_tri', 'near_mid'):
            for _ in range(rng.randint(1, 3)):
                z = 0.0 if av == 'mid_tri' else sgn(rng) * c * pow2(-rng.randint(3, 50))
                A.tri(*[(rdy(rng, -n, n, 1), rdy(rng, -n, n, 1), z) for _ in range(3)])
        elif av == 'mid_grid':
            k = rng.randint(1, n)
            grid(A, irange(-k, k), irange(-k, k), 0.0, rng.choice(['a', 'b', 'alt']), rng)
        else:
            A.tri((-1.0, -1.0, -c / 2), (1.0, -1.0, c / 2), (0.0, 1.0, rng.choice([0.0, c / 4, -c / 2])))
    else:
        for ax in (0, 1):
            for sd in (-1.0, 1.0):
                def mp(p, ax=ax, sd=sd):
                    return (sd * c, p[0], p[1]) if ax == 0 else (p[0], sd * c, p[1])
                grid(B, [-c, c], [-c, c], 0.0, rng.choice('ab'), rng, mapf=mp)
        if rng.random() < 0.4:
            grid(B, [-c, c], [-c, c], c, 'a', rng)
            grid(B, [-c, c], [-c, c], -c, 'b', rng)
            P['closed'] = 1
        av = rng.choice(['diag_plane', 'axis', 'x0_plane'])
        h = c / 2
        if av == 'diag_plane':
            A.tri((-h, -h, -h), (h, h, -h), (0.0, 0.0, h))
        elif av == 'axis':
            A.tri((0.0, 0.0, -h), (0.0, 0.0, h), (0.0, 0.0, 0.0))
        else:
            A.tri((0.0, -h, -h), (0.0, h, -h), (0.0, rdy(rng, -h, h, 6), h))
    P['a_var'] = av
    place(rng, [A, B], P, 0.75)
    return P, A, B


def snap(p, q=16.0):
    return tuple(round(c * q) / q for c in p)


def k_mirror_symmetric(rng):
    var = rng.choice(['gap', 'touch', 'straddle', 'self_sym', 'rot180'])
    bk, M = base_generic(rng, ['bumpy_grid', 'solid', 'fan', 'strip', 'soup'])
    lo, hi = bbox([M])
    ext = max(hi[i] - lo[i] for i in range(3)) or 1.0
    M.apply(lambda p: snap(vmul(2.0 / ext, vsub(p, lo))))
    lo, hi = bbox([M])
    g = {'gap': rng.choice([pow2(-rng.randint(2, 40)), 0.25, 1.0]), 'touch': 0.0,
         'straddle': -rng.choice([0.25, 0.5, 1.0]), 'self_sym': rng.choice([0.0, 0.25]),
         'rot180': rng.choice([0.0, 0.25, -0.5])}[var]
    M.apply(lambda p: (p[0] - lo[0] + g, p[1], p[2]))
    P = {'base': bk, 'variant': var, 'gap': g}
    if var == 'rot180':
        A, B = M, M.copy()
        B.apply(lambda p: (-p[0], -p[1], p[2]))
    elif var == 'self_sym':
        B = M.copy()
        Mi = M.copy()
        Mi.apply(lambda p: (-p[0], p[1], p[2]))
        Mi.f = [(a, c, b) for (a, b, c) in Mi.f]
        B.extend(Mi)
        A = Mesh()
        y0, y1, z0, z1 = lo[1], hi[1], lo[2], hi[2]
        A.tri((0.0, y0, z0), (0.0, y1, (z0 + z1) / 2), (0.0, (y0 + y1) / 2, z1))
        if rng.random() < 0.4:
            A.tri((0.0, y0, z0), (0.0, y1, z0), (0.0, y1, (z0 + z1) / 2))
    else:
        A, B = M, M.copy()
        B.apply(lambda p: (-p[0], p[1], p[2]))
        B.f = [(a, c, b) for (a, b, c) in B.f]
    place(rng, [A, B], P, 0.7)
    return P, A, B


def k_voronoi_boundary_points(rng):
    a, b = float(rng.randint(2, 8)), float(rng.randint(2, 8))
    c = float(rng.randint(-3, int(a) + 3))
    Pv = [(0.0, 0.0, 0.0), (a, 0.0, 0.0), (c, b, 0.0)]
    bv = rng.choice(['single', 'single', 'coplanar_pair', 'hinge_pair'])
    B = Mesh()
    B.tri(*Pv)
    tris = [list(Pv)]
    if bv != 'single':
        P3 = (float(rng.randint(-3, int(a) + 3)), -float(rng.randint(2, 8)),
              0.0 if bv == 'coplanar_pair' else float(rng.choice([-2, -1, 1, 2])))
        B.tri(Pv[1], Pv[0], P3)
    A = Mesh()
    tags = []
    cen3 = vadd(vadd(Pv[0], Pv[1]), Pv[2])
    Z = (0.0, 0.0, 1.0)
    zs = [0.0, 0.5, 1.0, 2.0, -1.0, -0.25]
    for _ in range(rng.randint(1, 5)):
        e = rng.randint(0, 2)
        Pi, Pj = Pv[e], Pv[(e + 1) % 3]
        ed = vsub(Pj, Pi)
        nrm = (ed[1], -ed[0], 0.0)
        if vdot(nrm, vsub(cen3, vmul(3.0, Pi))) > 0:
            nrm = vmul(-1.0, nrm)
        kind = rng.choice(['face_edge', 'edge_vertex', 'edge_vertex', 'vertical_line', 'point'])
        if kind == 'face_edge':
            ts = [rng.choice([0.0, 0.25, 0.5, 0.75, 1.0, -0.5, 1.5]) for _ in range(3)]
            pts = [vadd(lerp(Pi, Pj, t), vmul(rng.choice(zs), Z)) for t in ts]
        elif kind == 'edge_vertex':
            end = Pi if rng.random() < 0.5 else Pj
            # plane through the end point perpendicular to the edge, outward half
            pts = [vadd(vadd(end, vmul(rng.choice([0.0, 0.5, 1.0, 2.0, 0.25]), nrm)),
                        vmul(rng.choice(zs), Z)) for _ in range(3)]
        elif kind == 'vertical_line':
            base = rng.choice([Pi, lerp(Pi, Pj, 0.5)])
            pts = [vadd(base, vmul(z, Z)) for z in rng.sample(zs, 3)]
        else:
            base = vadd(rng.choice([Pi, lerp(Pi, Pj, 0.25)]), vmul(rng.choice([0.0, 0.5, 1.0]), nrm))
            point_tri(A, vadd(base, vmul(rng.choice(zs[1:]), Z)), rng)
            tags.append(kind)
            continue
        A.tri(*pts)
        tags.append(kind)
    P = {'b': bv, 'a': a, 'bb': b, 'c': c, 'planes': '-'.join(tags)}
    place(rng, [A, B], P, 0.8)
    return P, A, B


TRIPLES = [(3, 4, 5), (4, 3, 5), (5, 12, 13), (12, 5, 13), (8, 15, 17), (0, 1, 1),
           (-3, 4, 5), (-4, 3, 5), (-5, 12, 13), (-12, 5, 13)]


def k_bisector_plane(rng):
    p, q, c = rng.choice(TRIPLES)
    av = rng.choice(['in_bisector', 'in_bisector', 'other_bisector', 'bisector_segment', 'near_bisector'])
    s0 = rng.choice([0, 0, 1])
    s1 = s0 + rng.randint(1, 3)
    x0, x1 = float(rng.randint(-3, -1)), float(rng.randint(1, 3))
    B = Mesh()
    for face in (1, 2):
        # face 1: half-plane z=0, y>=0 (direction (0,c,0)); face 2: direction (0,p,q)
        dirv = (0.0, float(c), 0.0) if face == 1 else (0.0, float(p), float(q))
        a1, a2 = vmul(s0, dirv), vmul(s1, dirv)
        v00, v10 = B.pt((x0, a1[1], a1[2])), B.pt((x1, a1[1], a1[2]))
        v01, v11 = B.pt((x0, a2[1], a2[2])), B.pt((x1, a2[1], a2[2]))
        if rng.random() < 0.5:
            B.add_f(v00, v10, v11)
            B.add_f(v00, v11, v01)
        else:
            B.add_f(v00, v10, v01)
            B.add_f(v10, v11, v01)
    A = Mesh()
    wv = (0.0, float(c + p), float(q))
    if av == 'other_bisector':
        wv = (0.0, float(c - p), -float(q))
    tlo, thi = s0 * c / float(abs(c + p) or 1), s1 * c / float(abs(c + p) or 1)

    def bp(t, x):
        return (x, wv[1] * t, wv[2] * t)
    ts = [rdy(rng, tlo, thi, 3) if thi > tlo else tlo for _ in range(3)]
    xs = [rdy(rng, x0, x1, 2) for _ in range(3)]
    if av == 'bisector_segment':
        A.tri(bp(ts[0], xs[0]), bp(ts[1], xs[0]), bp(ts[2], xs[0]))
    else:
        pts = [bp(ts[i], xs[i]) for i in range(3)]
        if av == 'near_bisector':
            nb = (0.0, -float(q), float(c + p))
            e = pow2(-rng.randint(5, 50))
            pts = [vadd(pt, vmul(e, nb)) for pt in pts]
        A.tri(*pts)
        if rng.random() < 0.4:
            A.tri(bp(tlo, x0), bp(thi, x0), bp(thi, x1))
    P = {'triple': '%d_%d_%d' % (p, q, c), 'a_var': av, 's0': s0, 's1': s1}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_high_valence_fan(rng):
    rv = rng.choice(['float_closed', 'float_open', 'square_ring_exact'])
    bv = rng.choice(['point_above', 'rotated_fan', 'other_n', 'plate', 'tiny_tri_at_apex'])
    hv = rng.choice(['planar', 'tiny', 'cone'])

    def apex_h():
        if hv == 'planar':
            return 0.0
        if hv == 'tiny':
            return sgn(rng) * (pow2(-rng.randint(10, 40)) if rv == 'square_ring_exact' else logu(rng, -12, -3))
        return sgn(rng)
    h = apex_h()

    def ring_pts(n, rot):
        if rv == 'square_ring_exact':
            mm = n
            out = []
            for side in range(4):
                for i in range(2 * mm):
                    t = -mm + i + rot
                    out.append([(t, -mm), (mm, t), (-t, mm), (-mm, -t)][side])
            return [(float(x), float(y)) for (x, y) in out], True
        closed = rv == 'float_closed'
        span = 2 * math.pi if closed else rng.uniform(0.5, 6.0)
        cnt = n if closed else n + 1
        return [(math.cos(span * (i + rot) / n), math.sin(span * (i + rot) / n)) for i in range(cnt)], closed

    def fan(m, n, rot, hh):
        pts, closed = ring_pts(n, rot)
        ids = [m.pt((x, y, 0.0)) for (x, y) in pts]
        c = m.pt((0.0, 0.0, hh))
        L = len(ids)
        for i in range(L if closed else L - 1):
            m.add_f(c, ids[i], ids[(i + 1) % L])
    if rv == 'square_ring_exact':
        n = rng.randint(1, 3)
    else:
        n = rng.choice([30, rng.randint(8, 30)])
    A, B = Mesh(), Mesh()
    fan(A, n, 0.0, h)
    g = rng.choice([0.0, 0.5, pow2(-rng.randint(5, 40))]) * sgn(rng)
    if bv == 'point_above':
        point_tri(B, (0.0, 0.0, h + g), rng)
    elif bv == 'rotated_fan':
        fan(B, n, 0.5, h)
    elif bv == 'other_n':
        n2 = (rng.randint(1, 3) if rv == 'square_ring_exact' else rng.randint(3, 30))
        fan(B, n2, 0.0, h + rng.choice([0.0, g]))
    elif bv == 'plate':
        grid(B, [-1.0, 0.0, 1.0], [-1.0, 0.0, 1.0], g, rng.choice(['a', 'b', 'alt']), rng)
    else:
        s = logu(rng, -9, -3)
        B.tri((-s, -s, h + g * s), (s, -s, h + g * s), (0.0, s, h))
    P = {'ring': rv, 'b': bv, 'n': n, 'apex': h, 'g': g}
    place(rng, [A, B], P, 0.5)
    return P, A, B


def k_tiny_next_to_huge(rng):
    var = rng.choice(['on_vertex', 'on_edge', 'floating', 'fan'])
    bv = rng.choice(['huge_copy', 'tiny_cluster', 'tilted_huge', 'plate'])
    r = logu(rng, -12, -4)
    O, X, Y = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
    A, B = Mesh(), Mesh()
    A.tri(O, X, Y)

    def tiny_stuff(m):
        if var == 'on_vertex':
            for _ in range(rng.randint(1, 5)):
                m.tri(O, vmul(r, rand_unit(rng)), vmul(r, rand_unit(rng)))
        elif var == 'on_edge':
            for _ in range(rng.randint(1, 4)):
                t = rng.random()
                p, q = (t, 0.0, 0.0), (t + r, 0.0, 0.0)
                apex = rng.choice([(t + r / 2, -r, 0.0), (t, 0.0, r), (t + r / 2, r / 2, r)])
                m.tri(p, q, apex)
        elif var == 'floating':
            for _ in range(rng.randint(1, 4)):
                c = (rng.uniform(0, 0.5), rng.uniform(0, 0.5), r * rng.choice([1.0, 0.0, -1.0]))
                m.tri(c, vadd(c, vmul(r, rand_unit(rng))), vadd(c, vmul(r, rand_unit(rng))))
        else:
            k = rng.randint(3, 12)
            c = (rng.uniform(0, 0.5), rng.uniform(0, 0.5), rng.choice([0.0, r]))
            ids = [m.pt(vadd(c, (r * math.cos(2 * math.pi * i / k), r * math.sin(2 * math.pi * i / k), 0.0)))
                   for i in range(k)]
            ci = m.pt(c)
            for i in range(k):
                m.add_f(ci, ids[i], ids[(i + 1) % k])
    tiny_stuff(A)
    if bv == 'huge_copy':
        g = rng.choice([0.0, r, logu(rng, -15, -3)])
        B.tri((0.0, 0.0, g), (1.0, 0.0, g), (0.0, 1.0, g))
    elif bv == 'tiny_cluster':
        tiny_stuff(B)
    elif bv == 'tilted_huge':
        th = logu(rng, -9, -2)
        B.tri(O, (1.0, 0.0, 0.0), (0.0, math.cos(th), math.sin(th)))
        tiny_stuff(B)
    else:
        grid(B, [-0.5, 0.5, 1.5], [-0.5, 0.5, 1.5], rng.choice([0.0, r, -r]), rng.choice(['a', 'b']), rng)
    P = {'variant': var, 'b': bv, 'r': r}
    place(rng, [A, B], P, 0.3)
    return P, A, B


def k_collinear_chain(rng):
    dv = rng.choice(['x', 'xy', '123', 'float'])
    d = {'x': (1.0, 0.0, 0.0), 'xy': (1.0, 1.0, 0.0), '123': (1.0, 2.0, 3.0),
         'float': rand_unit(rng)}[dv]
    bv = rng.choice(['plate_crossing', 'parallel_chain', 'same_line', 'skew_chain', 'containing_surface'])
    ts = sorted(float(rng.randint(0, 16)) for _ in range(rng.randint(3, 10)))

    def chain(m, ts, off=(0.0, 0.0, 0.0), dd=d):
        for _ in range(rng.randint(1, 15)):
            m.tri(*[vadd(off, vmul(rng.choice(ts), dd)) for _ in range(3)])
    A, B = Mesh(), Mesh()
    chain(A, ts)
    u = any_perp(d)
    w = vcross(d, u)
    if dv != 'float':
        u = vmul(1.0 / max(abs(c) for c in u), u)
        w = vmul(1.0 / max(abs(c) for c in w), w)
    else:
        u, w = vunit(u), vunit(w)
    g = rng.choice([0.0, 1.0, pow2(-rng.randint(3, 50))])
    if bv == 'plate_crossing':
        t0 = rng.choice(ts + [(ts[0] + ts[-1]) / 2 + 0.5])
        c = vmul(t0, d)
        pl = [vadd(c, vadd(vmul(sx, u), vmul(sy, w))) for (sx, sy) in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        B.tri(pl[0], pl[1], pl[2])
        B.tri(pl[0], pl[2], pl[3])
    elif bv == 'parallel_chain':
        chain(B, ts, vmul(g if g else 1.0, u))
    elif bv == 'same_line':
        chain(B, sorted(float(rng.randint(0, 16)) for _ in range(rng.randint(3, 10))))
    elif bv == 'skew_chain':
        t0 = rng.choice(ts)
        chain(B, [x - 8.0 for x in ts], vadd(vmul(t0, d), vmul(g, u)), w)
    else:
        lo_, hi_ = ts[0] - 1, ts[-1] + 1
        pts = [vadd(vmul(lo_, d), vmul(-1.0, u)), vadd(vmul(hi_, d), vmul(-1.0, u)),
               vadd(vmul(hi_, d), u), vadd(vmul(lo_, d), u)]
        B.tri(pts[0], pts[1], pts[2])
        B.tri(pts[0], pts[2], pts[3])
    P = {'dir': dv, 'b': bv, 'g': g}
    place(rng, [A, B], P, 0.6)
    return P, A, B


def k_point_collapsed(rng):
    base = rng.choice(['grid_flat', 'grid_bumpy', 'cube', 'octa', 'tetra'])
    B = Mesh()
    if base.startswith('grid'):
        n = rng.randint(1, 3)
        Z = dict(((i, j), rng.choice([0.0, 0.5, 1.0]) if base == 'grid_bumpy' else 0.0)
                 for i in range(n + 1) for j in range(n + 1))
        grid(B, irange(0, n), irange(0, n), 0.0, rng.choice(['a', 'b', 'alt']), rng, zf=lambda i, j: Z[(i, j)])
    else:
        V, F = solid_vf(base, rng)
        add_vf(B, V, F)
    A = Mesh()
    tags = []
    lo, hi = bbox([B])
    for _ in range(rng.randint(1, 12)):
        f = B.f[rng.randint(0, len(B.f) - 1)]
        pts = [B.v[i] for i in f]
        t = rng.choice(['b_vertex', 'b_edge', 'b_face', 'above_face', 'random'])
        if t == 'b_vertex':
            p = pts[rng.randint(0, 2)]
        elif t == 'b_edge':
            w = list(rng.choice(BARY_EDGE))
            rng.shuffle(w)
            p = bary(pts, w)
        elif t == 'b_face':
            w = list(rng.choice(BARY_INT))
            rng.shuffle(w)
            p = bary(pts, w)
        elif t == 'above_face':
            nrm = vcross(vsub(pts[1], pts[0]), vsub(pts[2], pts[0]))
            w = list(rng.choice(BARY_INT))
            p = vadd(bary(pts, w), vmul(rng.choice([1.0, -1.0, 0.25]) * pow2(-rng.randint(0, 40)), nrm))
        else:
            p = tuple(rdy(rng, lo[i] - 1, hi[i] + 1, 3) for i in range(3))
        point_tri(A, p, rng)
        tags.append(t)
    both = rng.random() < 0.2
    if both:
        Bp = Mesh()
        for p in B.v[:12]:
            point_tri(Bp, p, rng)
        B = Bp
    P = {'base': base, 'points': '-'.join(tags), 'b_points': int(both)}
    place(rng, [A, B], P, 0.7)
    return P, A, B


def k_nested_solids(rng):
    name = rng.choice(['tetra', 'octa', 'cube', 'icosa', 'octa_sub1'])
    var = rng.choice(['scaled', 'retri', 'dual', 'rotated_tiny', 'inscribed', 'shifted'])
    if var in ('dual', 'inscribed'):
        name = 'cube'
    if var == 'retri' and name != 'cube':
        var = 'scaled'

    def build(nm, r=None):
        m = Mesh()
        if nm == 'octa_sub1':
            V, F = sphere_vf('octa', 1)
        else:
            V, F = solid_vf(nm, r or rng)
        add_vf(m, V, F)
        return m
    A = build(name)
    P = {'solid': name, 'variant': var}
    if var == 'scaled':
        eps = rng.choice([pow2(-rng.randint(1, 50)), logu(rng, -15, -1)]) * sgn(rng)
        B = A.copy()
        B.apply(lambda p: vmul(1.0 + eps, p))
        P['eps'] = eps
    elif var == 'retri':
        B = build('cube')
    elif var == 'dual':
        B = build('octa')
        e = rng.choice([0.0, 0.0, pow2(-rng.randint(3, 50)), -pow2(-rng.randint(3, 50)), 0.5])
        B.apply(lambda p: vmul(1.0 + e, p))
        P['eps'] = e
    elif var == 'inscribed':
        B = Mesh()
        V, F = solid_vf('tetra')
        if rng.random() < 0.5:
            V = [(-x, y, z) for (x, y, z) in V]
        add_vf(B, V, F)
    elif var == 'rotated_tiny':
        ang = logu(rng, -12, -3)
        R = axis_rot(rand_unit(rng), ang)
        B = A.copy()
        B.apply(lambda p: matvec(R, p))
        P['angle'] = ang
    else:
        d = vmul(rng.choice([pow2(-rng.randint(3, 50)), logu(rng, -15, -3)]), rand_unit(rng))
        B = A.copy()
        B.apply(lambda p: vadd(p, d))
    place(rng, [A, B], P, 0.6)
    return P, A, B


def k_cube_interior_ties(rng):
    B = Mesh()
    V, F = solid_vf('cube', rng)
    open_box = rng.random() < 0.3
    if open_box:
        F = [f for f in F if not all(V[i][2] > 0 for i in f)]
    add_vf(B, V, F)
    av = rng.choice(['centre_point', 'centre_tri', 'diag_plane_tri', 'axis_segment', 'body_diagonal',
                     'mid_plane_grid', 'face_parallel_near'])
    A = Mesh()
    s = rng.choice([0.25, 0.5, pow2(-rng.randint(3, 40))])
    if av == 'centre_point':
        point_tri(A, (0.0, 0.0, 0.0), rng)
    elif av == 'centre_tri':
        A.tri((s, 0.0, 0.0), (-s, s, 0.0), (-s, -s, 0.0))
    elif av == 'diag_plane_tri':
        pts = []
        for _ in range(3):
            t = rdy(rng, -0.75, 0.75, 3)
            pts.append((t, t, rdy(rng, -0.75, 0.75, 3)))
        A.tri(*pts)
    elif av == 'axis_segment':
        A.tri((0.0, 0.0, -0.5), (0.0, 0.0, 0.5), (0.0, 0.0, rdy(rng, -0.5, 0.5, 3)))
    elif av == 'body_diagonal':
        A.tri(*[(t, t, t) for t in (rdy(rng, -0.75, 0.75, 3) for _ in range(3))])
    elif av == 'mid_plane_grid':
        grid(A, [-0.5, 0.0, 0.5], [-0.5, 0.0, 0.5], 0.0, rng.choice(['a', 'b', 'alt']), rng)
    else:
        z = 1.0 - pow2(-rng.randint(3, 50))
        A.tri((-0.5, -0.5, z), (0.5, -0.5, z), (0.0, 0.5, z))
    P = {'a_var': av, 'open': int(open_box)}
    place(rng, [A, B], P, 0.75)
    return P, A, B


def k_same_vertices_alt_topology(rng):
    n, m = rng.randint(1, 5), rng.randint(1, 5)
    hv = rng.choice(['dyadic', 'float', 'saddle'])
    if hv == 'dyadic':
        Z = dict(((i, j), rng.randint(-4, 4) / 4) for i in range(n + 1) for j in range(m + 1))
    elif hv == 'float':
        Z = dict(((i, j), rng.uniform(-1, 1)) for i in range(n + 1) for j in range(m + 1))
    else:
        Z = dict(((i, j), (i - n / 2) * (j - m / 2) / 4) for i in range(n + 1) for j in range(m + 1))
    dA = rng.choice(['a', 'b', 'alt', 'altb'])
    bd = rng.choice(['flip', 'rand'])
    A, B = Mesh(), Mesh()
    grid(A, irange(0, n), irange(0, m), 0.0, dA, rng, zf=lambda i, j: Z[(i, j)])
    grid(B, irange(0, n), irange(0, m), 0.0, FLIP[dA] if bd == 'flip' else 'rand', rng, zf=lambda i, j: Z[(i, j)])
    P = {'heights': hv, 'diagA': dA, 'diagB': bd, 'n': n, 'm': m}
    place(rng, [A, B], P, 0.5)
    return P, A, B


def k_far_tiny_generic(rng):
    bv = rng.choice(['other_generic', 'offset_copy', 'jittered_copy'])
    bk, A = base_generic(rng)
    P = {'base': bk, 'b': bv}
    if bv == 'other_generic':
        bk2, B = base_generic(rng)
        P['base_b'] = bk2
    else:
        B = A.copy()
        e = logu(rng, -3, 0)
        if bv == 'offset_copy':
            d = vmul(e, rand_unit(rng))
            B.apply(lambda p: vadd(p, d))
        else:
            B.v = [vadd(p, vmul(e * rng.random(), rand_unit(rng))) for p in B.v]
            B._reindex()
        P['rel'] = e
    place_generic(rng, [A, B], P, size_exp=(-6, -2), far=rng.choice(['far', 'far_axis']))
    return P, A, B


def k_interpenetrating(rng):
    var = rng.choice(['through_vertex', 'along_edge', 'generic_cross', 'x_cross', 'tetra_pierce'])
    A, B = Mesh(), Mesh()
    if var == 'x_cross':
        A.tri((-2.0, 0.0, -1.0), (2.0, 0.0, -1.0), (0.0, 0.0, 2.0))
        B.tri((0.0, -2.0, rdy(rng, -0.5, 0.5)), (0.0, 2.0, rdy(rng, -0.5, 0.5)), (0.0, 0.0, rng.choice([-3.0, 0.0, 1.0])))
    else:
        grid(A, irange(-2, 2), irange(-2, 2), 0.0, rng.choice(['a', 'b', 'alt', 'rand']), rng)
        if var == 'through_vertex':
            B.tri((-1.0, -1.0, -1.0), (1.0, 1.0, -1.0), (rdy(rng, -1, 1), rdy(rng, -1, 1), 1.0))
            if rng.random() < 0.5:
                B.f[-1] = B.f[-1]
                B.v[-1] = (B.v[-1][0], B.v[-1][0], 1.0)
                B._reindex()
        elif var == 'along_edge':
            B.tri((-1.5, 0.0, -1.0), (1.5, 0.0, -1.0), (rdy(rng, -1, 1), 0.0, 1.5))
        elif var == 'generic_cross':
            B.tri(*[(rdy(rng, -2, 2, 3), rdy(rng, -2, 2, 3), rdy(rng, -1, 1, 3)) for _ in range(3)])
            B.tri(*[(rdy(rng, -2, 2, 3), rdy(rng, -2, 2, 3), rdy(rng, -1, 1, 3)) for _ in range(3)])
        else:
            e = pow2(-rng.randint(3, 50))
            c = (rdy(rng, -1, 1, 1), rdy(rng, -1, 1, 1), -e)
            p1, p2, p3 = vadd(c, (1.0, 0.0, 1.0)), vadd(c, (-1.0, 1.0, 1.0)), vadd(c, (-1.0, -1.0, 1.0))
            B.tri(c, p1, p2)
            B.tri(c, p2, p3)
            B.tri(c, p3, p1)
            B.tri(p1, p3, p2)
    P = {'variant': var}
    place(rng, [A, B], P, 0.7)
    return P, A, B


def k_lattice_soup(rng):
    k = rng.randint(1, 3)
    flat = rng.random() < 0.3
    L = [(float(i), float(j), 0.0 if flat else float(l))
         for i in range(k + 1) for j in range(k + 1) for l in range(1 if flat else k + 1)]
    cap = min(30, 2 * len(L))
    A, B = Mesh(), Mesh()
    ta = []
    for _ in range(rng.randint(1, cap)):
        t = [rng.choice(L) for _ in range(3)]
        A.tri(*t)
        ta.append(t)
    for _ in range(rng.randint(1, cap)):
        if ta and rng.random() < 0.2:
            B.tri(*rng.choice(ta))
        else:
            B.tri(*[rng.choice(L) for _ in range(3)])
    P = {'k': k, 'flat': int(flat)}
    place(rng, [A, B], P, 0.7)
    return P, A, B


def k_retessellated_sphere(rng):
    var = rng.choice(['octa_vs_icosa', 'octa1_vs_octa2', 'icosa_rot', 'icosa1_vs_octa1', 'same_rot_tiny', 'radius_eps'])
    A, B = Mesh(), Mesh()
    if var == 'octa_vs_icosa':
        add_vf(A, *sphere_vf('octa', rng.randint(0, 2)))
        add_vf(B, *sphere_vf('icosa', rng.randint(0, 1)))
    elif var == 'octa1_vs_octa2':
        add_vf(A, *sphere_vf('octa', 1))
        add_vf(B, *sphere_vf('octa', 2))
    elif var == 'icosa_rot':
        V, F = sphere_vf('icosa', rng.randint(0, 1))
        add_vf(A, V, F)
        R = rand_rot(rng)
        add_vf(B, V, F, lambda p: matvec(R, p))
    elif var == 'icosa1_vs_octa1':
        add_vf(A, *sphere_vf('icosa', 1))
        add_vf(B, *sphere_vf('octa', 1))
    elif var == 'same_rot_tiny':
        V, F = sphere_vf(rng.choice(['octa', 'icosa']), 1)
        add_vf(A, V, F)
        R = axis_rot(rand_unit(rng), logu(rng, -12, -3))
        add_vf(B, V, F, lambda p: matvec(R, p))
    else:
        V, F = sphere_vf(rng.choice(['octa', 'icosa']), rng.randint(0, 1))
        add_vf(A, V, F)
        e = logu(rng, -15, -3) * sgn(rng)
        add_vf(B, V, F, lambda p: vmul(1.0 + e, p))
    P = {'variant': var}
    place_generic(rng, [A, B], P)
    return P, A, B


GENS = [
    ('coplanar_retriangulation', k_coplanar_retriangulation),
    ('coplanar_partial_overlap', k_coplanar_partial_overlap),
    ('coplanar_t_junction', k_coplanar_t_junction),
    ('tilted_grid', k_tilted_grid),
    ('parallel_offset_planes', k_parallel_offset_planes),
    ('sliver_triangles', k_sliver_triangles),
    ('needle_triangles', k_needle_triangles),
    ('fin_on_plate', k_fin_on_plate),
    ('hinge_near_flat', k_hinge_near_flat),
    ('hinge_near_fold', k_hinge_near_fold),
    ('zero_area_mix', k_zero_area_mix),
    ('duplicated_faces', k_duplicated_faces),
    ('near_coincident_offset', k_near_coincident_offset),
    ('jittered_copy', k_jittered_copy),
    ('float32_rounded_copy', k_float32_rounded_copy),
    ('decimal_rounded_copy', k_decimal_rounded_copy),
    ('vertex_on_face', k_vertex_on_face),
    ('edge_on_edge', k_edge_on_edge),
    ('fan_apex_equidistant', k_fan_apex_equidistant),
    ('vertex_ties', k_vertex_ties),
    ('between_parallel_planes', k_between_parallel_planes),
    ('mirror_symmetric', k_mirror_symmetric),
    ('voronoi_boundary_points', k_voronoi_boundary_points),
    ('bisector_plane', k_bisector_plane),
    ('high_valence_fan', k_high_valence_fan),
    ('tiny_next_to_huge', k_tiny_next_to_huge),
    ('collinear_chain', k_collinear_chain),
    ('point_collapsed', k_point_collapsed),
    ('nested_solids', k_nested_solids),
    ('cube_interior_ties', k_cube_interior_ties),
    ('same_vertices_alt_topology', k_same_vertices_alt_topology),
    ('far_tiny_generic', k_far_tiny_generic),
    ('interpenetrating', k_interpenetrating),
    ('lattice_soup', k_lattice_soup),
    ('retessellated_sphere', k_retessellated_sphere),
]
KINDS = [k for (k, _) in GENS]
GEN = dict(GENS)


# ----------------------------------------------------------------------------
# validation, scrambling, output
# ----------------------------------------------------------------------------


def scramble(m, rng):
    m.f = [f[i:] + f[:i] for f in m.f for i in [rng.randint(0, 2)]]
    if rng.random() < 0.5:
        m.f = [(a, c, b) if rng.random() < 0.3 else (a, b, c) for (a, b, c) in m.f]
    rng.shuffle(m.f)
    order = list(range(len(m.v)))
    rng.shuffle(order)
    inv = [0] * len(order)
    for new, old in enumerate(order):
        inv[old] = new
    m.v = [m.v[old] for old in order]
    m.f = [(inv[a], inv[b], inv[c]) for (a, b, c) in m.f]
    m._reindex()


def problems(m):
    if not 1 <= len(m.f) <= MAX_TRI:
        return 'triangle count %d' % len(m.f)
    nv = len(m.v)
    for p in m.v:
        for c in p:
            if not math.isfinite(c) or abs(c) > MAX_ABS:
                return 'bad coordinate %r' % (c,)
    used = set()
    by_idx, by_pos = {}, {}
    for f in m.f:
        for i in f:
            if not 0 <= i < nv:
                return 'bad index'
        used.update(f)
        for i in set(f):
            by_idx[i] = by_idx.get(i, 0) + 1
        for p in set(m.v[i] for i in f):
            by_pos[p] = by_pos.get(p, 0) + 1
    if len(used) != nv:
        return 'unused vertices'
    if max(by_idx.values()) > MAX_VALENCE or max(by_pos.values()) > MAX_VALENCE:
        return 'valence'
    return None


def make_pair(seed):
    kind = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    for attempt in range(1000):
        P, A, B = GEN[kind](rng)
        if rng.random() < 0.5:
            A, B = B, A
            P['swapped'] = 1
        for tag, M in (('scr_a', A), ('scr_b', B)):
            M.compact()
            if rng.random() < 0.3:
                scramble(M, rng)
                P[tag] = 1
        if problems(A) is None and problems(B) is None:
            if attempt:
                P['redraws'] = attempt
            return kind, P, A, B
    raise RuntimeError('seed %d (%s): no valid draw' % (seed, kind))


def fmt_val(v):
    if isinstance(v, bool):
        return str(int(v))
    if isinstance(v, float):
        return repr(v)
    return str(v).replace(' ', '_').replace('\n', '_')


def write_obj(path, seed, kind, which, P, m):
    head = ['# gen18', 'seed=%d' % seed, 'kind=%s' % kind, 'mesh=%s' % which]
    head += ['%s=%s' % (k, fmt_val(v)) for (k, v) in P.items()]
    lines = [' '.join(head)]
    lines += ['v %s %s %s' % (repr(p[0] + 0.0), repr(p[1] + 0.0), repr(p[2] + 0.0)) for p in m.v]
    lines += ['f %d %d %d' % (a + 1, b + 1, c + 1) for (a, b, c) in m.f]
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: python3 generate_pairs18.py OUTDIR FROM TO\n')
        return 2
    outdir, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    counts = []
    n = 0
    for s in range(lo, hi):
        kind, P, A, B = make_pair(s)
        for which, M in (('a', A), ('b', B)):
            write_obj(os.path.join(outdir, '%06d_%s_%s.obj' % (s, kind, which)), s, kind, which, P, M)
            counts.append(len(M.f))
        n += 1
    counts.sort()
    if counts:
        stats = '%d/%d/%d' % (counts[0], counts[len(counts) // 2], counts[-1])
    else:
        stats = '0/0/0'
    print('gen18: %d pairs written to %s; triangles per mesh min/median/max = %s' % (n, outdir, stats))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
