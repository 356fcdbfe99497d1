#!/usr/bin/env python3
"""
generate_pairs14.py -- adversarial generator of pairs of small triangle meshes
for testing an exact Hausdorff-distance tool (one that computes, per triangle
of one mesh, the exact squared-distance field to the other mesh).

Usage
-----
    python3 generate_pairs14.py OUTDIR FROM TO

For every integer seed s in [FROM, TO) two files are written:

    OUTDIR/NNNNNN_KIND_a.obj   and   OUTDIR/NNNNNN_KIND_b.obj

NNNNNN is s zero-padded to 6 digits, KIND = KINDS[s % len(KINDS)].
OUTDIR is created if missing.  All randomness comes from random.Random(s), so
the output depends only on the seed.  Standard library only.

Format
------
Each OBJ file: one comment line ('# ...'), then 'v x y z' lines written with
repr(float) (exact double round trip), then 'f i j k' lines (1-based).
Every mesh has 1..200 triangles (mostly <= 80), finite coordinates, valid
indices and no unused vertices; this is checked before writing (ValueError
otherwise).  Zero-area faces (repeated index, repeated coordinates, collinear
corners) are produced on purpose by several kinds.

Placement
---------
Both meshes of a pair are built in a canonical frame (size ~1) and then get a
common placement, one of:
  exact     : axis permutation + sign flips + power-of-two scale + dyadic
              translation (keeps binary-exact ties exact),
  rotate    : uniformly random rotation + translation,
  near_axis : exact placement followed by a rotation of 1e-14..1e-4 rad.
The "_far" kinds additionally translate the pair 1e3..1e7 times its size
away from the origin.

Kinds (KIND = KINDS[seed % 29])
-----
  coplanar_retri       same polygon / square, two different triangulations (fan, zigzag, Steiner, grid diagonals)
  coplanar_partial     coplanar meshes overlapping partially (shifted grids/polygons, nested polygon sharing a corner)
  coplanar_rotated     in-plane rotated copy (exact quarter/half turn, random, pi/n, tiny 1e-14..1e-3 rad)
  coplanar_tjunction   coplanar meshes whose vertices lie on the other's edges (refined grids, split edges, medial triangles)
  near_coplanar_tilt   planar mesh vs copy/retriangulation tilted by 1e-14..1e-3 rad about an in-plane axis
  near_coplanar_offset planar mesh vs copy/retriangulation offset normally by 1e-15..1e-3 (or 2^-10..2^-50)
  near_coplanar_warp   tilt + offset + per-vertex noise 1e-15..1e-6 (sometimes on both meshes)
  sliver_plane         slivers/needles (aspect 1e3..1e14) in a plane vs covering plane, mirrored or crossing slivers
  sliver_above         plane vs slivers parallel above it, standing needles, tilted slivers, slivers above grid edges
  sliver_cross         plane vs slivers crossing it (steep, grazing, through a grid vertex)
  sliver_fan           fan of slivers sharing an apex (flat or conical) vs axis segment, shifted apex, rotated fan, plane
  sliver_tip_touch     slivers whose tips are 0 or 1e-12..1e-7 away from vertices / edges / faces of the other mesh
  wall_floor           floor grid vs perpendicular wall(s) touching / floating / sunk by eps, near-perpendicular walls, L shapes
  hinge                two flaps sharing an edge at 90/135/180/near-180/near-0 deg vs other angle, flat sheet, mirror, retri
  fin_plate            plate vs perpendicular fins (some double-walled with 1e-15..1e-5 thickness), touching/penetrating
  box_coincident       boxes with coincident facets (adjacent, partially shifted, retriangulated, nested, stacked)
  zero_area_mix        normal meshes with repeated-index, repeated-coordinate and collinear zero-area faces mixed in
  dup_flip_unwelded    meshes with duplicated, flipped, index-rotated and unwelded faces vs clean / other copies
  jitter_far           surface vs jittered copy (1e-15..1e-6 of size), 1e3..1e7 sizes from the origin
  retri_far            surface vs retriangulated copy, far from the origin
  offset_far           surface vs copy offset / scaled / tilted by 1e-9..1e-3 of size, far from the origin
  scale_extreme        a pair of another kind scaled to size 1e-6..1e6 (power of two or decimal factor)
  solid_simplify       closed solid (cylinder, uv-sphere, geodesic octahedron, height field) vs coarser version / edge collapses
  solid_refine         polyhedron vs its 1:4 / 1:3 / edge-split refinement (optionally nudged or projected)
  solid_perturb        small solid vs perturbed, inflated, scaled, rotated or translated copy
  heightfield_pair     height field (plane, paraboloid, saddle, sines, crease) at two resolutions / diagonal choices
  equi_cone_axis       cone / flat fan with D4-symmetric dyadic or regular rim vs points / segments / polygons on its axis
  equi_sym_solid       centred cube / octahedron / tetrahedron vs centre point, dual, scaled copy, diagonal segments
  equi_grid_centers    dyadic grid vs points / needles / dual grid above cell centres, vertices and edge midpoints
"""

import math
import os
import random
import sys

MAX_FACES = 200
TAU = 2.0 * math.pi

# --------------------------------------------------------------------------
# small vector helpers
# --------------------------------------------------------------------------


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


def vnorm(a):
    n = vlen(a)
    if n > 0.0 and math.isfinite(n):
        return (a[0] / n, a[1] / n, a[2] / n)
    return (0.0, 0.0, 1.0)


def vlerp(a, b, t):
    return (a[0] + (b[0] - a[0]) * t,
            a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t)


def vmid(a, b):
    return ((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5)


def matvec(M, p):
    return (M[0][0] * p[0] + M[0][1] * p[1] + M[0][2] * p[2],
            M[1][0] * p[0] + M[1][1] * p[1] + M[1][2] * p[2],
            M[2][0] * p[0] + M[2][1] * p[1] + M[2][2] * p[2])


def rot_axis(axis, ang):
    x, y, z = vnorm(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1.0 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def rand_rotation(rng):
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1.0 - u1), math.sqrt(u1)
    w, x = a * math.sin(TAU * u2), a * math.cos(TAU * u2)
    y, z = b * math.sin(TAU * u3), b * math.cos(TAU * u3)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def rand_unit(rng):
    while True:
        v = (rng.gauss(0.0, 1.0), rng.gauss(0.0, 1.0), rng.gauss(0.0, 1.0))
        n = vlen(v)
        if n > 1e-6:
            return (v[0] / n, v[1] / n, v[2] / n)


def perp_unit(rng, d):
    while True:
        c = vcross(d, rand_unit(rng))
        if vlen(c) > 1e-3:
            return vnorm(c)


def expo(rng, lo, hi):
    """10 ** -U(lo, hi): e.g. expo(rng, 3, 15) is in [1e-15, 1e-3]."""
    return 10.0 ** (-rng.uniform(lo, hi))


def sgn(rng):
    return rng.choice((-1.0, 1.0))


def dyadic(rng, lo, hi, bits=4):
    d = 1 << bits
    return rng.randint(int(math.ceil(lo * d)), int(math.floor(hi * d))) / float(d)


def aspect(rng):
    return 10.0 ** rng.uniform(3.0, 14.0)


# --------------------------------------------------------------------------
# mesh
# --------------------------------------------------------------------------


class Mesh(object):
    __slots__ = ('v', 'f')

    def __init__(self, v=None, f=None):
        self.v = list(v) if v else []
        self.f = list(f) if f else []

    def add(self, p):
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.v) - 1

    def tri(self, a, b, c):
        self.f.append((a, b, c))

    def tri_pts(self, p, q, r):
        self.f.append((self.add(p), self.add(q), self.add(r)))

    def merge(self, other):
        off = len(self.v)
        self.v.extend(other.v)
        self.f.extend((a + off, b + off, c + off) for a, b, c in other.f)
        return self

    def copy(self):
        return Mesh(self.v, self.f)

    def mapped(self, fn):
        return Mesh([fn(p) for p in self.v], self.f)

    def flipped(self):
        return Mesh(self.v, [(a, c, b) for a, b, c in self.f])


def merged(*ms):
    out = Mesh()
    for m in ms:
        out.merge(m)
    return out


def weld(m):
    key, remap, nv = {}, [], []
    for p in m.v:
        if p not in key:
            key[p] = len(nv)
            nv.append(p)
        remap.append(key[p])
    return Mesh(nv, [(remap[a], remap[b], remap[c]) for a, b, c in m.f])


def unweld(m):
    out = Mesh()
    for a, b, c in m.f:
        out.tri_pts(m.v[a], m.v[b], m.v[c])
    return out


def compact(m):
    used = sorted(set(i for f in m.f for i in f))
    remap = dict((old, new) for new, old in enumerate(used))
    return Mesh([m.v[i] for i in used],
                [(remap[a], remap[b], remap[c]) for a, b, c in m.f])


def bbox_size(m):
    if not m.v:
        return 1.0
    lo = [min(p[i] for p in m.v) for i in range(3)]
    hi = [max(p[i] for p in m.v) for i in range(3)]
    s = vlen(vsub(hi, lo))
    return s if s > 0 else 1.0


def centroid(m):
    n = float(len(m.v))
    return (sum(p[0] for p in m.v) / n, sum(p[1] for p in m.v) / n,
            sum(p[2] for p in m.v) / n)


def mesh_normal(m):
    acc = (0.0, 0.0, 0.0)
    for a, b, c in m.f:
        pa = m.v[a]
        acc = vadd(acc, vcross(vsub(m.v[b], pa), vsub(m.v[c], pa)))
    return vnorm(acc)


def orient_outward(m, c=None):
    if c is None:
        c = centroid(m)
    nf = []
    for a, b, cc in m.f:
        pa, pb, pc = m.v[a], m.v[b], m.v[cc]
        n = vcross(vsub(pb, pa), vsub(pc, pa))
        g = ((pa[0] + pb[0] + pc[0]) / 3.0, (pa[1] + pb[1] + pc[1]) / 3.0,
             (pa[2] + pb[2] + pc[2]) / 3.0)
        nf.append((a, cc, b) if vdot(n, vsub(g, c)) < 0 else (a, b, cc))
    return Mesh(m.v, nf)


# --------------------------------------------------------------------------
# refinement / simplification
# --------------------------------------------------------------------------


def subdivide4(m):
    out = Mesh(m.v, [])
    cache = {}

    def mid(a, b):
        k = (a, b) if a < b else (b, a)
        if k not in cache:
            cache[k] = out.add(vmid(out.v[a], out.v[b]))
        return cache[k]

    for a, b, c in m.f:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out.f.extend([(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)])
    return out


def subdivide3(m):
    out = Mesh(m.v, [])
    for a, b, c in m.f:
        pa, pb, pc = m.v[a], m.v[b], m.v[c]
        g = out.add(((pa[0] + pb[0] + pc[0]) / 3.0, (pa[1] + pb[1] + pc[1]) / 3.0,
                     (pa[2] + pb[2] + pc[2]) / 3.0))
        out.f.extend([(a, b, g), (b, c, g), (c, a, g)])
    return out


def split_edges(m, rng, k, t=None):
    """Split k random faces at a point of one of their edges (T-junctions)."""
    out = Mesh(m.v, m.f)
    for _ in range(k):
        if len(out.f) >= MAX_FACES:
            break
        i = rng.randrange(len(out.f))
        a, b, c = out.f[i]
        r = rng.randrange(3)
        a, b, c = [(a, b, c), (b, c, a), (c, a, b)][r]
        tt = 0.5 if t is None else t
        mm = out.add(vlerp(out.v[a], out.v[b], tt))
        out.f[i] = (a, mm, c)
        out.f.append((mm, b, c))
    return out


def refine(m, rng):
    n = len(m.f)
    if 4 * n <= 160 and rng.random() < 0.6:
        return subdivide4(m)
    if 3 * n <= 160 and rng.random() < 0.5:
        return subdivide3(m)
    return split_edges(m, rng, max(1, min(n // 2, MAX_FACES - n)),
                       None if rng.random() < 0.6 else rng.random())


def collapse(m, rng, k):
    v, f = list(m.v), list(m.f)
    for _ in range(k):
        if len(f) <= 2:
            break
        a, b, c = f[rng.randrange(len(f))]
        if a == b:
            continue
        nv = list(v)
        if rng.random() < 0.5:
            nv[a] = vmid(v[a], v[b])
        nf = [tuple(a if x == b else x for x in t) for t in f]
        nf = [t for t in nf if t[0] != t[1] and t[1] != t[2] and t[0] != t[2]]
        if not nf:
            break
        v, f = nv, nf
    return Mesh(v, f)


# --------------------------------------------------------------------------
# primitive shapes (canonical frame, size ~1)
# --------------------------------------------------------------------------

DIAGS = ['/', '\\', 'alt', 'rand', 'mixc', 'c']


def param_grid(o, eu, ev, nu, nv, diag='alt', rng=None):
    """Grid o + eu*s + ev*t, s,t in [0,1], nu x nv cells, orientation eu x ev."""
    m = Mesh()
    ids = {}
    for j in range(nv + 1):
        t = j / float(nv)
        for i in range(nu + 1):
            s = i / float(nu)
            ids[i, j] = m.add((o[0] + eu[0] * s + ev[0] * t,
                               o[1] + eu[1] * s + ev[1] * t,
                               o[2] + eu[2] * s + ev[2] * t))
    for j in range(nv):
        for i in range(nu):
            a, b, c, d = ids[i, j], ids[i + 1, j], ids[i + 1, j + 1], ids[i, j + 1]
            mode = diag
            if diag == 'alt':
                mode = '/' if (i + j) % 2 == 0 else '\\'
            elif diag == 'rand':
                mode = rng.choice('/\\') if rng else '/'
            elif diag == 'mixc':
                mode = rng.choice(['/', '\\', 'c']) if rng else 'c'
            if mode == '/':
                m.f.extend([(a, b, c), (a, c, d)])
            elif mode == '\\':
                m.f.extend([(a, b, d), (b, c, d)])
            else:
                s, t = (i + 0.5) / nu, (j + 0.5) / nv
                e = m.add((o[0] + eu[0] * s + ev[0] * t,
                           o[1] + eu[1] * s + ev[1] * t,
                           o[2] + eu[2] * s + ev[2] * t))
                m.f.extend([(a, b, e), (b, c, e), (c, d, e), (d, a, e)])
    return m


def grid_xy(x0, y0, x1, y1, nx, ny, diag='alt', rng=None, z=0.0):
    return param_grid((x0, y0, z), (x1 - x0, 0.0, 0.0), (0.0, y1 - y0, 0.0),
                      nx, ny, diag, rng)


DYADIC_POLYS = [
    [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
    [(0.0, 0.0), (1.0, 0.0), (1.0, 0.5), (0.0, 0.5)],
    [(0.0, 0.0), (1.0, 0.0), (0.5, 1.0)],
    [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)],
    [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)],
    [(0.25, 0.0), (0.75, 0.0), (1.0, 0.25), (1.0, 0.75), (0.75, 1.0),
     (0.25, 1.0), (0.0, 0.75), (0.0, 0.25)],
    [(0.0, 0.0), (1.0, 0.0), (1.5, 0.5), (1.0, 1.0), (0.0, 1.0), (-0.5, 0.5)],
    [(0.0, 0.0), (1.0, 0.0), (1.25, 0.5), (0.5, 1.0), (-0.25, 0.5)],
]


def random_convex(rng, n):
    angs = sorted(rng.uniform(0.0, TAU) for _ in range(n))
    a, b = rng.uniform(0.4, 1.0), rng.uniform(0.4, 1.0)
    rot = rng.uniform(0.0, TAU)
    cr, sr = math.cos(rot), math.sin(rot)
    pts = []
    for t in angs:
        x, y = a * math.cos(t), b * math.sin(t)
        pts.append((cr * x - sr * y, sr * x + cr * y))
    return pts


def pick_poly(rng):
    if rng.random() < 0.5:
        return list(rng.choice(DYADIC_POLYS))
    return random_convex(rng, rng.randint(3, 12))


TRI_METHODS = ['fan', 'zigzag', 'steiner', 'steiner_edge']


def poly_mesh(pts, method, k=0, z=0.0, steiner=None):
    m = Mesh()
    n = len(pts)
    ids = [m.add((p[0], p[1], z)) for p in pts]
    k %= n
    if method == 'fan':
        for i in range(1, n - 1):
            m.tri(ids[k], ids[(k + i) % n], ids[(k + i + 1) % n])
    elif method == 'zigzag':
        order = [ids[(k + i) % n] for i in range(n)]
        strip = [order[0]]
        lo, hi, front = 1, n - 1, True
        while lo <= hi:
            if front:
                strip.append(order[lo])
                lo += 1
            else:
                strip.append(order[hi])
                hi -= 1
            front = not front
        for i in range(len(strip) - 2):
            a, b, c = strip[i], strip[i + 1], strip[i + 2]
            if i % 2 == 0:
                m.tri(a, b, c)
            else:
                m.tri(b, a, c)
    elif method == 'steiner':
        if steiner is None:
            steiner = (sum(p[0] for p in pts) / n, sum(p[1] for p in pts) / n)
        ci = m.add((steiner[0], steiner[1], z))
        for i in range(n):
            m.tri(ci, ids[i], ids[(i + 1) % n])
    elif method == 'steiner_edge':
        a, b = pts[k], pts[(k + 1) % n]
        mi = m.add(((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, z))
        for i in range(1, n):
            m.tri(mi, ids[(k + i) % n], ids[(k + i + 1) % n])
    else:
        raise ValueError(method)
    return m


def two_methods(rng, n):
    opts = [(mt, k) for mt in TRI_METHODS for k in range(n)]
    a = rng.choice(opts)
    rest = [o for o in opts if o[0] != a[0]] if rng.random() < 0.6 else \
        [o for o in opts if o != a]
    return a, rng.choice(rest)


def random_steiner(rng, pts):
    w = [rng.random() + 1e-3 for _ in pts]
    s = sum(w)
    return (sum(wi * p[0] for wi, p in zip(w, pts)) / s,
            sum(wi * p[1] for wi, p in zip(w, pts)) / s)


def poly_pair(rng, pts, z=0.0):
    (m1, k1), (m2, k2) = two_methods(rng, len(pts))
    st1 = random_steiner(rng, pts) if rng.random() < 0.4 else None
    st2 = random_steiner(rng, pts) if rng.random() < 0.4 else None
    return (poly_mesh(pts, m1, k1, z, st1), poly_mesh(pts, m2, k2, z, st2),
            '%s%d/%s%d' % (m1, k1, m2, k2))


def tetra(s=1.0):
    V = [(s, s, s), (s, -s, -s), (-s, s, -s), (-s, -s, s)]
    return orient_outward(Mesh(V, [(0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)]),
                          (0.0, 0.0, 0.0))


def octa(s=1.0):
    V = [(s, 0.0, 0.0), (-s, 0.0, 0.0), (0.0, s, 0.0), (0.0, -s, 0.0),
         (0.0, 0.0, s), (0.0, 0.0, -s)]
    F = [(x, y, z) for x in (0, 1) for y in (2, 3) for z in (4, 5)]
    return orient_outward(Mesh(V, F), (0.0, 0.0, 0.0))


def box(x0, y0, z0, x1, y1, z1, sub=(1, 1, 1), diag='alt', rng=None, welded=True):
    dx, dy, dz = x1 - x0, y1 - y0, z1 - z0
    sx, sy, sz = sub
    fs = [
        param_grid((x0, y0, z0), (0, dy, 0), (dx, 0, 0), sy, sx, diag, rng),
        param_grid((x0, y0, z1), (dx, 0, 0), (0, dy, 0), sx, sy, diag, rng),
        param_grid((x0, y0, z0), (0, 0, dz), (0, dy, 0), sz, sy, diag, rng),
        param_grid((x1, y0, z0), (0, dy, 0), (0, 0, dz), sy, sz, diag, rng),
        param_grid((x0, y0, z0), (dx, 0, 0), (0, 0, dz), sx, sz, diag, rng),
        param_grid((x0, y1, z0), (0, 0, dz), (dx, 0, 0), sz, sx, diag, rng),
    ]
    m = merged(*fs)
    return weld(m) if welded else m


def prism(pts, z0, z1):
    m = Mesh()
    n = len(pts)
    bot = [m.add((p[0], p[1], z0)) for p in pts]
    top = [m.add((p[0], p[1], z1)) for p in pts]
    for i in range(n):
        j = (i + 1) % n
        m.f.extend([(bot[i], bot[j], top[j]), (bot[i], top[j], top[i])])
    for i in range(1, n - 1):
        m.f.append((bot[0], bot[i + 1], bot[i]))
        m.f.append((top[0], top[i], top[i + 1]))
    cx = sum(p[0] for p in pts) / n
    cy = sum(p[1] for p in pts) / n
    return orient_outward(m, (cx, cy, (z0 + z1) * 0.5))


def ring_pts(n, r, phase=0.0):
    if n == 4 and phase == 0.0:
        return [(r, 0.0), (0.0, r), (-r, 0.0), (0.0, -r)]
    return [(r * math.cos(phase + TAU * i / n), r * math.sin(phase + TAU * i / n))
            for i in range(n)]


def cylinder(n, r=1.0, h=1.0, phase=0.0, caps=True, cap_center=True):
    m = Mesh()
    ring = ring_pts(n, r, phase)
    b = [m.add((x, y, 0.0)) for x, y in ring]
    t = [m.add((x, y, h)) for x, y in ring]
    for i in range(n):
        j = (i + 1) % n
        m.f.extend([(b[i], b[j], t[j]), (b[i], t[j], t[i])])
    if caps:
        if cap_center:
            c0 = m.add((0.0, 0.0, 0.0))
            c1 = m.add((0.0, 0.0, h))
            for i in range(n):
                j = (i + 1) % n
                m.f.append((c0, b[j], b[i]))
                m.f.append((c1, t[i], t[j]))
        else:
            for i in range(1, n - 1):
                m.f.append((b[0], b[i + 1], b[i]))
                m.f.append((t[0], t[i], t[i + 1]))
    return m


def uv_sphere(nlat, nlon, r=1.0, phase=0.0):
    m = Mesh()
    top = m.add((0.0, 0.0, r))
    bot = m.add((0.0, 0.0, -r))
    rings = []
    for i in range(1, nlat):
        th = math.pi * i / nlat
        rings.append([m.add((r * math.sin(th) * math.cos(phase + TAU * j / nlon),
                             r * math.sin(th) * math.sin(phase + TAU * j / nlon),
                             r * math.cos(th))) for j in range(nlon)])
    for j in range(nlon):
        k = (j + 1) % nlon
        m.f.append((top, rings[0][j], rings[0][k]))
        m.f.append((bot, rings[-1][k], rings[-1][j]))
        for i in range(len(rings) - 1):
            a, b = rings[i][j], rings[i][k]
            c, d = rings[i + 1][k], rings[i + 1][j]
            m.f.extend([(a, d, c), (a, c, b)])
    return orient_outward(m, (0.0, 0.0, 0.0))


def geo_octa(level, r=1.0):
    m = octa(1.0)
    for _ in range(level):
        m = subdivide4(m)
    return m.mapped(lambda p: vmul(vnorm(p), r))


def random_solid(rng):
    t = rng.randrange(7)
    if t == 0:
        return tetra(rng.choice([1.0, 0.5])), 'tetra'
    if t == 1:
        return octa(rng.choice([1.0, 0.5])), 'octa'
    if t == 2:
        sub = (rng.randint(1, 2), rng.randint(1, 2), rng.randint(1, 2))
        return box(-1, -1, -1, 1, 1, 1, sub, rng.choice(DIAGS[:4]), rng), 'box'
    if t == 3:
        pts = pick_poly(rng)
        return prism(pts, 0.0, rng.choice([1.0, 0.5, 0.25, rng.uniform(0.1, 1.0)])), 'prism'
    if t == 4:
        n = rng.randint(3, 16)
        return cylinder(n, 1.0, rng.choice([1.0, 2.0, 0.5]), 0.0, True,
                        rng.random() < 0.5), 'cyl%d' % n
    if t == 5:
        return uv_sphere(rng.randint(3, 5), rng.randint(4, 8)), 'uvsphere'
    return geo_octa(1), 'geo_octa1'


def rand_height_fn(rng):
    t = rng.randrange(5)
    if t == 0:
        a, b, c = dyadic(rng, -1, 1, 3), dyadic(rng, -1, 1, 3), dyadic(rng, -1, 1, 2)
        return (lambda x, y: a * x + b * y + c), 'plane'
    if t == 1:
        a = dyadic(rng, -1, 1, 3) or 0.5
        return (lambda x, y: a * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5))), 'parab'
    if t == 2:
        a = dyadic(rng, -1, 1, 3) or 0.25
        return (lambda x, y: a * ((x - 0.5) * (x - 0.5) - (y - 0.5) * (y - 0.5))), 'saddle'
    if t == 3:
        a = rng.uniform(0.02, 0.3)
        kx, ky = rng.uniform(1, 9), rng.uniform(1, 9)
        ph = rng.uniform(0, TAU)
        return (lambda x, y: a * math.sin(kx * x + ph) * math.cos(ky * y)), 'sines'
    a = dyadic(rng, -1, 1, 3) or 0.5
    c = rng.choice([0.5, 0.25, rng.uniform(0.1, 0.9)])
    return (lambda x, y: a * abs(x - c)), 'crease'


def heightfield(nx, ny, f, diag, rng, x0=0.0, y0=0.0, x1=1.0, y1=1.0):
    g = grid_xy(x0, y0, x1, y1, nx, ny, diag, rng)
    return g.mapped(lambda p: (p[0], p[1], f(p[0], p[1])))


def sliver(rng, p, d, nrm, L, asp):
    """Sliver with long side L along d and thickness L/asp along nrm."""
    h = L / asp
    if rng.random() < 0.5:   # 'cap': apex very close to the long edge
        s = rng.uniform(-0.3, 1.3)
        return (p, vadd(p, vmul(d, L)), vadd(p, vadd(vmul(d, s * L), vmul(nrm, h))))
    # 'needle': one very short edge
    return (p, vadd(p, vmul(nrm, h)), vadd(p, vmul(d, L)))


def degen_tri(m, p, how):
    """Add a zero-area triangle located at point(s) p (a point or list of collinear points)."""
    if how == 'index':
        i = m.add(p)
        m.tri(i, i, i)
    else:
        m.tri_pts(p, p, p)


# --------------------------------------------------------------------------
# placement
# --------------------------------------------------------------------------


def exact_map(rng):
    perm = [0, 1, 2]
    rng.shuffle(perm)
    sg = [rng.choice((-1.0, 1.0)) for _ in range(3)]
    sc = 2.0 ** rng.randint(-2, 2)
    if rng.random() < 0.4:
        t = (0.0, 0.0, 0.0)
    else:
        t = tuple(rng.randint(-64, 64) / 16.0 for _ in range(3))

    def f(p):
        return (sg[0] * sc * p[perm[0]] + t[0],
                sg[1] * sc * p[perm[1]] + t[1],
                sg[2] * sc * p[perm[2]] + t[2])
    return f


def place(rng, meshes, exact_bias=0.5, mode=None):
    if mode is None:
        r = rng.random()
        if r < exact_bias:
            mode = 'exact'
        elif r < exact_bias + 0.6 * (1.0 - exact_bias):
            mode = 'rotate'
        else:
            mode = 'near_axis'
    if mode == 'exact':
        f = exact_map(rng)
    elif mode == 'rotate':
        M = rand_rotation(rng)
        t = (0.0, 0.0, 0.0) if rng.random() < 0.3 else \
            tuple(rng.uniform(-3.0, 3.0) for _ in range(3))
        f = lambda p: vadd(matvec(M, p), t)
    elif mode == 'near_axis':
        g = exact_map(rng)
        M = rot_axis(rand_unit(rng), sgn(rng) * expo(rng, 4, 14))
        f = lambda p: matvec(M, g(p))
    else:
        f = None
    out = [m.mapped(f) if f else m.copy() for m in meshes]
    return out, mode


def placed(rng, A, B, note, exact_bias=0.5, mode=None):
    (A, B), pm = place(rng, [A, B], exact_bias, mode)
    return A, B, '%s place=%s' % (note, pm)


def far_shift(rng, meshes):
    size = bbox_size(meshes[0])
    D = size * 10.0 ** rng.uniform(3.0, 7.0)
    r = rng.random()
    if r < 0.3:
        t = [0.0, 0.0, 0.0]
        t[rng.randrange(3)] = sgn(rng) * D
        how = 'axis'
    elif r < 0.6:
        e = int(math.floor(math.log(D, 2)))
        t = [sgn(rng) * (2.0 ** e) * rng.randint(1, 7) / 4.0 for _ in range(3)]
        how = 'dyadic'
    else:
        t = vmul(rand_unit(rng), D)
        how = 'dir'
    t = tuple(t)
    return [m.mapped(lambda p: vadd(p, t)) for m in meshes], 'far=%.3g(%s)' % (D / size, how)


# --------------------------------------------------------------------------
# shared bases
# --------------------------------------------------------------------------


def planar_pair_base(rng):
    """A in the z=0 plane (~[0,1]^2) and B covering the same region (copy/retri/partial)."""
    if rng.random() < 0.5:
        nx, ny = rng.randint(1, 5), rng.randint(1, 5)
        A = grid_xy(0, 0, 1, 1, nx, ny, rng.choice(DIAGS), rng)
        r = rng.random()
        if r < 0.4:
            return A, A.copy(), 'grid_copy'
        if r < 0.8:
            return A, grid_xy(0, 0, 1, 1, rng.randint(1, 5), rng.randint(1, 5),
                              rng.choice(DIAGS), rng), 'grid_retri'
        sx, sy = dyadic(rng, -0.5, 0.5, 3), dyadic(rng, -0.5, 0.5, 3)
        return A, grid_xy(sx, sy, sx + 1, sy + 1, rng.randint(1, 4), rng.randint(1, 4),
                          rng.choice(DIAGS), rng), 'grid_partial'
    pts = pick_poly(rng)
    if rng.random() < 0.35:
        (m1, k1), _ = two_methods(rng, len(pts))
        A = poly_mesh(pts, m1, k1)
        return A, A.copy(), 'poly_copy'
    A, B, nt = poly_pair(rng, pts)
    return A, B, 'poly_retri ' + nt


def base_surface(rng):
    """Returns (mesh, retri(rng) -> mesh, planar flag, name)."""
    t = rng.randrange(4)
    if t == 0:
        nx, ny = rng.randint(1, 5), rng.randint(1, 5)
        d1 = rng.choice(DIAGS)
        A = grid_xy(0, 0, 1, 1, nx, ny, d1, rng)

        def retri(r):
            if r.random() < 0.5:
                return grid_xy(0, 0, 1, 1, nx, ny, r.choice([d for d in DIAGS if d != d1]), r)
            return grid_xy(0, 0, 1, 1, r.randint(1, 5), r.randint(1, 5), r.choice(DIAGS), r)
        return A, retri, True, 'grid'
    if t == 1:
        pts = pick_poly(rng)
        A, B, nt = poly_pair(rng, pts)
        return A, (lambda r: B.copy() if r.random() < 0.7 else refine(B, r)), True, 'poly'
    if t == 2:
        f, fname = rand_height_fn(rng)
        nx, ny = rng.randint(2, 6), rng.randint(2, 6)
        d1 = rng.choice(DIAGS)
        A = heightfield(nx, ny, f, d1, rng)

        def retri(r):
            if r.random() < 0.5:
                return heightfield(nx, ny, f, r.choice([d for d in DIAGS if d != d1]), r)
            return refine(A, r)
        return A, retri, fname == 'plane', 'height_' + fname
    A, sname = random_solid(rng)
    return A, (lambda r: refine(A, r)), False, sname


# --------------------------------------------------------------------------
# kinds
# --------------------------------------------------------------------------


def k_coplanar_retri(rng):
    r = rng.random()
    if r < 0.35:
        nx, ny = rng.choice([1, 2, 3, 4, 5, 8]), rng.choice([1, 2, 3, 4])
        d1 = rng.choice(DIAGS)
        d2 = rng.choice([d for d in DIAGS if d != d1])
        A = grid_xy(0, 0, 1, 1, nx, ny, d1, rng)
        B = grid_xy(0, 0, 1, 1, nx, ny, d2, rng)
        note = 'grid%dx%d %s|%s' % (nx, ny, d1, d2)
    elif r < 0.5:
        n1 = rng.choice([1, 2, 4])
        n2 = rng.choice([1, 2, 3, 4, 6])
        A = grid_xy(0, 0, 1, 1, n1, n1, rng.choice(DIAGS), rng)
        B = grid_xy(0, 0, 1, 1, n2, rng.choice([1, 2, 3, 4]), rng.choice(DIAGS), rng)
        note = 'grid_res %d|%d' % (n1, n2)
    else:
        pts = pick_poly(rng)
        A, B, note = poly_pair(rng, pts)
        note = 'poly%d %s' % (len(pts), note)
    if rng.random() < 0.15:
        B = refine(B, rng)
        note += ' refined'
    if rng.random() < 0.2:
        B = B.flipped()
        note += ' flipped'
    return placed(rng, A, B, note, 0.6)


def k_coplanar_partial(rng):
    r = rng.random()
    if r < 0.5:
        A = grid_xy(0, 0, 1, 1, rng.randint(1, 5), rng.randint(1, 5), rng.choice(DIAGS), rng)
        if rng.random() < 0.6:
            sx, sy = dyadic(rng, -0.75, 0.75, 3), dyadic(rng, -0.75, 0.75, 3)
        else:
            sx, sy = rng.uniform(-0.8, 0.8), rng.uniform(-0.8, 0.8)
        w = rng.choice([1.0, 0.5, 0.75, rng.uniform(0.3, 1.5)])
        h = rng.choice([1.0, 0.5, 0.25, rng.uniform(0.3, 1.5)])
        B = grid_xy(sx, sy, sx + w, sy + h, rng.randint(1, 4), rng.randint(1, 4),
                    rng.choice(DIAGS), rng)
        note = 'grid shift %r %r' % (sx, sy)
    elif r < 0.75:
        pts = pick_poly(rng)
        sx, sy = dyadic(rng, -0.5, 0.5, 3), dyadic(rng, -0.5, 0.5, 3)
        if rng.random() < 0.3:
            sx = 0.0
        pts2 = [(x + sx, y + sy) for x, y in pts]
        (m1, k1), (m2, k2) = two_methods(rng, len(pts))
        A = poly_mesh(pts, m1, k1)
        B = poly_mesh(pts2, m2, k2)
        note = 'poly shift %r %r' % (sx, sy)
    else:
        pts = pick_poly(rng)
        k = rng.randrange(len(pts))
        c = pts[k]
        s = rng.choice([0.5, 0.25, 0.75, rng.uniform(0.2, 0.9)])
        pts2 = [(c[0] + (x - c[0]) * s, c[1] + (y - c[1]) * s) for x, y in pts]
        (m1, k1), (m2, k2) = two_methods(rng, len(pts))
        A = poly_mesh(pts, m1, k1)
        B = poly_mesh(pts2, m2, k2)
        if rng.random() < 0.3:
            A, B = B, A
        note = 'nested corner %d scale %r' % (k, s)
    return placed(rng, A, B, note, 0.6)


def k_coplanar_rotated(rng):
    if rng.random() < 0.5:
        n = rng.choice([1, 2, 3, 4])
        A = grid_xy(-1, -1, 1, 1, n, n, rng.choice(DIAGS), rng)
        note = 'grid%d' % n
    else:
        pts = pick_poly(rng)
        cx = sum(p[0] for p in pts) / len(pts)
        cy = sum(p[1] for p in pts) / len(pts)
        pts = [(x - cx, y - cy) for x, y in pts]
        (m1, k1), _ = two_methods(rng, len(pts))
        A = poly_mesh(pts, m1, k1)
        note = 'poly%d' % len(pts)
    B = A.copy()
    if rng.random() < 0.3:
        B = refine(B, rng)
        note += ' refined'
    mode = rng.choice(['quarter', 'half', 'random', 'tiny', 'tiny', 'pi_n'])
    if mode == 'quarter':
        B = B.mapped(lambda p: (-p[1], p[0], p[2]))
    elif mode == 'half':
        B = B.mapped(lambda p: (-p[0], -p[1], p[2]))
    else:
        if mode == 'random':
            ang = rng.uniform(0, TAU)
        elif mode == 'tiny':
            ang = sgn(rng) * expo(rng, 3, 14)
        else:
            ang = math.pi / rng.randint(3, 8)
        piv = (0.0, 0.0, 0.0) if rng.random() < 0.6 else A.v[rng.randrange(len(A.v))]
        c, s = math.cos(ang), math.sin(ang)
        B = B.mapped(lambda p: (piv[0] + c * (p[0] - piv[0]) - s * (p[1] - piv[1]),
                                piv[1] + s * (p[0] - piv[0]) + c * (p[1] - piv[1]), p[2]))
        note += ' ang=%r' % ang
    return placed(rng, A, B, note + ' ' + mode, 0.6)


def k_coplanar_tjunction(rng):
    nx, ny = rng.choice([1, 2, 3, 4]), rng.choice([1, 2, 3, 4])
    A = grid_xy(0, 0, 1, 1, nx, ny, rng.choice(DIAGS[:4]), rng)
    mode = rng.choice(['refine_x', 'split', 'medial', 'offset_half'])
    if mode == 'refine_x':
        k = rng.choice([2, 3])
        B = grid_xy(0, 0, 1, 1, nx * k, ny, rng.choice(DIAGS[:4]), rng)
    elif mode == 'split':
        B = split_edges(A, rng, rng.randint(1, max(1, len(A.f))),
                        None if rng.random() < 0.7 else rng.random())
    elif mode == 'medial':
        B = Mesh()
        for a, b, c in A.f:
            if rng.random() < 0.7:
                pa, pb, pc = A.v[a], A.v[b], A.v[c]
                B.tri_pts(vmid(pa, pb), vmid(pb, pc), vmid(pc, pa))
        if not B.f:
            a, b, c = A.f[0]
            B.tri_pts(vmid(A.v[a], A.v[b]), vmid(A.v[b], A.v[c]), vmid(A.v[c], A.v[a]))
        if rng.random() < 0.5:
            B = weld(B)
    else:
        h = 0.5 / nx
        B = grid_xy(h, 0, 1 + h, 1, nx, ny * rng.choice([1, 2]), rng.choice(DIAGS[:4]), rng)
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, mode, 0.6)


def k_near_coplanar_tilt(rng):
    A, B, note = planar_pair_base(rng)
    ang = sgn(rng) * expo(rng, 3, 14)
    r = rng.random()
    if r < 0.25:
        axis = (1.0, 0.0, 0.0)
    elif r < 0.5:
        axis = (0.0, 1.0, 0.0)
    elif r < 0.75:
        t = rng.uniform(0, TAU)
        axis = (math.cos(t), math.sin(t), 0.0)
    else:
        a, b, c = B.f[rng.randrange(len(B.f))]
        axis = vsub(B.v[b], B.v[a])
        if vlen(axis) == 0:
            axis = (1.0, 0.0, 0.0)
    r = rng.random()
    if r < 0.3:
        piv = (0.0, 0.0, 0.0)
    elif r < 0.6:
        piv = (0.5, 0.5, 0.0)
    elif r < 0.8:
        piv = B.v[rng.randrange(len(B.v))]
    else:
        piv = (rng.uniform(-1, 2), rng.uniform(-1, 2), 0.0)
    M = rot_axis(axis, ang)
    B = B.mapped(lambda p: vadd(matvec(M, vsub(p, piv)), piv))
    if rng.random() < 0.2:
        A, B = B, A
    return placed(rng, A, B, '%s tilt=%r' % (note, ang), 0.5)


def k_near_coplanar_offset(rng):
    A, B, note = planar_pair_base(rng)
    if rng.random() < 0.3:
        dz = sgn(rng) * 2.0 ** -rng.randint(10, 50)
    else:
        dz = sgn(rng) * expo(rng, 3, 15)
    dx = dy = 0.0
    r = rng.random()
    if r < 0.2:
        dx, dy = expo(rng, 3, 15) * sgn(rng), expo(rng, 3, 15) * sgn(rng)
    elif r < 0.35:
        dx = dyadic(rng, -0.5, 0.5, 3)
    B = B.mapped(lambda p: (p[0] + dx, p[1] + dy, p[2] + dz))
    if rng.random() < 0.2:
        A = A.mapped(lambda p: (p[0], p[1], p[2] - dz))
        note += ' sym'
    return placed(rng, A, B, '%s dz=%r' % (note, dz), 0.5)


def k_near_coplanar_warp(rng):
    A, B, note = planar_pair_base(rng)
    ang = sgn(rng) * expo(rng, 4, 14) if rng.random() < 0.7 else 0.0
    dz = sgn(rng) * expo(rng, 4, 15) if rng.random() < 0.7 else 0.0
    amp = expo(rng, 6, 15)
    t = rng.uniform(0, TAU)
    M = rot_axis((math.cos(t), math.sin(t), 0.0), ang)
    only_z = rng.random() < 0.6

    def noise(p, a):
        if only_z:
            return (p[0], p[1], p[2] + a * rng.uniform(-1, 1))
        return vadd(p, vmul(rand_unit(rng), a * rng.random()))
    B = B.mapped(lambda p: noise(vadd(matvec(M, p), (0.0, 0.0, dz)), amp))
    if rng.random() < 0.4:
        amp2 = expo(rng, 6, 15)
        A = A.mapped(lambda p: noise(p, amp2))
        note += ' bothwarped'
    return placed(rng, A, B, '%s ang=%r dz=%r amp=%r' % (note, ang, dz, amp), 0.4)


def k_sliver_plane(rng):
    k = rng.randint(1, 12)
    A = Mesh()
    params = []
    for _ in range(k):
        p = (rng.uniform(0, 1), rng.uniform(0, 1), 0.0)
        th = rng.uniform(0, TAU)
        d = (math.cos(th), math.sin(th), 0.0)
        nrm = (-d[1], d[0], 0.0)
        L = rng.uniform(0.2, 1.0)
        asp = aspect(rng)
        tri = sliver(rng, p, d, nrm, L, asp)
        A.tri_pts(*tri)
        params.append((p, th, d, nrm, L, asp))
    mode = rng.choice(['cover', 'mirror', 'cross', 'dup'])
    if mode == 'cover':
        if rng.random() < 0.5:
            B = grid_xy(-0.5, -0.5, 1.5, 1.5, rng.randint(1, 4), rng.randint(1, 4),
                        rng.choice(DIAGS), rng)
        else:
            B = Mesh()
            B.tri_pts((-1.0, -1.0, 0.0), (3.0, -1.0, 0.0), (-1.0, 3.0, 0.0))
    elif mode == 'mirror':
        B = Mesh()
        for p, th, d, nrm, L, asp in params:
            h = L / asp * rng.choice([-1.0, 2.0, -3.0])
            q = vadd(p, vmul(d, L))
            B.tri_pts(p, q, vadd(p, vadd(vmul(d, rng.uniform(0, 1) * L), vmul(nrm, h))))
    elif mode == 'cross':
        B = Mesh()
        for p, th, d, nrm, L, asp in params:
            a2 = th + sgn(rng) * expo(rng, 1, 8)
            d2 = (math.cos(a2), math.sin(a2), 0.0)
            n2 = (-d2[1], d2[0], 0.0)
            c = vadd(p, vmul(d, L * 0.5))
            s = vsub(c, vmul(d2, L * 0.5))
            B.tri_pts(*sliver(rng, s, d2, n2, L, aspect(rng)))
    else:
        B = Mesh(A.v, [(b, c, a) for a, b, c in A.f])
        if len(B.f) > 1:
            B.f.pop(rng.randrange(len(B.f)))
        B.tri_pts((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, mode, 0.5)


def k_sliver_above(rng):
    if rng.random() < 0.7:
        n = rng.choice([1, 2, 4])
        A = grid_xy(0, 0, 1, 1, n, n, rng.choice(DIAGS), rng)
    else:
        n = 1
        A = Mesh()
        A.tri_pts((-0.5, -0.5, 0.0), (2.0, -0.5, 0.0), (-0.5, 2.0, 0.0))
    mode = rng.choice(['parallel', 'vertical', 'tilted', 'edge_above'])
    B = Mesh()
    for _ in range(rng.randint(1, 10)):
        p = (rng.uniform(0, 1), rng.uniform(0, 1), 0.0)
        h = 0.0 if rng.random() < 0.15 else expo(rng, 1, 15)
        if rng.random() < 0.2:
            h = -h
        L = rng.uniform(0.1, 1.0)
        asp = aspect(rng)
        if mode == 'parallel':
            th = rng.uniform(0, TAU)
            d = (math.cos(th), math.sin(th), 0.0)
            B.tri_pts(*sliver(rng, (p[0], p[1], h), d, (-d[1], d[0], 0.0), L, asp))
        elif mode == 'vertical':
            d = (0.0, 0.0, 1.0) if rng.random() < 0.6 else vnorm((rng.uniform(-.3, .3), rng.uniform(-.3, .3), 1.0))
            th = rng.uniform(0, TAU)
            nrm = vnorm(vcross(d, (math.cos(th), math.sin(th), 0.0)))
            tip = (p[0], p[1], h)
            w = L / asp
            B.tri_pts(tip, vadd(tip, vmul(d, L)), vadd(vadd(tip, vmul(d, L)), vmul(nrm, w)))
        elif mode == 'tilted':
            th = rng.uniform(0, TAU)
            d = (math.cos(th) * L, math.sin(th) * L, expo(rng, 1, 15) * sgn(rng))
            q = vadd((p[0], p[1], h), d)
            nrm = vnorm(vcross(d, (0.0, 0.0, 1.0)))
            B.tri_pts((p[0], p[1], h), q, vadd(vlerp((p[0], p[1], h), q, rng.random()),
                                               vmul(nrm, L / asp)))
        else:
            i = rng.randint(0, n)
            x = i / float(n)
            y0 = rng.uniform(-0.2, 0.5)
            pa = (x, y0, h)
            if rng.random() < 0.5:
                B.tri_pts(pa, (x, y0 + L, h), (x + L / asp, y0 + rng.uniform(0, L), h))
            else:
                B.tri_pts(pa, (x, y0 + L, h), (x, y0 + rng.uniform(0, L), h + L / asp))
    if rng.random() < 0.25:
        A, B = B, A
    return placed(rng, A, B, mode, 0.5)


def k_sliver_cross(rng):
    if rng.random() < 0.6:
        n = rng.choice([1, 2, 4])
        A = grid_xy(0, 0, 1, 1, n, n, rng.choice(DIAGS), rng)
    else:
        n = 1
        A = Mesh()
        A.tri_pts((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
        A.tri_pts((1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0))
    B = Mesh()
    mode = rng.choice(['steep', 'grazing', 'through_vertex', 'mixed'])
    for _ in range(rng.randint(1, 10)):
        m = mode if mode != 'mixed' else rng.choice(['steep', 'grazing', 'through_vertex'])
        c = (rng.uniform(0, 1), rng.uniform(0, 1), 0.0)
        if m == 'steep':
            a, b = rng.uniform(0.05, 1), rng.uniform(0.05, 1)
            d = vnorm((rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0))
        elif m == 'grazing':
            a = b = 1.0
            th = rng.uniform(0, TAU)
            d = vnorm((math.cos(th), math.sin(th), expo(rng, 3, 14)))
            a, b = rng.uniform(0.1, 0.6), rng.uniform(0.1, 0.6)
        else:
            c = (rng.randint(0, n) / float(n), rng.randint(0, n) / float(n), 0.0)
            d = rng.choice([(1.0, 0.0, 1.0), (0.0, 1.0, 1.0), (1.0, 1.0, 1.0),
                            (0.0, 0.0, 1.0), (1.0, -1.0, 0.5)])
            a, b = rng.choice([0.25, 0.5, 1.0]), rng.choice([0.25, 0.5, 1.0])
        e1 = vsub(c, vmul(d, a))
        e2 = vadd(c, vmul(d, b))
        L = vlen(vsub(e2, e1))
        nrm = perp_unit(rng, vnorm(d))
        apex = vadd(vlerp(e1, e2, rng.uniform(-0.2, 1.2)), vmul(nrm, L / aspect(rng)))
        B.tri_pts(e1, e2, apex)
    if rng.random() < 0.25:
        A, B = B, A
    return placed(rng, A, B, mode, 0.5)


def k_sliver_fan(rng):
    k = rng.randint(2, 24)
    R = rng.choice([1.0, 0.5, rng.uniform(0.3, 1.5)])
    hc = rng.choice([0.0, 0.0, 0.5, -0.25, 1.0])
    contiguous = rng.random() < 0.4
    A = Mesh()
    O = A.add((0.0, 0.0, 0.0))

    def P(a):
        return (R * math.cos(a), R * math.sin(a), hc)
    th = rng.uniform(0, TAU)
    if contiguous:
        angs = [th]
        for _ in range(k):
            angs.append(angs[-1] + expo(rng, 3, 12))
        ids = [A.add(P(a)) for a in angs]
        for i in range(k):
            A.tri(O, ids[i], ids[i + 1])
    else:
        for i in range(k):
            a = th + TAU * i / k
            A.tri(O, A.add(P(a)), A.add(P(a + expo(rng, 3, 12))))
    mode = rng.choice(['axis', 'apex_shift', 'plane', 'rotfan', 'mirror'])
    B = Mesh()
    if mode == 'axis':
        zs = [rng.choice([0.5, 1.0, -1.0, 0.25, -0.5, 2.0]) for _ in range(3)]
        if rng.random() < 0.5:
            degen_tri(B, (0.0, 0.0, zs[0]), rng.choice(['index', 'coords']))
        else:
            B.tri_pts((0.0, 0.0, zs[0]), (0.0, 0.0, zs[1]), (0.0, 0.0, zs[2]))
        if rng.random() < 0.4:
            s = rng.choice([0.25, 0.125])
            z = zs[1]
            B.tri_pts((s, 0.0, z), (-s, s, z), (-s, -s, z))
    elif mode == 'apex_shift':
        eps = expo(rng, 6, 12)
        d = rand_unit(rng)
        B = A.copy()
        B.v[O] = vadd(B.v[O], vmul(d, eps))
    elif mode == 'plane':
        if hc == 0.0 or rng.random() < 0.5:
            B = poly_mesh(ring_pts(rng.choice([3, 4, 6]), 2.5 * R), 'fan', 0, 0.0)
        else:
            B = poly_mesh(ring_pts(4, 2.0 * R), 'fan', 0, hc)
    elif mode == 'rotfan':
        ang = sgn(rng) * expo(rng, 3, 13)
        c, s = math.cos(ang), math.sin(ang)
        B = A.mapped(lambda p: (c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]))
    else:
        B = A.mapped(lambda p: (p[0], p[1], -p[2])).flipped()
        if hc == 0.0:
            B = B.mapped(lambda p: (p[0], -p[1], p[2]))
    if rng.random() < 0.2:
        A, B = B, A
    return placed(rng, A, B, '%s k=%d contiguous=%s hc=%r' % (mode, k, contiguous, hc), 0.6)


def k_sliver_tip_touch(rng):
    r = rng.random()
    if r < 0.4:
        A = grid_xy(0, 0, 1, 1, rng.randint(1, 3), rng.randint(1, 3), rng.choice(DIAGS[:4]), rng)
    elif r < 0.7:
        A, _ = random_solid(rng)
    else:
        A = Mesh()
        for _ in range(rng.randint(1, 4)):
            A.tri_pts(*[(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1))
                        for _ in range(3)])
    B = Mesh()
    zero = 0
    for _ in range(rng.randint(1, 10)):
        a, b, c = A.f[rng.randrange(len(A.f))]
        pa, pb, pc = A.v[a], A.v[b], A.v[c]
        t = rng.random()
        if t < 0.35:
            target = pa
        elif t < 0.75:
            target = vlerp(pa, pb, rng.choice([0.5, 0.25, rng.random()]))
        else:
            w1, w2 = rng.random(), rng.random()
            if w1 + w2 > 1:
                w1, w2 = 1 - w1, 1 - w2
            target = vadd(pa, vadd(vmul(vsub(pb, pa), w1), vmul(vsub(pc, pa), w2)))
        nf = vnorm(vcross(vsub(pb, pa), vsub(pc, pa)))
        if rng.random() < 0.1:
            eps = 0.0
            zero += 1
        else:
            eps = expo(rng, 7, 12)
        dm = rng.random()
        if dm < 0.4:
            dr = vmul(nf, sgn(rng))
        elif dm < 0.7:
            dr = vnorm(vcross(nf, vsub(pb, pa)))
        else:
            dr = rand_unit(rng)
        tip = vadd(target, vmul(dr, eps))
        d = rand_unit(rng)
        if vdot(d, dr) < 0 and rng.random() < 0.7:
            d = vmul(d, -1.0)
        L = rng.uniform(0.1, 1.0)
        nn = perp_unit(rng, d)
        far = vadd(tip, vmul(d, L))
        B.tri_pts(tip, far, vadd(far, vmul(nn, L / aspect(rng))))
    if rng.random() < 0.25:
        A, B = B, A
    return placed(rng, A, B, 'zero_eps=%d' % zero, 0.4)


def k_wall_floor(rng):
    nx, ny = rng.choice([1, 2, 4]), rng.choice([1, 2, 4])
    A = grid_xy(0, 0, 1, 1, nx, ny, rng.choice(DIAGS), rng)
    B = Mesh()
    mode = rng.choice(['touch', 'float', 'sink', 'tilt', 'L', 'multi'])
    nw = rng.randint(2, 3) if mode == 'multi' else 1
    for _ in range(nw):
        if rng.random() < 0.7:
            c = rng.randint(0, nx) / float(nx)
        else:
            c = rng.uniform(0, 1)
        y0 = rng.choice([0.0, 0.25, -0.25, rng.uniform(-0.3, 0.5)])
        y1 = rng.choice([1.0, 0.75, 1.25, rng.uniform(0.6, 1.3)])
        H = rng.choice([1.0, 0.5, rng.uniform(0.2, 1.0)])
        if mode == 'float':
            zb = expo(rng, 1, 15)
        elif mode == 'sink':
            zb = -expo(rng, 1, 15)
        else:
            zb = 0.0
        ev = (0.0, 0.0, H)
        if mode == 'tilt':
            a = sgn(rng) * expo(rng, 3, 14)
            ev = (math.sin(a) * H, 0.0, math.cos(a) * H)
        wall = param_grid((c, y0, zb), (0.0, y1 - y0, 0.0), ev,
                          rng.randint(1, 4), rng.randint(1, 3), rng.choice(DIAGS), rng)
        if rng.random() < 0.5:
            wall = wall.mapped(lambda p: (p[1], p[0], p[2]))   # wall along x instead
        B.merge(wall)
    if mode == 'L':
        A = weld(merged(A, param_grid((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0),
                                      rng.randint(1, 3), ny, rng.choice(DIAGS), rng)))
        B = weld(merged(grid_xy(0, 0, 1, 1, rng.randint(1, 3), rng.randint(1, 3),
                                rng.choice(DIAGS), rng),
                        param_grid((0.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, 1.0, 0.0),
                                   rng.randint(1, 3), rng.randint(1, 3), rng.choice(DIAGS), rng)))
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, mode, 0.6)


def hinge_dir(rng):
    r = rng.random()
    if r < 0.2:
        return (0.0, 1.0, 0.0), '90'      # (y,z) components of flap-2 direction
    if r < 0.35:
        return (-1.0, 0.0, 0.0), '180'
    if r < 0.45:
        return (-1.0, 1.0, 0.0), '135'
    if r < 0.5:
        return (1.0, 1.0, 0.0), '45'
    if r < 0.7:
        e = expo(rng, 3, 12) * sgn(rng)
        return (-math.cos(e), math.sin(e), 0.0), '180-%.3g' % e
    if r < 0.8:
        e = expo(rng, 3, 12)
        return (math.cos(e), math.sin(e), 0.0), '0+%.3g' % e
    a = rng.uniform(0.2, math.pi - 0.2)
    return (math.cos(a), math.sin(a), 0.0), '%.4f' % a


def hinge_mesh(rng, dr, w1, w2, n, m1, m2, diag):
    f1 = param_grid((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, w1, 0.0), n, m1, diag, rng)
    f2 = param_grid((0.0, 0.0, 0.0), (0.0, dr[0] * w2, dr[1] * w2), (1.0, 0.0, 0.0),
                    m2, n, diag, rng)
    return weld(merged(f1, f2))


def k_hinge(rng):
    da, na = hinge_dir(rng)
    w1, w2 = rng.choice([1.0, 0.5, 0.75]), rng.choice([1.0, 0.5, 0.25])
    n = rng.randint(1, 4)
    A = hinge_mesh(rng, da, w1, w2, n, rng.randint(1, 3), rng.randint(1, 3), rng.choice(DIAGS))
    mode = rng.choice(['retri', 'tilt', 'flat', 'flap2only', 'mirror', 'other'])
    if mode == 'retri':
        B = hinge_mesh(rng, da, w1, w2, rng.randint(1, 4), rng.randint(1, 3),
                       rng.randint(1, 3), rng.choice(DIAGS))
    elif mode == 'tilt':
        e = sgn(rng) * expo(rng, 3, 13)
        c, s = math.cos(e), math.sin(e)
        db = (c * da[0] - s * da[1], s * da[0] + c * da[1], 0.0)
        B = hinge_mesh(rng, db, w1, w2, rng.randint(1, 4), rng.randint(1, 3),
                       rng.randint(1, 3), rng.choice(DIAGS))
    elif mode == 'flat':
        B = grid_xy(0, -w2, 1, w1, rng.randint(1, 4), rng.randint(1, 4), rng.choice(DIAGS), rng)
    elif mode == 'flap2only':
        db, nb = hinge_dir(rng)
        B = param_grid((0.0, 0.0, 0.0), (0.0, db[0] * w2, db[1] * w2), (1.0, 0.0, 0.0),
                       rng.randint(1, 3), rng.randint(1, 4), rng.choice(DIAGS), rng)
        mode += nb
    elif mode == 'mirror':
        B = A.mapped(lambda p: (p[0], p[1], -p[2])).flipped()
    else:
        db, nb = hinge_dir(rng)
        B = hinge_mesh(rng, db, w1, w2, rng.randint(1, 4), rng.randint(1, 3),
                       rng.randint(1, 3), rng.choice(DIAGS))
        mode += nb
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, 'angle=%s %s' % (na, mode), 0.6)


def k_fin_plate(rng):
    nx, ny = rng.choice([1, 2, 4]), rng.choice([1, 2, 4])
    A = grid_xy(0, 0, 1, 1, nx, ny, rng.choice(DIAGS), rng)
    B = Mesh()
    nfin = rng.randint(1, 5)
    for _ in range(nfin):
        c = rng.randint(0, nx) / float(nx) if rng.random() < 0.6 else rng.uniform(0, 1)
        a = rng.choice([0.0, 0.25, rng.uniform(-0.2, 0.5)])
        b = rng.choice([1.0, 0.75, rng.uniform(0.55, 1.2)])
        zr = rng.random()
        if zr < 0.4:
            zb = 0.0
        elif zr < 0.6:
            zb = expo(rng, 1, 15)
        elif zr < 0.8:
            zb = -expo(rng, 1, 15)
        else:
            zb = -rng.choice([0.25, 0.5])
        H = rng.choice([0.5, 1.0, rng.uniform(0.1, 1.0)])
        fin = param_grid((c, a, zb), (0.0, b - a, 0.0), (0.0, 0.0, H),
                         rng.randint(1, 3), rng.randint(1, 2), rng.choice(DIAGS), rng)
        if rng.random() < 0.3:
            t = expo(rng, 5, 15)
            fin.merge(fin.mapped(lambda p: (p[0] + t, p[1], p[2])).flipped())
        if rng.random() < 0.4:
            fin = fin.mapped(lambda p: (p[1], p[0], p[2]))
        B.merge(fin)
    if rng.random() < 0.3:
        A = merged(A, B)
        B = grid_xy(0, 0, 1, 1, rng.randint(1, 4), rng.randint(1, 4), rng.choice(DIAGS), rng)
        note = 'plate+fins vs plate'
    else:
        note = 'plate vs %d fins' % nfin
    if rng.random() < 0.25:
        A, B = B, A
    return placed(rng, A, B, note, 0.6)


def k_box_coincident(rng):
    sub1 = (rng.randint(1, 2), rng.randint(1, 2), rng.randint(1, 2))
    sub2 = (rng.randint(1, 2), rng.randint(1, 2), rng.randint(1, 2))
    d1, d2 = rng.choice(DIAGS[:4]), rng.choice(DIAGS[:4])
    mode = rng.choice(['adjacent', 'shifted', 'retri', 'nested', 'stacked'])
    A = box(0, 0, 0, 1, 1, 1, sub1, d1, rng)
    if mode == 'adjacent':
        B = box(1, 0, 0, 2, 1, 1, sub2, d2, rng)
    elif mode == 'shifted':
        sy = dyadic(rng, -0.75, 0.75, 2)
        sz = dyadic(rng, -0.75, 0.75, 2)
        ox = rng.choice([1.0, 0.5, 0.0])
        B = box(ox, sy, sz, ox + 1, sy + 1, sz + 1, sub2, d2, rng)
    elif mode == 'retri':
        B = box(0, 0, 0, 1, 1, 1, sub2, d2, rng, welded=rng.random() < 0.5)
        if rng.random() < 0.3:
            B = B.flipped()
    elif mode == 'nested':
        s = rng.choice([0.5, 0.25, 0.75])
        oy = rng.choice([0.0, 0.25])
        B = box(0, oy, 0, s, oy + s, s, sub2, d2, rng)
    else:
        A = merged(box(0, 0, 0, 1, 1, 0.5, sub1, d1, rng), box(0, 0, 0.5, 1, 1, 1, sub1, d1, rng))
        B = box(0, 0, 0, 1, 1, 1, sub2, d2, rng)
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, mode, 0.6)


def add_degenerates(m, rng, k):
    m = m.copy()
    n0 = len(m.v)
    kinds = []
    for _ in range(k):
        t = rng.randrange(7)
        i, j = rng.randrange(n0), rng.randrange(n0)
        if t == 0:
            m.tri(i, i, j)
        elif t == 1:
            m.tri(i, i, i)
        elif t == 2:
            m.tri(i, m.add(m.v[i]), j)
        elif t == 3 or t == 4:
            a, b, c = m.f[rng.randrange(len(m.f))]
            pa, pb = m.v[a], m.v[b]
            if t == 3:
                m.tri(a, m.add(vmid(pa, pb)), b)
            else:
                m.tri(a, b, m.add(vadd(pa, vmul(vsub(pb, pa), 2.0))))
        elif t == 5:
            p = m.v[i]
            m.tri_pts(p, p, p)
        else:
            a, b, c = m.f[rng.randrange(len(m.f))]
            m.tri(a, b, a)
        kinds.append(t)
    if rng.random() < 0.5:
        rng.shuffle(m.f)
    return m, kinds


def k_zero_area_mix(rng):
    S, retri, planar, name = base_surface(rng)
    A, kinds = add_degenerates(S, rng, rng.randint(1, 12))
    mode = rng.choice(['clean', 'retri', 'both', 'perturb'])
    if mode == 'clean':
        B = S.copy()
    elif mode == 'retri':
        B = retri(rng)
    elif mode == 'both':
        B, _ = add_degenerates(retri(rng), rng, rng.randint(1, 8))
    else:
        amp = expo(rng, 4, 14)
        B = S.mapped(lambda p: vadd(p, vmul(rand_unit(rng), amp)))
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, '%s %s degen=%s' % (name, mode, kinds), 0.5)


def k_dup_flip_unwelded(rng):
    S, retri, planar, name = base_surface(rng)
    A = S.copy()
    if rng.random() < 0.4:
        A = unweld(A)
        name += ' unwelded'
    ops = []
    for _ in range(rng.randint(1, 10)):
        if len(A.f) >= MAX_FACES:
            break
        i = rng.randrange(len(A.f))
        a, b, c = A.f[i]
        t = rng.randrange(5)
        if t == 0:
            A.f.append((a, b, c))
        elif t == 1:
            A.f.append((a, c, b))
        elif t == 2:
            A.f[i] = (a, c, b)
        elif t == 3:
            A.f.append((b, c, a))
        else:
            A.tri_pts(A.v[a], A.v[b], A.v[c])
        ops.append(t)
    if rng.random() < 0.5:
        rng.shuffle(A.f)
    mode = rng.choice(['clean', 'unwelded_flipped', 'retri', 'dup_all'])
    if mode == 'clean':
        B = S.copy()
    elif mode == 'unwelded_flipped':
        B = unweld(S).flipped()
    elif mode == 'retri':
        B = retri(rng)
    else:
        B = S.copy()
        if 2 * len(B.f) <= MAX_FACES:
            B.f.extend([(a, c, b) for a, b, c in S.f])
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, '%s %s ops=%s' % (name, mode, ops), 0.5)


def jitter(m, rng, amp, frac=1.0):
    return m.mapped(lambda p: vadd(p, vmul(rand_unit(rng), amp * rng.random()))
                    if rng.random() < frac else p)


def k_jitter_far(rng):
    S, retri, planar, name = base_surface(rng)
    (A, B), pm = place(rng, [S, S.copy()], 0.4)
    (A, B), fn = far_shift(rng, [A, B])
    size = bbox_size(A)
    amp = size * expo(rng, 6, 15)
    mode = rng.choice(['all', 'some', 'normal', 'both'])
    if mode == 'all':
        B = jitter(B, rng, amp)
    elif mode == 'some':
        B = jitter(B, rng, amp, rng.uniform(0.1, 0.6))
    elif mode == 'normal':
        nrm = mesh_normal(A)
        B = B.mapped(lambda p: vadd(p, vmul(nrm, amp * rng.uniform(-1, 1))))
    else:
        A = jitter(A, rng, amp)
        B = jitter(B, rng, amp)
    return A, B, '%s %s amp=%.3g place=%s %s' % (name, mode, amp / size, pm, fn)


def k_retri_far(rng):
    S, retri, planar, name = base_surface(rng)
    B = retri(rng)
    (A, B), pm = place(rng, [S, B], 0.4)
    (A, B), fn = far_shift(rng, [A, B])
    note = ''
    if rng.random() < 0.3:
        amp = bbox_size(A) * expo(rng, 8, 15)
        B = jitter(B, rng, amp)
        note = ' jit'
    if rng.random() < 0.3:
        A, B = B, A
    return A, B, '%s%s place=%s %s' % (name, note, pm, fn)


def offset_op(rng, A, B, planar, eps):
    mode = rng.choice(['normal', 'dir', 'scale', 'tilt'])
    c = centroid(B)
    if mode == 'normal':
        d = mesh_normal(A) if planar else rand_unit(rng)
        return B.mapped(lambda p: vadd(p, vmul(d, eps))), mode
    if mode == 'dir':
        d = rand_unit(rng)
        return B.mapped(lambda p: vadd(p, vmul(d, eps))), mode
    if mode == 'scale':
        f = 1.0 + sgn(rng) * eps
        return B.mapped(lambda p: vadd(c, vmul(vsub(p, c), f))), mode
    M = rot_axis(rand_unit(rng), sgn(rng) * eps)
    return B.mapped(lambda p: vadd(c, matvec(M, vsub(p, c)))), mode


def k_offset_far(rng):
    S, retri, planar, name = base_surface(rng)
    B = S.copy() if rng.random() < 0.6 else retri(rng)
    rel = expo(rng, 3, 9)
    pre = rng.random() < 0.5
    if pre:
        B, om = offset_op(rng, S, B, planar, rel * bbox_size(S))
    (A, B), pm = place(rng, [S, B], 0.4)
    (A, B), fn = far_shift(rng, [A, B])
    if not pre:
        B, om = offset_op(rng, A, B, planar, rel * bbox_size(A))
    return A, B, '%s %s rel=%.3g pre=%s place=%s %s' % (name, om, rel, pre, pm, fn)


def k_scale_extreme(rng):
    subs = [k_coplanar_retri, k_coplanar_tjunction, k_near_coplanar_offset,
            k_near_coplanar_tilt, k_sliver_plane, k_sliver_tip_touch, k_sliver_fan,
            k_box_coincident, k_hinge, k_wall_floor, k_solid_perturb,
            k_equi_sym_solid, k_equi_cone_axis, k_zero_area_mix]
    sub = rng.choice(subs)
    A, B, note = sub(rng)
    r = rng.random()
    if r < 0.45:
        e = rng.randint(-20, 20)
        f = 2.0 ** e
    elif r < 0.9:
        f = 10.0 ** rng.uniform(-6, 6)
    else:
        f = rng.choice([1e-6, 1e6])
    A = A.mapped(lambda p: vmul(p, f))
    B = B.mapped(lambda p: vmul(p, f))
    return A, B, '%s x%r (%s)' % (sub.__name__[2:], f, note)


def k_solid_simplify(rng):
    mode = rng.choice(['cyl', 'sphere', 'geo', 'collapse', 'height'])
    if mode == 'cyl':
        m = rng.randint(3, 12)
        ph = 0.0 if rng.random() < 0.7 else rng.uniform(0, TAU / m)
        cc = rng.random() < 0.5
        h = rng.choice([1.0, 2.0, 0.5])
        A = cylinder(2 * m, 1.0, h, 0.0, True, cc)
        B = cylinder(m, 1.0, h, ph, True, rng.random() < 0.5)
        note = 'cyl %d vs %d' % (2 * m, m)
    elif mode == 'sphere':
        nl, no = rng.randint(4, 6), rng.randint(6, 10)
        A = uv_sphere(nl, no)
        B = uv_sphere(rng.randint(2, nl - 1), rng.randint(3, no - 2))
        note = 'uv'
    elif mode == 'geo':
        A = geo_octa(rng.choice([1, 2]))
        B = geo_octa(0) if rng.random() < 0.6 else geo_octa(1)
        note = 'geo'
    elif mode == 'collapse':
        S, sname = random_solid(rng)
        A = S
        B = collapse(S, rng, rng.randint(1, max(1, len(S.f) // 4)))
        note = 'collapse ' + sname
    else:
        f, fname = rand_height_fn(rng)
        n = rng.randint(2, 4)
        A = heightfield(2 * n, 2 * n, f, rng.choice(DIAGS[:4]), rng)
        B = heightfield(n, n, f, rng.choice(DIAGS[:4]), rng)
        note = 'height ' + fname
    if rng.random() < 0.3:
        A, B = B, A
    return placed(rng, A, B, mode + ' ' + note, 0.4)


def k_solid_refine(rng):
    t = rng.randrange(5)
    if t == 0:
        S = tetra()
    elif t == 1:
        S = octa()
    elif t == 2:
        S = box(-1, -1, -1, 1, 1, 1, (1, 1, 1), rng.choice(DIAGS[:4]), rng)
    elif t == 3:
        S = prism(pick_poly(rng), 0.0, rng.choice([1.0, 0.5]))
    else:
        S = cylinder(rng.randint(3, 8), 1.0, 1.0, 0.0, True, False)
    mode = rng.choice(['sub4', 'sub3', 'split', 'sub4_nudge', 'project'])
    if mode == 'sub4' or (mode == 'project' and t != 1):
        B = subdivide4(S)
        if len(B.f) <= 50 and rng.random() < 0.3:
            B = subdivide4(B)
    elif mode == 'sub3':
        B = subdivide3(S)
    elif mode == 'split':
        B = split_edges(S, rng, rng.randint(1, len(S.f)))
    elif mode == 'sub4_nudge':
        B = subdivide4(S)
        n0 = len(S.v)
        amp = expo(rng, 3, 15)
        B.v = B.v[:n0] + [vadd(p, vmul(rand_unit(rng), amp)) for p in B.v[n0:]]
    else:
        B = geo_octa(1)
    if rng.random() < 0.3:
        S, B = B, S
    return placed(rng, S, B, mode, 0.5)


def k_solid_perturb(rng):
    S, name = random_solid(rng)
    mode = rng.choice(['noise', 'inflate', 'scale', 'rotate', 'translate'])
    eps = expo(rng, 2, 12)
    if mode == 'noise':
        B = jitter(S, rng, eps)
    elif mode == 'inflate':
        B = S.mapped(lambda p: vadd(p, vmul(vnorm(p), eps)))
    elif mode == 'scale':
        f = 1.0 + sgn(rng) * eps
        B = S.mapped(lambda p: vmul(p, f))
    elif mode == 'rotate':
        M = rot_axis(rand_unit(rng), sgn(rng) * eps)
        B = S.mapped(lambda p: matvec(M, p))
    else:
        d = vmul(rand_unit(rng), eps)
        B = S.mapped(lambda p: vadd(p, d))
    if rng.random() < 0.3:
        S, B = B, S
    return placed(rng, S, B, '%s %s eps=%.3g' % (name, mode, eps), 0.4)


def k_heightfield_pair(rng):
    f, fname = rand_height_fn(rng)
    n1, m1 = rng.randint(1, 6), rng.randint(1, 6)
    r = rng.random()
    if r < 0.35:
        n2, m2 = n1, m1
    elif r < 0.7:
        n2, m2 = min(2 * n1, 8), min(2 * m1, 8)
    else:
        n2, m2 = rng.randint(1, 6), rng.randint(1, 6)
    d1 = rng.choice(DIAGS)
    d2 = rng.choice(DIAGS)
    if d2 in ('c', 'mixc') and n2 * m2 > 40:   # keep <= 200 faces without subsampling
        d2 = 'alt'
    A = heightfield(n1, m1, f, d1, rng)
    B = heightfield(n2, m2, f, d2, rng)
    if rng.random() < 0.25:
        dz = sgn(rng) * expo(rng, 3, 15)
        B = B.mapped(lambda p: (p[0], p[1], p[2] + dz))
        fname += ' dz=%r' % dz
    return placed(rng, A, B, '%s %dx%d%s|%dx%d%s' % (fname, n1, m1, d1, n2, m2, d2), 0.5)


def d4_rim(rng, r):
    """Rim with exact D4 symmetry (dyadic), or a regular n-gon (near-ties only)."""
    t = rng.random()
    if t < 0.35:
        return [(r, 0.0), (0.0, r), (-r, 0.0), (0.0, -r)], 'sq'
    if t < 0.5:
        return [(r, r), (-r, r), (-r, -r), (r, -r)], 'sq45'
    if t < 0.7:
        a = r * rng.choice([0.75, 0.5, 0.625])
        return [(r, 0.0), (a, a), (0.0, r), (-a, a), (-r, 0.0), (-a, -a), (0.0, -r), (a, -a)], 'oct'
    n = rng.choice([3, 5, 6, 7, 8, 12, 16])
    return ring_pts(n, r, 0.0), 'reg%d' % n


def k_equi_cone_axis(rng):
    r = rng.choice([1.0, 0.5, 2.0, 0.75])
    h = rng.choice([0.0, 1.0, 0.5, 2.0, -1.0, 0.25])
    rim, rname = d4_rim(rng, r)
    n = len(rim)
    A = Mesh()
    apex = A.add((0.0, 0.0, h))
    ids = [A.add((x, y, 0.0)) for x, y in rim]
    for i in range(n):
        A.tri(apex, ids[i], ids[(i + 1) % n])
    if h != 0.0 and rng.random() < 0.4:
        if rng.random() < 0.5:
            c = A.add((0.0, 0.0, 0.0))
            for i in range(n):
                A.tri(c, ids[(i + 1) % n], ids[i])
        else:
            ap2 = A.add((0.0, 0.0, -h))
            for i in range(n):
                A.tri(ap2, ids[(i + 1) % n], ids[i])
    mode = rng.choice(['axis_seg', 'axis_point', 'coax_poly', 'coax_cone', 'multi_point'])
    B = Mesh()
    zs = [0.5, 1.0, -1.0, 0.25, -0.5, 2.0, 0.0, 0.125, -0.25]
    if mode == 'axis_seg':
        B.tri_pts((0.0, 0.0, rng.choice(zs)), (0.0, 0.0, rng.choice(zs)),
                  (0.0, 0.0, rng.choice(zs)))
    elif mode == 'axis_point':
        degen_tri(B, (0.0, 0.0, rng.choice(zs)), rng.choice(['index', 'coords']))
    elif mode == 'coax_poly':
        s = rng.choice([0.25, 0.125, 0.5])
        z = rng.choice(zs)
        if rng.random() < 0.5:
            pts = [(x * s, y * s) for x, y in rim]
        else:
            pts = [(x * s, y * s) for x, y in d4_rim(rng, 1.0)[0]]
        B = poly_mesh(pts, 'steiner', 0, z, (0.0, 0.0))
    elif mode == 'coax_cone':
        f = rng.choice([0.5, 0.25, 2.0])
        B = Mesh()
        ap = B.add((0.0, 0.0, rng.choice(zs)))
        bid = [B.add((x * f, y * f, 0.0)) for x, y in rim]
        for i in range(n):
            B.tri(ap, bid[i], bid[(i + 1) % n])
    else:
        for _ in range(rng.randint(2, 6)):
            degen_tri(B, (0.0, 0.0, rng.choice(zs)), rng.choice(['index', 'coords']))
    if rng.random() < 0.2:
        A, B = B, A
    return placed(rng, A, B, '%s h=%r %s' % (rname, h, mode), 0.75)


def k_equi_sym_solid(rng):
    t = rng.randrange(3)
    if t == 0:
        sub = rng.choice([1, 2])
        A = box(-1, -1, -1, 1, 1, 1, (sub, sub, sub), rng.choice(['/', '\\', 'alt', 'c']), rng)
        name = 'cube%d' % sub
    elif t == 1:
        A = octa(1.0)
        name = 'octa'
    else:
        A = tetra(1.0)
        name = 'tetra'
    mode = rng.choice(['center', 'dual', 'scaled', 'diag_seg', 'perm', 'axis_pts'])
    B = Mesh()
    if mode == 'center':
        degen_tri(B, (0.0, 0.0, 0.0), rng.choice(['index', 'coords']))
    elif mode == 'dual':
        s = rng.choice([0.5, 0.25, 1.0, 0.75])
        B = octa(s) if t != 1 else box(-s, -s, -s, s, s, s, (1, 1, 1), rng.choice(DIAGS[:3]), rng)
    elif mode == 'scaled':
        s = rng.choice([0.5, 0.25, 2.0, 0.75])
        B = A.mapped(lambda p: vmul(p, s))
    elif mode == 'diag_seg':
        for _ in range(rng.randint(1, 4)):
            d = (sgn(rng), sgn(rng), sgn(rng))
            ts = [rng.choice([0.0, 0.25, 0.5, 0.125, -0.25]) for _ in range(3)]
            B.tri_pts(vmul(d, ts[0]), vmul(d, ts[1]), vmul(d, ts[2]))
    elif mode == 'perm':
        B = A.mapped(lambda p: (p[1], p[2], p[0]))
        if rng.random() < 0.5:
            B = B.mapped(lambda p: (-p[0], p[1], p[2])).flipped()
    else:
        for ax in range(3):
            for s in (-1.0, 1.0):
                if rng.random() < 0.6:
                    p = [0.0, 0.0, 0.0]
                    p[ax] = s * rng.choice([0.25, 0.5, 0.75])
                    degen_tri(B, tuple(p), rng.choice(['index', 'coords']))
        if not B.f:
            degen_tri(B, (0.5, 0.0, 0.0), 'index')
    if rng.random() < 0.2:
        A, B = B, A
    return placed(rng, A, B, '%s %s' % (name, mode), 0.75)


def k_equi_grid_centers(rng):
    n = rng.choice([1, 2, 4])
    A = grid_xy(0, 0, 1, 1, n, n, rng.choice(DIAGS), rng)
    cell = 1.0 / n
    mode = rng.choice(['points', 'needles', 'dual_grid', 'tiny_tris'])
    hs = [0.0, 0.25, 0.5, 0.125, 2.0 ** -20, 2.0 ** -40, 1.0, -0.25]
    B = Mesh()

    def sites():
        out = []
        for _ in range(rng.randint(1, 10)):
            t = rng.randrange(3)
            i, j = rng.randrange(n), rng.randrange(n)
            if t == 0:
                out.append(((i + 0.5) * cell, (j + 0.5) * cell))
            elif t == 1:
                out.append((rng.randint(0, n) * cell, rng.randint(0, n) * cell))
            else:
                out.append(((i + 0.5) * cell, rng.randint(0, n) * cell))
        return out
    if mode == 'points':
        for x, y in sites():
            degen_tri(B, (x, y, rng.choice(hs)), rng.choice(['index', 'coords']))
    elif mode == 'needles':
        for x, y in sites():
            z0, z1 = rng.choice(hs), rng.choice(hs)
            B.tri_pts((x, y, z0), (x, y, z1), (x, y, (z0 + z1) * 0.5))
    elif mode == 'dual_grid':
        h = rng.choice(hs)
        B = grid_xy(0.5 * cell, 0.5 * cell, 1 + 0.5 * cell, 1 + 0.5 * cell, n, n,
                    rng.choice(DIAGS), rng, z=h)
    else:
        s = cell * rng.choice([0.25, 0.125])
        for x, y in sites():
            z = rng.choice(hs)
            B.tri_pts((x - s, y - s, z), (x + s, y - s, z), (x, y + s, z))
    if rng.random() < 0.2:
        A, B = B, A
    return placed(rng, A, B, 'n=%d %s' % (n, mode), 0.8)


# --------------------------------------------------------------------------
# registry, validation, output
# --------------------------------------------------------------------------

BUILDERS = [
    ('coplanar_retri', k_coplanar_retri),
    ('coplanar_partial', k_coplanar_partial),
    ('coplanar_rotated', k_coplanar_rotated),
    ('coplanar_tjunction', k_coplanar_tjunction),
    ('near_coplanar_tilt', k_near_coplanar_tilt),
    ('near_coplanar_offset', k_near_coplanar_offset),
    ('near_coplanar_warp', k_near_coplanar_warp),
    ('sliver_plane', k_sliver_plane),
    ('sliver_above', k_sliver_above),
    ('sliver_cross', k_sliver_cross),
    ('sliver_fan', k_sliver_fan),
    ('sliver_tip_touch', k_sliver_tip_touch),
    ('wall_floor', k_wall_floor),
    ('hinge', k_hinge),
    ('fin_plate', k_fin_plate),
    ('box_coincident', k_box_coincident),
    ('zero_area_mix', k_zero_area_mix),
    ('dup_flip_unwelded', k_dup_flip_unwelded),
    ('jitter_far', k_jitter_far),
    ('retri_far', k_retri_far),
    ('offset_far', k_offset_far),
    ('scale_extreme', k_scale_extreme),
    ('solid_simplify', k_solid_simplify),
    ('solid_refine', k_solid_refine),
    ('solid_perturb', k_solid_perturb),
    ('heightfield_pair', k_heightfield_pair),
    ('equi_cone_axis', k_equi_cone_axis),
    ('equi_sym_solid', k_equi_sym_solid),
    ('equi_grid_centers', k_equi_grid_centers),
]
KINDS = [k for k, _ in BUILDERS]
BUILDER = dict(BUILDERS)

for _k in KINDS:
    assert _k and all(ch in 'abcdefghijklmnopqrstuvwxyz0123456789_' for ch in _k), _k
    assert 'fan_thin' not in _k, _k
assert len(set(KINDS)) == len(KINDS)


def finalize(m, rng):
    """Cap the face count (deterministically), drop unused vertices, canonicalise -0.0."""
    f = list(m.f)
    if len(f) > MAX_FACES:
        keep = sorted(rng.sample(range(len(f)), MAX_FACES))
        f = [f[i] for i in keep]
    m = compact(Mesh(m.v, f))
    m.v = [(float(p[0]) + 0.0, float(p[1]) + 0.0, float(p[2]) + 0.0) for p in m.v]
    return m


def validate(m):
    nv, nf = len(m.v), len(m.f)
    if not (1 <= nf <= MAX_FACES):
        raise ValueError('bad face count %d' % nf)
    for p in m.v:
        if len(p) != 3 or not all(isinstance(c, float) and math.isfinite(c) for c in p):
            raise ValueError('non-finite vertex %r' % (p,))
    used = [False] * nv
    for fc in m.f:
        if len(fc) != 3:
            raise ValueError('bad face %r' % (fc,))
        for i in fc:
            if not (isinstance(i, int) and 0 <= i < nv):
                raise ValueError('bad index %r' % (i,))
            used[i] = True
    if not all(used):
        raise ValueError('unused vertices')


def write_obj(path, m, comment):
    validate(m)
    lines = ['# ' + comment.replace('\n', ' ').replace('\r', ' ')]
    lines.extend('v %r %r %r' % p for p in m.v)
    lines.extend('f %d %d %d' % (a + 1, b + 1, c + 1) for a, b, c in m.f)
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')


def generate(seed):
    kind = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    A, B, note = BUILDER[kind](rng)
    A = finalize(A, rng)
    B = finalize(B, rng)
    return kind, A, B, note


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: %s OUTDIR FROM TO\n' % argv[0])
        return 2
    outdir = argv[1]
    lo, hi = int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    for s in range(lo, hi):
        kind, A, B, note = generate(s)
        base = os.path.join(outdir, '%06d_%s' % (s, kind))
        for tag, m in (('a', A), ('b', B)):
            write_obj('%s_%s.obj' % (base, tag), m,
                      'generate_pairs14 seed=%d kind=%s mesh=%s nv=%d nf=%d | %s'
                      % (s, kind, tag, len(m.v), len(m.f), note))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
