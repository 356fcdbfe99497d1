#!/usr/bin/env python3
"""gen17 -- seeded generator of random *degenerate triangle-mesh pairs*.

Written blind: no test, core, doc or other generator code of the Hausdorff
tool was read while writing this file; it is an independent stress source.
Standard library only (random, math, struct, os, sys, statistics).

Synopsis
    python3 generate_pairs17.py OUTDIR FROM TO

    For every integer seed s in [FROM, TO) writes
        OUTDIR/NNNNNN_KIND_a.obj and OUTDIR/NNNNNN_KIND_b.obj
    (NNNNNN = s zero-padded to 6 digits, KIND = KINDS[s % len(KINDS)]) and
    finally prints one summary line
        gen17: N pairs written to OUTDIR; triangles per mesh min/median/max = a/b/c
    All randomness comes from random.Random(s), so a pair depends only on s.
    (Exception by design: kind scale_sweep draws its configuration from
    random.Random(s0), s0 = the first seed of its group of five, so that five
    consecutive scale_sweep seeds hold the same configuration at scales
    1e-6, 1e-3, 1, 1e3, 1e6; s0 is itself a function of s.)

Format (Wavefront OBJ subset)
    line 1 : '# gen17 seed=S kind=K mesh=a|b key=value ...' (parameters)
    then   : 'v x y z' lines, each coordinate written with repr(float), so it
             reads back bit-exactly ('-0.0' may occur)
    then   : 'f i j k' lines, 1-based vertex indices.
    Every mesh has 1..200 triangles (mostly <= 60), finite coordinates, valid
    indices, no unused vertices and at most 30 triangles around any vertex,
    counted by index and by identical coordinates.  A draw that breaks a limit
    is redrawn from the same random stream (the header records attempt=N).
    Zero-area triangles (repeated index, repeated coordinates, collinear
    corners) occur on purpose in many kinds.

Placements (applied identically to both meshes of a pair, after the kind
built them in its local frame and before its export step, if any)
    identity : coordinates unchanged.
    dyadic   : axis permutation, sign flips, scale 2^k (|k|<=4) and a dyadic
               translation (multiple of 2^floor(log2 size) / 2^j); exact for
               dyadic inputs, so exact ties stay exact.
    rotate   : random rotation (uniform quaternion) plus a translation of up
               to one mesh size per axis (rounds coordinates).
    Kinds that depend on exact ties allow identity/dyadic only.

Kinds (KIND = KINDS[seed % 34])
    coplanar_retri     same planar region (rectangle / convex polygon) triangulated two ways
    coplanar_partial   two coplanar grids overlapping partially, shifted/in-plane rotated, or just touching
    coplanar_tjunction same region, edges split at interior points (T-junctions) or tiles of different resolution
    tilted_grid        grid vs. the same grid rotated by 1e-12..1e-3 rad about an in-plane axis
    offset_sheet       flat or curved sheet vs. copy offset by 1e-15..1e-4 of size (also dyadic offsets)
    offset_sheet_far   offset_sheet moved 1e3..1e7 sizes from the origin, optionally float32/decimal rounded
    sliver             sliver triangles (height 1e-12..1e-6 of edge) vs. collapsed/regrown slivers, or a sliver strip on a plate
    needle             needles (one edge 1e-12..1e-6 of the others): soup, fan, through a plate, vs. segments
    cap                real triangles with a cap (apex 1e-12..1e-6 off the long edge) coplanar, folded or out of plane
    fan_sliver         planar fan (partial or closed) with a sliver spoke at one side vs. resampled/lifted/coned fan
    fin_perp           plate vs. perpendicular (or nearly perpendicular) fin standing on it, touching or nudged
    hinge              two leaves sharing an edge, dihedral angle near 0 (folded) or near pi (flat)
    t_joint            plate + stem meeting in a T: non-conformal vs. conformal, tilted or gapped stem
    crossing           plate vs. plate/triangle crossing it, edge lying in it, vertex touching it
    zero_area_mixed    surface vs. same surface with repeated-index, repeated-coordinate, collinear, floating zero-area triangles
    degenerate_only    surface vs. a mesh made only of zero-area triangles (points, segments), or both degenerate
    dup_faces          mesh vs. copy with duplicated faces, flipped duplicates, duplicated vertices, shuffles
    csg_boxes          concatenated boxes with coincident faces vs. the same with one box nudged by 1e-9..1e-6
    csg_prism_cyl      box + cylinder + prism with coincident cap/side faces, nudged by 1e-9..1e-6
    lod_sphere         sphere patch (up to a closed UV sphere) fine vs. coarse, cracks, skirts or snapped vertices
    lod_saddle         saddle z=k(x^2-y^2) fine vs. coarse, cracks, skirts or snapped vertices
    lod_terrain        random terrain height field fine vs. coarse, cracks, skirts or snapped vertices
    lod_cylinder       open cylinder patch (seam unwelded) fine vs. coarse, cracks, skirts or snapped vertices
    terrain_far        lod_terrain 1e3..1e7 sizes from the origin, optionally float32/decimal rounded
    export_f32         mesh vs. its (possibly retessellated) copy rounded to float32
    export_decimal     mesh vs. its copy rounded to a decimal grid (fixed decimals or significant digits)
    export_f32_far     export_f32 moved 1e3..1e6 sizes from the origin before rounding
    export_decimal_far export_decimal moved 1e3..1e7 sizes from the origin before rounding
    mirror_rot         mesh vs. mirrored / 90-degree / tiny / random rotated / inverted copy
    ulp_jitter         mesh vs. copy with coordinates moved by a few ulps (all or some vertices)
    subset             one mesh a subset of the other's faces (single face, block, all but one, random)
    self_retri         polyhedral surface vs. itself retriangulated (box, prism, polyomino, octahedron)
    scale_sweep        one of several configurations at absolute scale 1e-6..1e6 (groups of five seeds)
    exact_ties         dyadic symmetric configurations with many exactly tied distances
"""

import math
import os
import random
import statistics
import struct
import sys

MAX_TRI = 200
MAX_VAL = 30
TWO_PI = 2.0 * math.pi

KINDS = [
    'coplanar_retri', 'coplanar_partial', 'coplanar_tjunction', 'tilted_grid',
    'offset_sheet', 'offset_sheet_far', 'sliver', 'needle', 'cap', 'fan_sliver',
    'fin_perp', 'hinge', 't_joint', 'crossing', 'zero_area_mixed',
    'degenerate_only', 'dup_faces', 'csg_boxes', 'csg_prism_cyl', 'lod_sphere',
    'lod_saddle', 'lod_terrain', 'lod_cylinder', 'terrain_far', 'export_f32',
    'export_decimal', 'export_f32_far', 'export_decimal_far', 'mirror_rot',
    'ulp_jitter', 'subset', 'self_retri', 'scale_sweep', 'exact_ties',
]

ALL = ('identity', 'dyadic', 'rotate')
EXACT = ('identity', 'dyadic')
DIAGS = ('same', 'flip', 'alt', 'alt2', 'random')


# --------------------------------------------------------------------------
# mesh container and small vector helpers
# --------------------------------------------------------------------------
class Mesh:
    def __init__(self, v=None, f=None):
        self.v = list(v) if v else []
        self.f = list(f) if f else []
        self.ids = None

    def add(self, p):
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.v) - 1

    def tri(self, a, b, c):
        self.f.append((a, b, c))

    def extend(self, o):
        off = len(self.v)
        self.v.extend(o.v)
        self.f.extend((a + off, b + off, c + off) for a, b, c in o.f)
        return self

    def copy(self):
        return Mesh(self.v, self.f)

    def mapped(self, fn):
        return Mesh([tuple(float(x) for x in fn(p)) for p in self.v], self.f)

    def flipped(self):
        return Mesh(self.v, [(a, c, b) for a, b, c in self.f])


def concat(*ms):
    r = Mesh()
    for m in ms:
        r.extend(m)
    return r


def weld(m):
    idx, nv, remap = {}, [], []
    for p in m.v:
        if p not in idx:
            idx[p] = len(nv)
            nv.append(p)
        remap.append(idx[p])
    return Mesh(nv, [(remap[a], remap[b], remap[c]) for a, b, c in m.f])


def compact(m):
    used = sorted({i for f in m.f for i in f})
    remap = {o: n for n, o in enumerate(used)}
    return Mesh([m.v[i] for i in used],
                [(remap[a], remap[b], remap[c]) for a, b, c in m.f])


def v_add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def v_sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def v_mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def v_dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def v_cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def v_norm(a):
    return math.sqrt(v_dot(a, a))


def v_unit(a):
    n = v_norm(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def lerp(a, b, t):
    return (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
            a[2] + t * (b[2] - a[2]))


def rand_unit(rng):
    while True:
        g = (rng.gauss(0, 1), rng.gauss(0, 1), rng.gauss(0, 1))
        n = v_norm(g)
        if n > 1e-3:
            return (g[0] / n, g[1] / n, g[2] / n)


def perp_unit(d, rng):
    du = v_unit(d)
    while True:
        r = rand_unit(rng)
        w = v_sub(r, v_mul(du, v_dot(r, du)))
        if v_norm(w) > 1e-2:
            return v_unit(w)


def rot_matrix(axis, ang):
    x, y, z = v_unit(axis)
    c, s = math.cos(ang), math.sin(ang)
    C = 1.0 - c
    return ((c + x * x * C, x * y * C - z * s, x * z * C + y * s),
            (y * x * C + z * s, c + y * y * C, y * z * C - x * s),
            (z * x * C - y * s, z * y * C + x * s, c + z * z * C))


def rand_rot(rng):
    q = [rng.gauss(0, 1) for _ in range(4)]
    n = math.sqrt(sum(t * t for t in q))
    w, x, y, z = (t / n for t in q)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def mat_apply(M, p):
    return (M[0][0] * p[0] + M[0][1] * p[1] + M[0][2] * p[2],
            M[1][0] * p[0] + M[1][1] * p[1] + M[1][2] * p[2],
            M[2][0] * p[0] + M[2][1] * p[1] + M[2][2] * p[2])


def rot_about(p, M, c):
    return v_add(c, mat_apply(M, v_sub(p, c)))


def lu(rng, a, b):
    """log-uniform in [10^a, 10^b]"""
    return 10.0 ** rng.uniform(a, b)


def sgn(rng):
    return rng.choice((1.0, -1.0))


def g6(x):
    return '%.6g' % x


def draw_L(rng):
    r = rng.random()
    if r < 0.5:
        return 1.0
    if r < 0.8:
        return 2.0 ** rng.randint(-3, 4)
    return float('%.4g' % lu(rng, -1, 1.5))


def res(rng, lo, hi, big=None):
    if big and rng.random() < 0.07:
        return rng.randint(hi + 1, big)
    return rng.randint(lo, hi)


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def ulp_move(x, k):
    d = math.inf if k > 0 else -math.inf
    for _ in range(abs(k)):
        x = math.nextafter(x, d)
    return x


def bbox(ms):
    lo = [math.inf] * 3
    hi = [-math.inf] * 3
    for m in ms:
        for p in m.v:
            for k in range(3):
                if p[k] < lo[k]:
                    lo[k] = p[k]
                if p[k] > hi[k]:
                    hi[k] = p[k]
    return lo, hi


def size_of(ms):
    lo, hi = bbox(ms)
    s = max(hi[k] - lo[k] for k in range(3))
    if not (s > 0 and math.isfinite(s)):
        s = max([abs(x) for x in lo + hi if math.isfinite(x)] + [1.0])
    return s


# --------------------------------------------------------------------------
# primitive builders
# --------------------------------------------------------------------------
def grid(nu, nv, fn, diag='same', rng=None):
    """(nu x nv)-cell grid of fn(u, v), u = i/nu, v = j/nv; m.ids[i][j]."""
    m = Mesh()
    ids = [[m.add(fn(i / nu, j / nv)) for j in range(nv + 1)]
           for i in range(nu + 1)]
    for i in range(nu):
        for j in range(nv):
            a, b, c, d = ids[i][j], ids[i + 1][j], ids[i + 1][j + 1], ids[i][j + 1]
            if diag == 'same':
                s = True
            elif diag == 'flip':
                s = False
            elif diag == 'alt':
                s = (i + j) % 2 == 0
            elif diag == 'alt2':
                s = (i + j) % 2 == 1
            else:
                s = rng.random() < 0.5
            if s:
                m.f += [(a, b, c), (a, c, d)]
            else:
                m.f += [(a, b, d), (b, c, d)]
    m.ids = ids
    return m


def grid_boundary(m):
    """boundary edges of a grid() mesh, as index pairs."""
    ids = m.ids
    nu, nv = len(ids) - 1, len(ids[0]) - 1
    e = []
    for i in range(nu):
        e.append((ids[i][0], ids[i + 1][0]))
        e.append((ids[i + 1][nv], ids[i][nv]))
    for j in range(nv):
        e.append((ids[nu][j], ids[nu][j + 1]))
        e.append((ids[0][j + 1], ids[0][j]))
    return e


def add_skirt(m, depth, sdir):
    m2 = m.copy()
    low = {}
    for a, b in grid_boundary(m):
        for i in (a, b):
            if i not in low:
                p = m.v[i]
                low[i] = m2.add(v_add(p, v_mul(sdir(p), depth)))
        m2.f += [(b, a, low[a]), (b, low[a], low[b])]
    return m2


def plane(x0, y0, lx, ly, z=0.0):
    return lambda u, v: (x0 + u * lx, y0 + v * ly, z)


def poly_fan(pts, k):
    n = len(pts)
    m = Mesh()
    for p in pts:
        m.add(p)
    o = [(k + i) % n for i in range(n)]
    for i in range(1, n - 1):
        m.tri(o[0], o[i], o[i + 1])
    return m


def poly_zigzag(pts, k):
    n = len(pts)
    m = Mesh()
    for p in pts:
        m.add(p)
    o = [(k + i) % n for i in range(n)]
    lo, hi, turn = 0, n - 1, 0
    while hi - lo >= 2:
        if turn == 0:
            m.tri(o[lo], o[lo + 1], o[hi])
            lo += 1
        else:
            m.tri(o[lo], o[hi - 1], o[hi])
            hi -= 1
        turn ^= 1
    return m


def box(lo, hi, k=1, diag='same', rng=None, do_weld=True):
    m = Mesh()
    for a in range(3):
        b, c = (a + 1) % 3, (a + 2) % 3
        for side in (0, 1):
            def fn(u, v, a=a, b=b, c=c, side=side):
                p = [0.0, 0.0, 0.0]
                p[a] = hi[a] if side else lo[a]
                p[b] = lo[b] + u * (hi[b] - lo[b])
                p[c] = lo[c] + v * (hi[c] - lo[c])
                return p
            g = grid(k, k, fn, diag, rng)
            m.extend(g if side else g.flipped())
    return weld(m) if do_weld else m


def cylinder(c, R, H, n, nz=1, caps=True, phi0=0.0):
    m = Mesh()
    rings = []
    for j in range(nz + 1):
        z = c[2] + H * (j / nz)
        rings.append([m.add((c[0] + R * math.cos(phi0 + TWO_PI * i / n),
                             c[1] + R * math.sin(phi0 + TWO_PI * i / n), z))
                      for i in range(n)])
    for j in range(nz):
        r0, r1 = rings[j], rings[j + 1]
        for i in range(n):
            i2 = (i + 1) % n
            m.f += [(r0[i], r0[i2], r1[i2]), (r0[i], r1[i2], r1[i])]
    if caps:
        cb = m.add((c[0], c[1], c[2]))
        ct = m.add((c[0], c[1], c[2] + H))
        for i in range(n):
            i2 = (i + 1) % n
            m.tri(cb, rings[0][i2], rings[0][i])
            m.tri(ct, rings[nz][i], rings[nz][i2])
    return m


def prism(base_pts, h, side_diag=0):
    """extruded convex polygon (z from base z to base z + h), caps fanned."""
    n = len(base_pts)
    m = Mesh()
    bot = [m.add(p) for p in base_pts]
    top = [m.add((p[0], p[1], p[2] + h)) for p in base_pts]
    for i in range(n):
        i2 = (i + 1) % n
        if (side_diag + i) % 2 == 0:
            m.f += [(bot[i], bot[i2], top[i2]), (bot[i], top[i2], top[i])]
        else:
            m.f += [(bot[i], bot[i2], top[i]), (bot[i2], top[i2], top[i])]
    for i in range(1, n - 1):
        m.tri(bot[0], bot[i + 1], bot[i])
        m.tri(top[0], top[i], top[i + 1])
    return m


def split_edges(m, rng, k, tmode='mid'):
    """split k random faces at a point of one edge (creates T-junctions)."""
    m2 = Mesh(m.v, [])
    chosen = set(rng.sample(range(len(m.f)), min(k, len(m.f))))
    for fi, f in enumerate(m.f):
        if fi in chosen:
            e = rng.randrange(3)
            a, b, c = f[e], f[(e + 1) % 3], f[(e + 2) % 3]
            t = 0.5 if tmode == 'mid' else rng.choice([0.5, 0.25, 1 / 3, rng.uniform(0.05, 0.95)])
            p = m2.add(lerp(m.v[a], m.v[b], t))
            m2.f += [(a, p, c), (p, b, c)]
        else:
            m2.f.append(f)
    return m2


# --------------------------------------------------------------------------
# surfaces (fn(u,v) on [0,1]^2, plus a skirt direction)
# --------------------------------------------------------------------------
DOWN = lambda p: (0.0, 0.0, -1.0)


def surf_sphere(rng, L, P, closed_ok=True):
    if closed_ok and rng.random() < 0.25:
        th0, th1, ph0, ph1 = 0.0, math.pi, 0.0, TWO_PI
    else:
        th0 = rng.choice([0.0, rng.uniform(0.0, 1.0)])
        th1 = th0 + rng.uniform(0.3, math.pi - th0)
        ph0 = rng.uniform(0, TWO_PI)
        ph1 = ph0 + rng.choice([rng.uniform(0.3, TWO_PI), TWO_PI])
    P += ['R=%r' % L, 'theta=%s..%s' % (g6(th0), g6(th1)), 'phi=%s..%s' % (g6(ph0), g6(ph1))]

    def fn(u, v):
        th = th0 + u * (th1 - th0)
        ph = ph0 + v * (ph1 - ph0)
        return (L * math.sin(th) * math.cos(ph), L * math.sin(th) * math.sin(ph),
                L * math.cos(th))

    def sd(p):
        n = v_norm(p)
        return v_mul(p, -1.0 / n) if n > 0 else (0.0, 0.0, -1.0)
    return fn, sd


def surf_saddle(rng, L, P):
    k = rng.choice([rng.uniform(0.05, 1.0), lu(rng, -6, -1)])
    P += ['saddle_k=%s' % g6(k)]
    return (lambda u, v: ((u - 0.5) * L, (v - 0.5) * L,
                          k * L * ((u - 0.5) ** 2 - (v - 0.5) ** 2))), DOWN


def surf_terrain(rng, L, P):
    bumps = [(rng.uniform(-0.2, 0.2), rng.uniform(0, 1), rng.uniform(0, 1),
              rng.uniform(0.1, 0.5)) for _ in range(rng.randint(1, 4))]
    waves = [(rng.uniform(0, 0.05), rng.uniform(0.5, 3), rng.uniform(0.5, 3),
              rng.uniform(0, TWO_PI)) for _ in range(rng.randint(0, 2))]
    P += ['bumps=%d' % len(bumps), 'waves=%d' % len(waves)]

    def fn(u, v):
        h = 0.0
        for a, cx, cy, w in bumps:
            h += a * math.exp(-((u - cx) ** 2 + (v - cy) ** 2) / (w * w))
        for a, fx, fy, ph in waves:
            h += a * math.sin(TWO_PI * (fx * u + fy * v) + ph)
        return (u * L, v * L, h * L)
    return fn, DOWN


def surf_cylinder(rng, L, P):
    R = L * rng.choice([1.0, 0.5, rng.uniform(0.2, 1)])
    H = L * rng.choice([1.0, 0.5, 2.0])
    ph0 = rng.choice([0.0, rng.uniform(0, TWO_PI)])
    arc = rng.choice([TWO_PI, TWO_PI, math.pi, rng.uniform(0.5, TWO_PI)])
    P += ['R=%s' % g6(R), 'H=%s' % g6(H), 'arc=%s' % g6(arc)]

    def fn(u, v):
        a = ph0 + u * arc
        return (R * math.cos(a), R * math.sin(a), v * H)

    def sd(p):
        n = math.hypot(p[0], p[1])
        return (-p[0] / n, -p[1] / n, 0.0) if n > 0 else (0.0, 0.0, -1.0)
    return fn, sd


def surf_wave(rng, L, P):
    a = rng.choice([rng.uniform(0.01, 0.3), lu(rng, -9, -2)])
    fx, fy, ph = rng.uniform(0.3, 1.5), rng.uniform(0.3, 1.5), rng.uniform(0, TWO_PI)
    P += ['amp=%s' % g6(a)]
    return (lambda u, v: (u * L, v * L,
                          a * L * math.sin(TWO_PI * fx * u + ph) * math.cos(TWO_PI * fy * v))), DOWN


def surf_flat(rng, L, P):
    ly = L * rng.choice([1.0, 0.5, 2.0])
    return plane(0.0, 0.0, L, ly), DOWN


SURFS = {'sphere': surf_sphere, 'saddle': surf_saddle, 'terrain': surf_terrain,
         'cylinder': surf_cylinder, 'wave': surf_wave, 'flat': surf_flat}


def random_surface(rng, L, P, names=None):
    name = rng.choice(names or sorted(SURFS))
    P.append('surf=' + name)
    fn, sd = SURFS[name](rng, L, P)
    return name, fn, sd


def random_shape(rng, L, P):
    """an assorted small mesh (<= ~60 triangles)"""
    t = rng.choice(['surface', 'surface', 'surface', 'box', 'cyl', 'soup', 'octa'])
    P.append('shape=' + t)
    if t == 'surface':
        _, fn, _ = random_surface(rng, L, P)
        return grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), fn, rng.choice(DIAGS), rng)
    if t == 'box':
        hi = (L, L * rng.choice([1.0, 0.5, 0.75]), L * rng.choice([1.0, 0.25, 2.0]))
        return box((0.0, 0.0, 0.0), hi, rng.choice([1, 1, 2]), rng.choice(DIAGS), rng)
    if t == 'cyl':
        return cylinder((0.0, 0.0, 0.0), L * 0.5, L, rng.randint(3, 12),
                        rng.choice([1, 1, 2]), caps=rng.random() < 0.7)
    if t == 'octa':
        return octa(L, rng.random() < 0.5)
    m = Mesh()
    for _ in range(rng.randint(1, 20)):
        p = [m.add((rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, L)))
             for _ in range(3)]
        m.tri(*p)
    return m


def octa(L, subdiv):
    P6 = [(L, 0.0, 0.0), (-L, 0.0, 0.0), (0.0, L, 0.0), (0.0, -L, 0.0),
          (0.0, 0.0, L), (0.0, 0.0, -L)]
    F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4),
         (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    m = Mesh()
    for a, b, c in F:
        pa, pb, pc = P6[a], P6[b], P6[c]
        if subdiv:
            ab, bc, ca = lerp(pa, pb, 0.5), lerp(pb, pc, 0.5), lerp(pc, pa, 0.5)
            ids = [m.add(q) for q in (pa, pb, pc, ab, bc, ca)]
            m.f += [(ids[0], ids[3], ids[5]), (ids[3], ids[1], ids[4]),
                    (ids[5], ids[4], ids[2]), (ids[3], ids[4], ids[5])]
        else:
            ids = [m.add(q) for q in (pa, pb, pc)]
            m.tri(*ids)
    return weld(m)


# --------------------------------------------------------------------------
# export / far post-processing (applied after placement)
# --------------------------------------------------------------------------
def dec_rounder(rng, size, mag, P, far=False):
    mode = rng.choice(['fixed', 'sig'])
    if mode == 'fixed':
        e = int(math.floor(math.log10(size))) - rng.randint(1, 6)
        if e < 0:
            fmt = '%%.%df' % (-e)
            fn = lambda x: float(fmt % x)
        else:
            q = 10.0 ** e
            fn = lambda x: float(round(x / q) * q)
        P.append('round=dec_fixed(1e%d)' % e)
    else:
        need = math.log10(max(mag, size) / size) if far else 0.0
        dg = min(17, int(need) + rng.randint(2, 6)) if far else rng.randint(3, 9)
        fmt = '%%.%dg' % dg
        fn = lambda x: float(fmt % x)
        P.append('round=dec_sig(%d)' % dg)
    return fn


def round_mesh(m, fn):
    return m.mapped(lambda p: (fn(p[0]), fn(p[1]), fn(p[2])))


def make_far_post(rounding, dlo, dhi, which='both'):
    """translate both meshes far away, then round ('none','f32','dec',
    or 'any' to draw one); which = 'both' or 'b' chooses what is rounded."""
    def post(rng, A, B, P):
        size = size_of([A, B])
        r = rounding if rounding != 'any' else rng.choice(['none', 'none', 'f32', 'dec'])
        # float32 has 24 bits: beyond ~1e6 sizes everything would collapse
        D = size * lu(rng, dlo, min(dhi, 6) if r == 'f32' else dhi)
        mode = rng.choice(['axis', 'diag', 'random', 'integer'])
        if mode == 'axis':
            T = [0.0, 0.0, 0.0]
            T[rng.randrange(3)] = sgn(rng) * D
        elif mode == 'diag':
            T = [sgn(rng) * D, sgn(rng) * D, sgn(rng) * D]
        else:
            u = rand_unit(rng)
            T = [u[0] * D, u[1] * D, u[2] * D]
            if mode == 'integer':
                T = [float(round(t)) for t in T]
        P.append('far=%s(%s)' % (mode, g6(D / size)))
        tr = lambda p: (p[0] + T[0], p[1] + T[1], p[2] + T[2])
        A, B = A.mapped(tr), B.mapped(tr)
        w = which if which != 'any' else rng.choice(['both', 'b'])
        if r == 'none':
            P.append('round=none')
            return A, B
        if r == 'f32':
            fn = f32
            P.append('round=f32')
        else:
            fn = dec_rounder(rng, size, D, P, far=True)
        P.append('rounded=' + w)
        B = round_mesh(B, fn)
        if w == 'both':
            A = round_mesh(A, fn)
        return A, B
    return post


def out(a, b, P, post=None, place=ALL):
    return {'a': a, 'b': b, 'p': P, 'post': post, 'place': place}


# --------------------------------------------------------------------------
# kinds
# --------------------------------------------------------------------------
def k_coplanar_retri(rng, seed):
    L = draw_L(rng)
    var = rng.choice(['diag', 'refine', 'res', 'polygon', 'polygon_mid'])
    P = ['var=' + var, 'L=%r' % L]
    if var.startswith('polygon'):
        n = rng.randint(4, 14)
        if rng.random() < 0.4:
            angs = [TWO_PI * i / n for i in range(n)]
        else:
            angs = sorted(rng.uniform(0, TWO_PI) for _ in range(n))
        pts = [(L * math.cos(t), L * math.sin(t), 0.0) for t in angs]
        if var == 'polygon_mid':
            new = []
            for i, p in enumerate(pts):
                new.append(p)
                if rng.random() < 0.4:
                    new.append(lerp(p, pts[(i + 1) % n], rng.choice([0.5, rng.random()])))
            pts = new
        n = len(pts)
        A = poly_fan(pts, rng.randrange(n))
        bv = rng.choice(['fan', 'zigzag'])
        B = poly_fan(pts, rng.randrange(n)) if bv == 'fan' else poly_zigzag(pts, rng.randrange(n))
        P += ['n=%d' % n, 'b=' + bv]
        return out(A, B, P)
    ly = L * rng.choice([1.0, 1.0, 0.5, 2.0, 0.75])
    fn = plane(0.0, 0.0, L, ly)
    nu, nv = res(rng, 1, 5, 9), res(rng, 1, 5, 9)
    dA = rng.choice(DIAGS)
    A = grid(nu, nv, fn, dA, rng)
    if var == 'diag':
        dB = rng.choice([d for d in DIAGS if d != dA])
        nuB, nvB = nu, nv
    elif var == 'refine':
        f = rng.choice([2, 2, 3])
        nuB = nu * f if nu * f <= 10 else nu
        nvB = nv * f if nv * f <= 10 and rng.random() < 0.5 else nv
        dB = rng.choice(DIAGS)
    else:
        nuB, nvB, dB = res(rng, 1, 6), res(rng, 1, 6), rng.choice(DIAGS)
    B = grid(nuB, nvB, fn, dB, rng)
    P += ['ly=%r' % ly, 'a=%dx%d/%s' % (nu, nv, dA), 'b=%dx%d/%s' % (nuB, nvB, dB)]
    return out(A, B, P)


def k_coplanar_partial(rng, seed):
    L = draw_L(rng)
    nu, nv = res(rng, 1, 5, 8), res(rng, 1, 5, 8)
    A = grid(nu, nv, plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)

    def off():
        return L * rng.choice([0.0, 0.5, 0.25, 1 / 3, rng.random(), 1.0, -0.5,
                               1.0 + lu(rng, -12, -4), 1.0 - lu(rng, -12, -4)])
    dx = off()
    dy = off() if rng.random() < 0.5 else 0.0
    sx = L * rng.choice([1.0, 0.5, 1.5, 0.3])
    sy = L * rng.choice([1.0, 0.5, 1.5, 0.3])
    B = grid(res(rng, 1, 5), res(rng, 1, 5), plane(dx, dy, sx, sy), rng.choice(DIAGS), rng)
    P = ['L=%r' % L, 'dx=%r' % dx, 'dy=%r' % dy, 'sx=%r' % sx, 'sy=%r' % sy]
    if rng.random() < 0.3:
        th = rng.choice([rng.uniform(0, TWO_PI), sgn(rng) * lu(rng, -12, -3),
                         math.pi / 4, math.pi / 2])
        cx, cy = dx + sx / 2, dy + sy / 2
        ct, st = math.cos(th), math.sin(th)
        B = B.mapped(lambda p: (cx + ct * (p[0] - cx) - st * (p[1] - cy),
                                cy + st * (p[0] - cx) + ct * (p[1] - cy), p[2]))
        P.append('inplane_rot=%s' % g6(th))
    if rng.random() < 0.5:
        A, B = B, A
        P.append('swapped=1')
    return out(A, B, P)


def k_coplanar_tjunction(rng, seed):
    L = draw_L(rng)
    var = rng.choice(['split', 'both_split', 'tiles', 'tiles'])
    fn = plane(0.0, 0.0, L, L)
    nu, nv = res(rng, 1, 4, 7), res(rng, 1, 4, 7)
    base = grid(nu, nv, fn, rng.choice(DIAGS), rng)
    P = ['var=' + var, 'L=%r' % L, 'grid=%dx%d' % (nu, nv)]
    tm = rng.choice(['mid', 'any'])
    if var == 'split':
        A = base
        B = split_edges(base, rng, rng.randint(1, len(base.f)), tm)
    elif var == 'both_split':
        A = split_edges(base, rng, rng.randint(1, len(base.f)), tm)
        B = split_edges(base, rng, rng.randint(1, len(base.f)), tm)
    else:
        s = rng.choice([0.5, 0.25, 1 / 3, rng.uniform(0.2, 0.8)])
        t1 = grid(res(rng, 1, 3), res(rng, 1, 5), plane(0.0, 0.0, s * L, L), rng.choice(DIAGS), rng)
        t2 = grid(res(rng, 1, 3), res(rng, 1, 5), plane(s * L, 0.0, L - s * L, L), rng.choice(DIAGS), rng)
        A = base
        B = concat(t1, t2)
        if rng.random() < 0.5:
            B = weld(B)
        P.append('s=%r' % s)
    P.append('t=' + tm)
    return out(A, B, P)


def k_tilted_grid(rng, seed):
    L = draw_L(rng)
    fn = plane(0.0, 0.0, L, L)
    A = grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), fn, rng.choice(DIAGS), rng)
    ang = sgn(rng) * lu(rng, -12, -3)
    ax = rng.choice(['edge', 'center', 'diag', 'random'])
    if ax == 'edge':
        c, d = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)
    elif ax == 'center':
        c, d = (L / 2, L / 2, 0.0), (1.0, 0.0, 0.0)
    elif ax == 'diag':
        c, d = (0.0, 0.0, 0.0), (1.0, 1.0, 0.0)
    else:
        t = rng.uniform(0, TWO_PI)
        c, d = (rng.uniform(0, L), rng.uniform(0, L), 0.0), (math.cos(t), math.sin(t), 0.0)
    M = rot_matrix(d, ang)
    B = grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), fn, rng.choice(DIAGS), rng)
    B = B.mapped(lambda p: rot_about(p, M, c))
    return out(A, B, ['L=%r' % L, 'tilt=%s' % g6(ang), 'axis=' + ax])


def offset_base(rng):
    L = draw_L(rng)
    if rng.random() < 0.7:
        d = L * lu(rng, -15, -4) * sgn(rng)
    else:
        d = L * 2.0 ** -rng.randint(12, 50) * sgn(rng)
    var = rng.choice(['flat', 'flat', 'curved', 'partial', 'oblique'])
    P = ['var=' + var, 'L=%r' % L, 'offset=%r' % d]
    nA = (res(rng, 1, 5, 8), res(rng, 1, 5, 8))
    nB = nA if rng.random() < 0.5 else (res(rng, 1, 5), res(rng, 1, 5))
    dA, dB = rng.choice(DIAGS), rng.choice(DIAGS)
    if var in ('flat', 'partial'):
        A = grid(nA[0], nA[1], plane(0.0, 0.0, L, L), dA, rng)
        x0 = 0.0 if var == 'flat' else L * rng.choice([0.5, 0.25, rng.random()])
        B = grid(nB[0], nB[1], plane(x0, 0.0, L, L, d), dB, rng)
    elif var == 'curved':
        k = rng.uniform(0.05, 0.5)
        h = lambda u, v: k * L * ((u - 0.5) ** 2 + (v - 0.5) ** 2)
        A = grid(nA[0], nA[1], lambda u, v: (u * L, v * L, h(u, v)), dA, rng)
        B = grid(nB[0], nB[1], lambda u, v: (u * L, v * L, h(u, v) + d), dB, rng)
    else:
        n = rand_unit(rng)
        A = grid(nA[0], nA[1], plane(0.0, 0.0, L, L), dA, rng)
        B = A.mapped(lambda p: v_add(p, v_mul(n, d)))
    return A, B, P


def k_offset_sheet(rng, seed):
    A, B, P = offset_base(rng)
    return out(A, B, P)


def k_offset_sheet_far(rng, seed):
    A, B, P = offset_base(rng)
    return out(A, B, P, post=make_far_post('any', 3, 7, 'both'))


def sliver_tri(rng, L, planar):
    if planar:
        p = (rng.uniform(0, L), rng.uniform(0, L), 0.0)
        t = rng.uniform(0, TWO_PI)
        d = (math.cos(t) * L * rng.uniform(0.3, 1), math.sin(t) * L * rng.uniform(0.3, 1), 0.0)
        n = v_unit((-d[1], d[0], 0.0))
    else:
        p = (rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, L))
        d = v_mul(rand_unit(rng), L * rng.uniform(0.3, 1))
        n = perp_unit(d, rng)
    q = v_add(p, d)
    s = rng.choice([rng.uniform(0, 1), rng.uniform(-0.5, 1.5), 0.5])
    h = lu(rng, -12, -6)
    return p, q, s, n, h, v_norm(d)


def k_sliver(rng, seed):
    L = draw_L(rng)
    var = rng.choice(['soup', 'soup', 'strip'])
    P = ['var=' + var, 'L=%r' % L]
    if var == 'strip':
        nu, nv = res(rng, 1, 5), res(rng, 1, 4)
        h = lu(rng, -12, -6)
        plate = grid(nu, nv, plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
        orient = rng.choice(['inplane', 'vertical'])
        if orient == 'inplane':
            sf = lambda u, v: (u * L, -h * L * (1 - v), 0.0)
        else:
            sf = lambda u, v: (u * L, 0.0, -h * L * (1 - v))
        strip = grid(res(rng, 1, 8), 1, sf, rng.choice(DIAGS), rng)
        A = weld(concat(plate, strip))
        bv = rng.choice(['plate', 'other_h'])
        if bv == 'plate':
            B = plate
        else:
            h2 = lu(rng, -12, -6)
            sf2 = lambda u, v: (u * L, -h2 * L * (1 - v), 0.0)
            B = weld(concat(plate, grid(res(rng, 1, 8), 1, sf2, rng.choice(DIAGS), rng)))
            P.append('h2=%s' % g6(h2))
        P += ['h=%s' % g6(h), 'orient=' + orient, 'b=' + bv]
        return out(A, B, P)
    k = rng.randint(1, 12)
    planar = rng.random() < 0.5
    A, B = Mesh(), Mesh()
    bv = rng.choice(['collapsed', 'regrown', 'segment', 'other_side', 'plate'])
    for _ in range(k):
        p, q, s, n, h, dl = sliver_tri(rng, L, planar)
        foot = lerp(p, q, s)
        r = v_add(foot, v_mul(n, h * dl))
        A.f.append((A.add(p), A.add(q), A.add(r)))
        if bv == 'collapsed':
            B.f.append((B.add(p), B.add(q), B.add(foot)))
        elif bv == 'regrown':
            r2 = v_add(lerp(p, q, rng.uniform(-0.5, 1.5)), v_mul(n, lu(rng, -12, -6) * dl))
            B.f.append((B.add(p), B.add(q), B.add(r2)))
        elif bv == 'segment':
            i, j = B.add(p), B.add(q)
            B.f.append((i, j, j))
        elif bv == 'other_side':
            B.f.append((B.add(p), B.add(q), B.add(v_sub(foot, v_mul(n, h * dl)))))
    if bv == 'plate':
        B = grid(res(rng, 1, 4), res(rng, 1, 4), plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
    P += ['k=%d' % k, 'planar=%d' % planar, 'b=' + bv]
    return out(A, B, P)


def k_needle(rng, seed):
    L = draw_L(rng)
    var = rng.choice(['soup', 'fan', 'plate'])
    k = rng.randint(1, 15)
    bv = rng.choice(['segments', 'width', 'plate', 'shortened'])
    P = ['var=' + var, 'L=%r' % L, 'k=%d' % k, 'b=' + bv]
    A, B = Mesh(), Mesh()
    apex = (rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, L) if var != 'plate' else 0.0)
    for _ in range(k):
        p = apex if var == 'fan' else (rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, L))
        if var == 'plate':
            d = v_mul(rand_unit(rng), L * rng.uniform(0.3, 1))
            p = v_sub((rng.uniform(0, L), rng.uniform(0, L), 0.0), v_mul(d, rng.choice([0.5, rng.random()])))
        else:
            d = v_mul(rand_unit(rng), L * rng.uniform(0.3, 1))
        q = v_add(p, d)
        w = lu(rng, -12, -6) * L
        e = v_mul(perp_unit(d, rng) if rng.random() < 0.7 else rand_unit(rng), w)
        r = v_add(q, e)
        ia = A.add(p)
        A.f.append((ia, A.add(q), A.add(r)))
        if bv == 'segments':
            i, j = B.add(p), B.add(q)
            B.f.append((i, j, i))
        elif bv == 'width':
            B.f.append((B.add(p), B.add(q), B.add(v_add(q, v_mul(perp_unit(d, rng), lu(rng, -12, -6) * L)))))
        elif bv == 'shortened':
            q2 = lerp(p, q, rng.uniform(0.5, 1.0))
            B.f.append((B.add(p), B.add(q2), B.add(v_add(q2, e))))
    if var == 'fan':
        A = weld(A)
        B = weld(B) if B.f else B
    if bv == 'plate':
        B = grid(res(rng, 1, 4), res(rng, 1, 4), plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
    return out(A, B, P)


def k_cap(rng, seed):
    L = draw_L(rng)
    k = rng.randint(1, 8)
    bv = rng.choice(['t_only', 'recap', 'segment', 'split'])
    side = rng.choice(['out', 'folded', 'normal', 'mixed'])
    P = ['L=%r' % L, 'k=%d' % k, 'b=' + bv, 'side=' + side]
    A, B = Mesh(), Mesh()
    for _ in range(k):
        a = (rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, L))
        d = v_mul(rand_unit(rng), L * rng.uniform(0.3, 1))
        b = v_add(a, d)
        n1 = perp_unit(d, rng)
        n2 = v_unit(v_cross(d, n1))
        c = v_add(lerp(a, b, rng.uniform(0.2, 0.8)), v_mul(n1, v_norm(d) * rng.uniform(0.3, 1)))
        s = rng.uniform(0.05, 0.95)
        h = lu(rng, -12, -6) * v_norm(d)
        sd = side if side != 'mixed' else rng.choice(['out', 'folded', 'normal'])
        dirc = {'out': v_mul(n1, -1.0), 'folded': n1, 'normal': n2}[sd]
        foot = lerp(a, b, s)
        r = v_add(foot, v_mul(dirc, h))
        ia, ib, ic, ir = A.add(a), A.add(b), A.add(c), A.add(r)
        A.f += [(ia, ib, ic), (ib, ia, ir)]
        ja, jb, jc = B.add(a), B.add(b), B.add(c)
        if bv == 't_only':
            B.f.append((ja, jb, jc))
        elif bv == 'recap':
            r2 = v_add(lerp(a, b, rng.uniform(0.05, 0.95)), v_mul(dirc, lu(rng, -12, -6) * v_norm(d) * sgn(rng)))
            B.f += [(ja, jb, jc), (jb, ja, B.add(r2))]
        elif bv == 'segment':
            B.f += [(ja, jb, jc), (jb, ja, ja)]
        else:
            jf = B.add(foot)
            B.f += [(ja, jf, jc), (jf, jb, jc)]
    return out(weld(A), weld(B), P)


def k_fan_sliver(rng, seed):
    L = draw_L(rng)
    n = rng.randint(3, 20)
    Th = rng.choice([math.pi / 2, math.pi, 1.5 * math.pi, TWO_PI, rng.uniform(0.5, TWO_PI)])
    closed = Th == TWO_PI
    delta = lu(rng, -12, -6)
    radii = rng.random() < 0.5
    rad = lambda: L * (rng.uniform(0.5, 1.0) if radii else 1.0)
    c = (0.0, 0.0, 0.0)
    spokes = [(TWO_PI * i / n if closed else Th * i / n) for i in range(n if closed else n + 1)]
    pts = [(r * math.cos(t), r * math.sin(t), 0.0) for t, r in ((t, rad()) for t in spokes)]
    where = rng.choice(['end', 'start'])
    if closed or where == 'start':
        t = -delta
        ins = 1  # insert before first spoke in cyclic order
    else:
        t = spokes[-1] + delta
        ins = None
    rs = rng.choice([L, rad(), L * (1 + lu(rng, -9, -3))])
    sp = (rs * math.cos(t), rs * math.sin(t), 0.0)

    def fan(points, closed_, lift=None, apex_h=0.0):
        m = Mesh()
        ic = m.add((0.0, 0.0, apex_h))
        ids = [m.add(p) for p in points]
        if lift is not None:
            j, dz = lift
            x, y, z = m.v[ids[j]]
            m.v[ids[j]] = (x, y, z + dz)
        cnt = len(ids) if closed_ else len(ids) - 1
        for i in range(cnt):
            m.tri(ic, ids[i], ids[(i + 1) % len(ids)])
        return m
    if ins is None:
        with_s = pts + [sp]
        sidx = len(pts)
    else:
        with_s = [sp] + pts
        sidx = 0
    A = fan(with_s, closed)
    bv = rng.choice(['no_sliver', 'resampled', 'lifted', 'cone'])
    if bv == 'no_sliver':
        B = fan(pts, closed)
    elif bv == 'resampled':
        n2 = rng.randint(3, 20)
        sp2 = [(TWO_PI * i / n2 if closed else Th * i / n2) for i in range(n2 if closed else n2 + 1)]
        B = fan([(L * math.cos(t), L * math.sin(t), 0.0) for t in sp2], closed)
    elif bv == 'lifted':
        B = fan(with_s, closed, lift=(sidx, delta * L * sgn(rng)))
    else:
        B = fan(with_s, closed, apex_h=L * lu(rng, -12, -3) * sgn(rng))
    P = ['L=%r' % L, 'n=%d' % n, 'angle=%s' % g6(Th), 'delta=%s' % g6(delta), 'b=' + bv]
    return out(A, B, P)


def k_fin_perp(rng, seed):
    L = draw_L(rng)
    nu, nv = res(rng, 1, 5, 8), res(rng, 1, 5, 8)
    plate = grid(nu, nv, plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
    cx = L * rng.choice([rng.randint(0, nu) / nu, 0.5, rng.uniform(0.1, 0.9)])
    y0 = L * rng.choice([0.0, -0.25, rng.uniform(0, 0.5)])
    y1 = L * rng.choice([1.0, 1.25, rng.uniform(0.5, 1)])
    H = L * rng.uniform(0.1, 1.0) * sgn(rng)

    def fin(zb, tau):
        tt = math.tan(tau)
        return grid(res(rng, 1, 4), res(rng, 1, 3),
                    lambda u, v: (cx + (v * H) * tt, y0 + u * (y1 - y0), zb + v * H),
                    rng.choice(DIAGS), rng)
    zb = rng.choice([0.0, 0.0, sgn(rng) * L * lu(rng, -12, -4)])
    tau = rng.choice([0.0, 0.0, sgn(rng) * lu(rng, -12, -3)])
    av = rng.choice(['plate', 'plate', 'plate_fin'])
    bv = rng.choice(['fin_only', 'plate_fin'])
    B = fin(zb, tau)
    if bv == 'plate_fin':
        B = concat(grid(res(rng, 1, 5), res(rng, 1, 5), plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng), B)
    A = plate
    if av == 'plate_fin':
        A = concat(plate, fin(0.0, sgn(rng) * lu(rng, -12, -3)))
    P = ['L=%r' % L, 'x=%r' % cx, 'zb=%r' % zb, 'tau=%s' % g6(tau), 'a=' + av, 'b=' + bv]
    return out(A, B, P)


def k_hinge(rng, seed):
    L = draw_L(rng)
    W = L * rng.choice([1.0, 0.5, rng.uniform(0.3, 1)])

    def leaves(phi, nu, nv, exact_flat=False, only1=False):
        d2 = (0.0, -1.0, 0.0) if exact_flat else (0.0, math.cos(phi), math.sin(phi))

        def fn(u, v):
            s = 2.0 * v - 1.0
            if s <= 0:
                return (u * L, -s * W, 0.0)
            return (u * L, s * W * d2[1], s * W * d2[2])
        if only1:
            return grid(nu, nv, lambda u, v: (u * L, v * W, 0.0), rng.choice(DIAGS), rng)
        return grid(nu, 2 * nv, fn, rng.choice(DIAGS), rng)
    eps = lu(rng, -12, -2)
    phiA = rng.choice([eps, math.pi - eps])
    nA = (res(rng, 1, 4), res(rng, 1, 3))
    A = leaves(phiA, *nA)
    bv = rng.choice(['flat', 'exact_flat', 'folded0', 'other_eps', 'leaf1', 'res'])
    nB = (res(rng, 1, 4), res(rng, 1, 3))
    if bv == 'flat':
        B = leaves(math.pi, *nB)
    elif bv == 'exact_flat':
        B = leaves(0.0, *nB, exact_flat=True)
    elif bv == 'folded0':
        B = leaves(0.0, *nB)
    elif bv == 'other_eps':
        e2 = lu(rng, -12, -2)
        B = leaves(rng.choice([e2, math.pi - e2]), *nB)
    elif bv == 'leaf1':
        B = leaves(0.0, *nB, only1=True)
    else:
        B = leaves(phiA, *nB)
    P = ['L=%r' % L, 'W=%r' % W, 'phi=%r' % phiA, 'b=' + bv]
    return out(A, B, P)


def k_t_joint(rng, seed):
    L = draw_L(rng)
    nu, nv = res(rng, 1, 5), res(rng, 1, 5)
    c = L * rng.choice([rng.randint(1, max(1, nv - 1)) / nv, 0.5, rng.uniform(0.1, 0.9)])
    H = L * rng.uniform(0.2, 1.0) * sgn(rng)
    plate = grid(nu, nv, plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
    x0 = L * rng.choice([0.0, 0.25, rng.uniform(0, 0.4)])
    x1 = L * rng.choice([1.0, 0.75, rng.uniform(0.6, 1)])

    def stem(ztop=0.0, tau=0.0, xa=x0, xb=x1, ns=None):
        tt = math.tan(tau)
        return grid(ns or res(rng, 1, 4), res(rng, 1, 3),
                    lambda u, v: (xa + u * (xb - xa), c + v * H * tt, ztop + v * H),
                    rng.choice(DIAGS), rng)
    A = concat(plate, stem())
    bv = rng.choice(['conformal', 'tilted', 'gap', 'plate_only'])
    if bv == 'conformal':
        h1 = grid(nu, res(rng, 1, 3), plane(0.0, 0.0, L, c), rng.choice(DIAGS), rng)
        h2 = grid(nu, res(rng, 1, 3), plane(0.0, c, L, L - c), rng.choice(DIAGS), rng)
        B = weld(concat(h1, h2, stem(xa=0.0, xb=L, ns=nu)))
    elif bv == 'tilted':
        B = concat(plate, stem(tau=sgn(rng) * lu(rng, -12, -3)))
    elif bv == 'gap':
        B = concat(plate, stem(ztop=sgn(rng) * L * lu(rng, -12, -4)))
    else:
        B = plate
    if rng.random() < 0.3:
        A, B = B, A
    P = ['L=%r' % L, 'c=%r' % c, 'H=%r' % H, 'b=' + bv]
    return out(A, B, P)


def k_crossing(rng, seed):
    L = draw_L(rng)
    A = grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
    var = rng.choice(['through', 'edge_in_plane', 'vertex_touch', 'edge_edge'])
    P = ['var=' + var, 'L=%r' % L]
    if var in ('through', 'edge_in_plane'):
        alpha = rng.choice([math.pi / 2, rng.uniform(0.1, 1.5), lu(rng, -6, -1)])
        c = L * rng.choice([0.5, rng.random(), 0.25])
        t = rng.uniform(0, math.pi)
        dl = (math.cos(t), math.sin(t), 0.0)
        up = v_add(v_mul(v_unit((-dl[1], dl[0], 0.0)), math.cos(alpha)), (0.0, 0.0, math.sin(alpha)))
        o = (c, L * rng.uniform(0.2, 0.8), 0.0)
        lo = -L * rng.uniform(0.1, 0.5) if var == 'through' else 0.0
        hi = L * rng.uniform(0.2, 0.8)
        B = grid(res(rng, 1, 4), res(rng, 1, 3),
                 lambda u, v: v_add(v_add(o, v_mul(dl, (u - 0.5) * L)), v_mul(up, lo + v * (hi - lo))),
                 rng.choice(DIAGS), rng)
        P.append('alpha=%s' % g6(alpha))
    elif var == 'vertex_touch':
        B = Mesh()
        for _ in range(rng.randint(1, 6)):
            i = rng.randrange(len(A.f))
            a, b, c = (A.v[j] for j in A.f[i])
            w = rng.choice([(1.0, 0.0, 0.0), (0.5, 0.5, 0.0), (0.25, 0.25, 0.5),
                            (rng.random(), rng.random(), 0.0)])
            s = sum(w)
            w = [x / s for x in w]
            tp = (w[0] * a[0] + w[1] * b[0] + w[2] * c[0], w[0] * a[1] + w[1] * b[1] + w[2] * c[1], 0.0)
            h = L * rng.uniform(0.1, 0.5) * sgn(rng)
            q1 = v_add(tp, (rng.uniform(-0.3, 0.3) * L, rng.uniform(-0.3, 0.3) * L, h))
            q2 = v_add(tp, (rng.uniform(-0.3, 0.3) * L, rng.uniform(-0.3, 0.3) * L, h * rng.uniform(0.5, 1.5)))
            B.tri(B.add(tp), B.add(q1), B.add(q2))
    else:
        B = Mesh()
        for _ in range(rng.randint(1, 6)):
            i = rng.randrange(len(A.f))
            a, b, _c = (A.v[j] for j in A.f[i])
            m = lerp(a, b, 0.5)
            dl = v_unit(v_sub(b, a))
            cr = (-dl[1], dl[0], 0.0)
            ell = L * rng.uniform(0.05, 0.3)
            p1, p2 = v_sub(m, v_mul(cr, ell)), v_add(m, v_mul(cr, ell))
            q = v_add(m, (0.0, 0.0, L * rng.uniform(0.1, 0.5) * sgn(rng)))
            B.tri(B.add(p1), B.add(p2), B.add(q))
    return out(A, B, P)


def add_degenerates(base, rng, k, L, types):
    m = base.copy()
    for _ in range(k):
        t = rng.choice(types)
        f = m.f[rng.randrange(len(base.f))]
        a, b, c = f
        if t == 'rep_idx':
            m.tri(a, a, b)
        elif t == 'rep_idx3':
            m.tri(a, a, a)
        elif t == 'dup_coord':
            a2 = m.add(m.v[a])
            m.tri(a, a2, b)
        elif t == 'collinear_mid':
            p = m.add(lerp(m.v[a], m.v[b], rng.choice([0.5, rng.random()])))
            m.tri(a, p, b)
        elif t == 'collinear_ext':
            p = m.add(lerp(m.v[a], m.v[b], rng.uniform(1.0, 1.6)))
            m.tri(a, b, p)
        elif t in ('off_point', 'off_segment'):
            pa, pb, pc = m.v[a], m.v[b], m.v[c]
            nrm = v_cross(v_sub(pb, pa), v_sub(pc, pa))
            nn = v_norm(nrm)
            nrm = v_mul(nrm, 1.0 / nn) if nn > 0 else (0.0, 0.0, 1.0)
            cen = ((pa[0] + pb[0] + pc[0]) / 3, (pa[1] + pb[1] + pc[1]) / 3, (pa[2] + pb[2] + pc[2]) / 3)
            q = v_add(cen, v_mul(nrm, L * lu(rng, -12, -3) * sgn(rng)))
            i = m.add(q)
            if t == 'off_point':
                m.tri(i, i, i)
            else:
                j = m.add(v_add(q, v_mul(v_sub(pb, pa), 0.5)))
                m.tri(i, j, j)
    return m


DEG_TYPES = ['rep_idx', 'rep_idx3', 'dup_coord', 'collinear_mid', 'collinear_ext',
             'off_point', 'off_segment']


def k_zero_area_mixed(rng, seed):
    L = draw_L(rng)
    P = ['L=%r' % L]
    _, fn, _ = random_surface(rng, L, P, ['flat', 'flat', 'wave', 'saddle', 'sphere'])
    base = grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), fn, rng.choice(DIAGS), rng)
    types = rng.sample(DEG_TYPES, rng.randint(1, len(DEG_TYPES)))
    k = rng.randint(1, 12)
    B = add_degenerates(base, rng, k, L, types)
    A = base
    if rng.random() < 0.3:
        A = add_degenerates(base, rng, rng.randint(1, 4), L, ['rep_idx', 'dup_coord', 'collinear_mid'])
    P += ['ndeg=%d' % k, 'types=' + ','.join(types)]
    return out(A, B, P)


def k_degenerate_only(rng, seed):
    L = draw_L(rng)
    P = ['L=%r' % L]
    _, fn, _ = random_surface(rng, L, P, ['flat', 'wave', 'sphere', 'saddle'])
    A = grid(res(rng, 1, 5), res(rng, 1, 5), fn, rng.choice(DIAGS), rng)

    def degen_mesh(src, k):
        m = Mesh()
        for _ in range(k):
            t = rng.choice(['vertex', 'edge', 'collinear', 'float_point', 'float_seg', 'centroid'])
            a, b, c = (src.v[j] for j in src.f[rng.randrange(len(src.f))])
            if t == 'vertex':
                i = m.add(a)
                m.tri(i, i, i)
            elif t == 'edge':
                i, j = m.add(a), m.add(b)
                m.tri(i, j, j)
            elif t == 'collinear':
                m.tri(m.add(a), m.add(lerp(a, b, rng.choice([0.5, rng.random()]))), m.add(b))
            elif t == 'centroid':
                cen = ((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3)
                i = m.add(cen)
                m.tri(i, i, i)
            else:
                q = v_add(lerp(a, c, rng.random()), v_mul(rand_unit(rng), L * lu(rng, -12, -1)))
                i = m.add(q)
                if t == 'float_point':
                    m.tri(i, i, i)
                else:
                    j = m.add(v_add(q, v_mul(v_sub(b, a), rng.uniform(-1, 1))))
                    m.tri(i, j, i)
        return m
    B = degen_mesh(A, rng.randint(1, 30))
    if rng.random() < 0.3:
        A = degen_mesh(A, rng.randint(1, 30))
        P.append('both=1')
    if rng.random() < 0.3:
        A, B = B, A
        P.append('swapped=1')
    return out(A, B, P)


def dup_ops(base, rng, P, tag):
    m = base.copy()
    ops = []
    nf = len(base.f)
    for _ in range(rng.randint(1, 4)):
        op = rng.choice(['dup', 'dup_flip', 'dup_newverts', 'flip', 'shuffle_f', 'shuffle_v'])
        ops.append(op)
        if op in ('dup', 'dup_flip', 'dup_newverts'):
            for fi in rng.sample(range(nf), rng.randint(1, max(1, min(nf, 12)))):
                a, b, c = m.f[fi]
                if op == 'dup':
                    m.f.append((a, b, c))
                elif op == 'dup_flip':
                    m.f.append((a, c, b))
                else:
                    m.f.append((m.add(m.v[a]), m.add(m.v[b]), m.add(m.v[c])))
        elif op == 'flip':
            for fi in rng.sample(range(len(m.f)), rng.randint(1, len(m.f))):
                a, b, c = m.f[fi]
                m.f[fi] = (a, c, b)
        elif op == 'shuffle_f':
            rng.shuffle(m.f)
        else:
            perm = list(range(len(m.v)))
            rng.shuffle(perm)
            nv = [None] * len(m.v)
            for o, n in enumerate(perm):
                nv[n] = m.v[o]
            m = Mesh(nv, [(perm[a], perm[b], perm[c]) for a, b, c in m.f])
    P.append('ops_%s=%s' % (tag, ','.join(ops)))
    return m


def k_dup_faces(rng, seed):
    L = draw_L(rng)
    P = ['L=%r' % L]
    base = random_shape(rng, L, P)
    A = base if rng.random() < 0.6 else dup_ops(base, rng, P, 'a')
    B = dup_ops(base, rng, P, 'b')
    if rng.random() < 0.2 and len(B.f) > 1:
        del B.f[rng.randrange(len(B.f))]
        P.append('dropped_one=1')
    return out(A, B, P)


def k_csg_boxes(rng, seed):
    L = draw_L(rng)
    k = rng.choice([1, 1, 1, 2])
    dg = rng.choice(DIAGS)
    b1 = ((0.0, 0.0, 0.0), (L, L, L))
    ax = rng.randrange(3)
    mode = rng.choice(['touch', 'touch_full', 'overlap', 'inside_flush'])
    lo2, hi2 = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
    for a in range(3):
        if a == ax:
            if mode in ('touch', 'touch_full'):
                lo2[a], hi2[a] = L, L * rng.choice([1.5, 2.0, 1.25])
            elif mode == 'overlap':
                lo2[a], hi2[a] = L * 0.5, L * 1.5
            else:
                lo2[a], hi2[a] = L * 0.25, L
        else:
            if mode == 'touch_full':
                lo2[a], hi2[a] = 0.0, L
            else:
                lo2[a], hi2[a] = rng.choice([(0.0, L * 0.5), (L * 0.25, L * 0.75), (0.0, L), (L * 0.5, L * 1.25)])
    boxes = [b1, (tuple(lo2), tuple(hi2))]
    if rng.random() < 0.4:
        boxes.append(((0.0, 0.0, L), (L * 0.5, L * 0.5, L * 1.5)))
    nudge_i = rng.randrange(1, len(boxes))
    delta = L * lu(rng, -9, -6) * sgn(rng)
    nax = rng.choice([ax, rng.randrange(3)])
    how = rng.choice(['shift', 'face'])

    def build(nudged, dsign):
        ms = []
        for i, (lo, hi) in enumerate(boxes):
            lo, hi = list(lo), list(hi)
            if nudged and i == nudge_i:
                if how == 'shift':
                    lo[nax] += dsign * delta
                    hi[nax] += dsign * delta
                else:
                    lo[nax] += dsign * delta
            ms.append(box(lo, hi, k, dg, rng))
        m = concat(*ms)
        return m
    av = rng.choice(['exact', 'exact', 'opposite'])
    A = build(av == 'opposite', -1.0)
    B = build(True, 1.0)
    P = ['L=%r' % L, 'mode=' + mode, 'axis=%d' % ax, 'boxes=%d' % len(boxes),
         'delta=%r' % delta, 'nudge=%s/%d' % (how, nax), 'a=' + av, 'k=%d' % k]
    return out(A, B, P)


def k_csg_prism_cyl(rng, seed):
    L = draw_L(rng)
    top = L * 0.5
    n = rng.randint(5, 14)
    R = L * rng.choice([0.25, 0.5, rng.uniform(0.1, 0.5)])
    cxy = (L * rng.choice([0.5, rng.uniform(0.2, 0.8)]), L * rng.choice([0.5, rng.uniform(0.2, 0.8)]))
    Hc = L * rng.uniform(0.2, 1.0)
    use_prism = rng.random() < 0.6
    pw = L * rng.uniform(0.1, 0.5)
    y0, y1 = L * rng.uniform(0, 0.4), L * rng.uniform(0.6, 1)
    ph = L * rng.choice([0.5, rng.uniform(0.1, 0.5)])
    d1 = L * lu(rng, -9, -6) * sgn(rng)
    d2 = L * lu(rng, -9, -6) * sgn(rng)
    phi0 = rng.choice([0.0, rng.uniform(0, 1)])

    def build(e1, e2):
        parts = [box((0.0, 0.0, 0.0), (L, L, top), 1, rng.choice(DIAGS), rng),
                 cylinder((cxy[0], cxy[1], top + e1), R, Hc, n, 1, True, phi0)]
        if use_prism:
            x = L + e2
            base = [(x, y1, 0.0), (x, y0, 0.0), (x + pw, (y0 + y1) / 2, 0.0)]
            parts.append(prism(base, ph, rng.randrange(2)))
        return concat(*parts)
    av = rng.choice(['exact', 'exact', 'nudged'])
    A = build(0.0, 0.0) if av == 'exact' else build(-d1, -d2)
    B = build(d1, d2 if rng.random() < 0.7 else 0.0)
    P = ['L=%r' % L, 'n=%d' % n, 'R=%s' % g6(R), 'prism=%d' % use_prism,
         'd1=%r' % d1, 'd2=%r' % d2, 'a=' + av]
    return out(A, B, P)


def lod_build(rng, fn, sd, L, P):
    nuA, nvA = res(rng, 3, 6, 9), res(rng, 3, 5, 9)
    A = grid(nuA, nvA, fn, rng.choice(DIAGS), rng)
    mode = rng.choice(['plain', 'crack', 'crack_gap', 'skirt', 'snap', 'snap_skirt'])
    nuB, nvB = res(rng, 1, 3), res(rng, 1, 3)
    dB = rng.choice(DIAGS)
    P += ['a=%dx%d' % (nuA, nvA), 'b=%dx%d' % (nuB, nvB), 'mode=' + mode]
    if mode.startswith('crack'):
        s = rng.choice([0.5, 0.25, rng.uniform(0.2, 0.8)])
        g = lu(rng, -9, -3) if mode == 'crack_gap' else 0.0
        t1 = grid(res(rng, 1, 3), res(rng, 1, 4), lambda u, v: fn(s * u, v), dB, rng)
        t2 = grid(res(rng, 1, 3), res(rng, 1, 4), lambda u, v: fn(s + g + (1 - s - g) * u, v), dB, rng)
        B = concat(t1, t2)
        P += ['split=%s' % g6(s), 'gap=%s' % g6(g)]
    else:
        B = grid(nuB, nvB, fn, dB, rng)
        if 'skirt' in mode:
            depth = L * lu(rng, -3, -1)
            B = add_skirt(B, depth, sd)
            P.append('skirt=%s' % g6(depth))
        if mode.startswith('snap'):
            q = L / 2 ** rng.randint(2, 6) if rng.random() < 0.5 else L * 10.0 ** -rng.randint(1, 2)
            B = B.mapped(lambda p: tuple(float(round(x / q) * q) for x in p))
            P.append('snap=%s' % g6(q))
    if rng.random() < 0.3:
        A, B = B, A
        P.append('swapped=1')
    return A, B


def lod_kind(name):
    def k(rng, seed):
        L = draw_L(rng)
        P = ['L=%r' % L]
        fn, sd = SURFS[name](rng, L, P)
        A, B = lod_build(rng, fn, sd, L, P)
        return out(A, B, P)
    return k


def k_terrain_far(rng, seed):
    L = float('%.4g' % lu(rng, 1, 3))
    P = ['L=%r' % L]
    fn, sd = surf_terrain(rng, L, P)
    A, B = lod_build(rng, fn, sd, L, P)
    return out(A, B, P, post=make_far_post('any', 3, 7, 'both'))


def export_base(rng, P):
    L = draw_L(rng)
    P.append('L=%r' % L)
    if rng.random() < 0.35:
        _, fn, _ = random_surface(rng, L, P)
        A = grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), fn, rng.choice(DIAGS), rng)
        B = grid(res(rng, 1, 5, 8), res(rng, 1, 5, 8), fn, rng.choice(DIAGS), rng)
        P.append('retri=1')
        return A, B
    A = random_shape(rng, L, P)
    return A, A.copy()


def export_post(kind):
    def post(rng, A, B, P):
        size = size_of([A, B])
        if kind == 'f32':
            fn = f32
            P.append('round=f32')
        else:
            fn = dec_rounder(rng, size, size, P)
        w = rng.choice(['b', 'b', 'both'])
        P.append('rounded=' + w)
        B = round_mesh(B, fn)
        if w == 'both':
            A = round_mesh(A, fn)
        return A, B
    return post


def k_export_f32(rng, seed):
    P = []
    A, B = export_base(rng, P)
    return out(A, B, P, post=export_post('f32'))


def k_export_decimal(rng, seed):
    P = []
    A, B = export_base(rng, P)
    return out(A, B, P, post=export_post('dec'))


def k_export_f32_far(rng, seed):
    P = []
    A, B = export_base(rng, P)
    return out(A, B, P, post=make_far_post('f32', 3, 6, 'any'))


def k_export_decimal_far(rng, seed):
    P = []
    A, B = export_base(rng, P)
    return out(A, B, P, post=make_far_post('dec', 3, 7, 'any'))


def k_mirror_rot(rng, seed):
    L = draw_L(rng)
    P = ['L=%r' % L]
    A = random_shape(rng, L, P)
    lo, hi = bbox([A])
    c = tuple((lo[k] + hi[k]) / 2 for k in range(3))
    var = rng.choice(['mirror', 'rot90', 'rot_small', 'rot_random', 'invert', 'mirror_flip'])
    P.append('var=' + var)
    if var in ('mirror', 'mirror_flip'):
        a = rng.randrange(3)

        def fn(p):
            q = list(p)
            q[a] = 2 * c[a] - p[a]
            return q
        B = A.mapped(fn)
        if var == 'mirror_flip':
            B = B.flipped()
        P.append('axis=%d' % a)
    elif var == 'rot90':
        a = rng.randrange(3)
        b, d = (a + 1) % 3, (a + 2) % 3

        def fn(p):
            q = list(p)
            q[b] = c[b] - (p[d] - c[d])
            q[d] = c[d] + (p[b] - c[b])
            return q
        B = A.mapped(fn)
        P.append('axis=%d' % a)
    elif var == 'invert':
        B = A.mapped(lambda p: (2 * c[0] - p[0], 2 * c[1] - p[1], 2 * c[2] - p[2]))
    else:
        ang = sgn(rng) * lu(rng, -12, -3) if var == 'rot_small' else rng.uniform(0, TWO_PI)
        M = rot_matrix(rand_unit(rng), ang)
        B = A.mapped(lambda p: rot_about(p, M, c))
        P.append('angle=%s' % g6(ang))
    return out(A, B, P)


def k_ulp_jitter(rng, seed):
    L = draw_L(rng)
    P = ['L=%r' % L]
    A = random_shape(rng, L, P)

    def post(rng, A, B, P):
        kmax = rng.randint(1, 4)
        mode = rng.choice(['all_coords', 'per_vertex', 'some_vertices'])
        frac = rng.uniform(0.1, 0.6)
        P += ['kmax=%d' % kmax, 'jitter=' + mode]

        def jit(p):
            if mode == 'some_vertices' and rng.random() > frac:
                return p
            if mode == 'per_vertex':
                k = rng.randint(-kmax, kmax)
                return tuple(ulp_move(x, k) for x in p)
            return tuple(ulp_move(x, rng.randint(-kmax, kmax)) for x in p)
        return A, B.mapped(jit)
    return out(A, A.copy(), P, post=post)


def k_subset(rng, seed):
    L = draw_L(rng)
    P = ['L=%r' % L]
    A = random_shape(rng, L, P)
    nf = len(A.f)
    var = rng.choice(['single', 'block', 'all_but_one', 'random', 'random'])
    if var == 'single':
        keep = [rng.randrange(nf)]
    elif var == 'block':
        i = rng.randrange(nf)
        keep = list(range(i, min(nf, i + rng.randint(1, max(1, nf // 2)))))
    elif var == 'all_but_one' and nf > 1:
        j = rng.randrange(nf)
        keep = [i for i in range(nf) if i != j]
    else:
        keep = sorted(rng.sample(range(nf), rng.randint(1, nf)))
    B = Mesh(A.v, [A.f[i] for i in keep])
    if rng.random() < 0.4:
        rng.shuffle(B.f)
    if rng.random() < 0.4:
        A, B = B, A
        P.append('swapped=1')
    P += ['var=' + var, 'kept=%d/%d' % (len(keep), nf)]
    return out(A, B, P)


def k_self_retri(rng, seed):
    L = draw_L(rng)
    var = rng.choice(['box', 'prism', 'polyomino', 'octa'])
    P = ['var=' + var, 'L=%r' % L]
    if var == 'box':
        hi = (L, L * rng.choice([1.0, 0.5, 0.75]), L * rng.choice([1.0, 0.25, 2.0]))
        k1, k2 = rng.choice([1, 2, 2, 3]), rng.choice([1, 2, 2, 4])
        A = box((0.0, 0.0, 0.0), hi, k1, rng.choice(DIAGS), rng)
        B = box((0.0, 0.0, 0.0), hi, k2, rng.choice(DIAGS), rng, do_weld=rng.random() < 0.7)
        P.append('k=%d/%d' % (k1, k2))
    elif var == 'prism':
        n = rng.randint(3, 10)
        pts = [(L * math.cos(TWO_PI * i / n), L * math.sin(TWO_PI * i / n), 0.0) for i in range(n)]
        h = L * rng.choice([1.0, 0.5, rng.uniform(0.1, 2)])
        r = rng.randrange(n)
        A = prism(pts, h, 0)
        B = prism(pts[r:] + pts[:r], h, 1)
        P.append('n=%d' % n)
    elif var == 'polyomino':
        g = rng.randint(2, 5)
        cells = {(rng.randrange(g), rng.randrange(g))}
        for _ in range(rng.randint(1, g * g)):
            cx, cy = rng.choice(sorted(cells))
            dx, dy = rng.choice([(1, 0), (-1, 0), (0, 1), (0, -1)])
            if 0 <= cx + dx < g and 0 <= cy + dy < g:
                cells.add((cx + dx, cy + dy))
        s = L / g
        A, B = Mesh(), Mesh()
        for (cx, cy) in sorted(cells):
            q = [A.add((cx * s, cy * s, 0.0)), A.add(((cx + 1) * s, cy * s, 0.0)),
                 A.add(((cx + 1) * s, (cy + 1) * s, 0.0)), A.add((cx * s, (cy + 1) * s, 0.0))]
            if (cx + cy) % 2:
                A.f += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
            else:
                A.f += [(q[0], q[1], q[3]), (q[1], q[2], q[3])]
        for cy in range(g):
            cx = 0
            while cx < g:
                if (cx, cy) in cells:
                    e = cx
                    while (e + 1, cy) in cells:
                        e += 1
                    q = [B.add((cx * s, cy * s, 0.0)), B.add(((e + 1) * s, cy * s, 0.0)),
                         B.add(((e + 1) * s, (cy + 1) * s, 0.0)), B.add((cx * s, (cy + 1) * s, 0.0))]
                    B.f += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
                    cx = e + 1
                else:
                    cx += 1
        A, B = weld(A), weld(B)
        P.append('cells=%d' % len(cells))
    else:
        A, B = octa(L, False), octa(L, True)
        if rng.random() < 0.5:
            A, B = B, A
    return out(A, B, P, place=rng.choice([ALL, EXACT]))


SCALE_SUBKINDS = ['tilted_grid', 'offset_sheet', 'sliver', 'needle', 'cap', 'hinge',
                  'fin_perp', 'fan_sliver', 'csg_boxes', 'lod_sphere', 'crossing']


_SCALE_RNG = {}


def k_scale_sweep(rng, seed):
    g = seed // len(KINDS)
    e = (-6, -3, 0, 3, 6)[g % 5]
    s0 = seed - (g % 5) * len(KINDS)
    crng = _SCALE_RNG.get(seed)
    if crng is None:  # kept across redraws so a redraw continues the stream
        crng = _SCALE_RNG[seed] = random.Random(s0)
    sub = crng.choice(SCALE_SUBKINDS)
    r = KIND_FN[sub](crng, s0)
    A, B = r['a'], r['b']
    pname, pfn = draw_placement(crng, r['place'], size_of([A, B]))
    if pfn:
        A, B = A.mapped(pfn), B.mapped(pfn)
    exact2 = crng.random() < 0.5
    S = 2.0 ** round(e * math.log2(10)) if exact2 else 10.0 ** e
    P = ['group_seed=%d' % s0, 'sub=' + sub, 'scale=%r' % S, 'subplace=' + pname] + r['p']
    A = A.mapped(lambda p: (p[0] * S, p[1] * S, p[2] * S))
    B = B.mapped(lambda p: (p[0] * S, p[1] * S, p[2] * S))
    return out(A, B, P, place=('identity',))


def k_exact_ties(rng, seed):
    L = 2.0 ** rng.randint(-3, 3)
    j = rng.randint(0, 3)
    n = 2 ** j
    A = grid(n, n, plane(0.0, 0.0, L, L), rng.choice(DIAGS), rng)
    var = rng.choice(['corners', 'parallel', 'rot90', 'midlines', 'checker', 'center_point'])
    h = L / 2 ** rng.randint(0, 4)
    P = ['var=' + var, 'L=%r' % L, 'n=%d' % n, 'h=%r' % h]
    B = Mesh()
    if var == 'corners':
        w = L / 2 ** rng.randint(2, 4)
        pt = rng.random() < 0.5
        for cx, cy in ((0.0, 0.0), (L, 0.0), (0.0, L), (L, L)):
            if pt:
                i = B.add((cx, cy, h))
                B.tri(i, i, i)
            else:
                sx = w if cx == 0.0 else -w
                sy = w if cy == 0.0 else -w
                B.tri(B.add((cx, cy, h)), B.add((cx + sx, cy, h)), B.add((cx, cy + sy, h)))
    elif var == 'parallel':
        B = concat(grid(n, n, plane(0.0, 0.0, L, L, h), rng.choice(DIAGS), rng),
                   grid(n, n, plane(0.0, 0.0, L, L, -h), rng.choice(DIAGS), rng))
    elif var == 'rot90':
        c = L / 2
        B = A.mapped(lambda p: (c - (p[1] - c), c + (p[0] - c), p[2]))
    elif var == 'midlines':
        c = L / 2
        for seg in (((c, 0.0, 0.0), (c, L, 0.0)), ((0.0, c, 0.0), (L, c, 0.0))):
            i, k = B.add(seg[0]), B.add(seg[1])
            B.tri(i, k, k)
    elif var == 'checker':
        B = Mesh(A.v, [f for idx, f in enumerate(A.f) if (idx // 2) % 2 == 0 or n == 1])
    else:
        i = B.add((L / 2, L / 2, h))
        B.tri(i, i, i)
    if rng.random() < 0.3:
        A, B = B, A
        P.append('swapped=1')
    return out(A, B, P, place=EXACT)


KIND_FN = {
    'coplanar_retri': k_coplanar_retri, 'coplanar_partial': k_coplanar_partial,
    'coplanar_tjunction': k_coplanar_tjunction, 'tilted_grid': k_tilted_grid,
    'offset_sheet': k_offset_sheet, 'offset_sheet_far': k_offset_sheet_far,
    'sliver': k_sliver, 'needle': k_needle, 'cap': k_cap, 'fan_sliver': k_fan_sliver,
    'fin_perp': k_fin_perp, 'hinge': k_hinge, 't_joint': k_t_joint,
    'crossing': k_crossing, 'zero_area_mixed': k_zero_area_mixed,
    'degenerate_only': k_degenerate_only, 'dup_faces': k_dup_faces,
    'csg_boxes': k_csg_boxes, 'csg_prism_cyl': k_csg_prism_cyl,
    'lod_sphere': lod_kind('sphere'), 'lod_saddle': lod_kind('saddle'),
    'lod_terrain': lod_kind('terrain'), 'lod_cylinder': lod_kind('cylinder'),
    'terrain_far': k_terrain_far, 'export_f32': k_export_f32,
    'export_decimal': k_export_decimal, 'export_f32_far': k_export_f32_far,
    'export_decimal_far': k_export_decimal_far, 'mirror_rot': k_mirror_rot,
    'ulp_jitter': k_ulp_jitter, 'subset': k_subset, 'self_retri': k_self_retri,
    'scale_sweep': k_scale_sweep, 'exact_ties': k_exact_ties,
}
assert sorted(KIND_FN) == sorted(KINDS)


# --------------------------------------------------------------------------
# placement, validation, output
# --------------------------------------------------------------------------
PLACE_W = {'identity': 0.35, 'dyadic': 0.35, 'rotate': 0.30}


def draw_placement(rng, allowed, size):
    opts = [k for k in ('identity', 'dyadic', 'rotate') if k in allowed]
    tot = sum(PLACE_W[k] for k in opts)
    r = rng.random() * tot
    name = opts[-1]
    for k in opts:
        r -= PLACE_W[k]
        if r < 0:
            name = k
            break
    if name == 'identity':
        return 'identity', None
    if name == 'dyadic':
        perm = rng.sample(range(3), 3)
        sg = [rng.choice((1.0, -1.0)) for _ in range(3)]
        ke = rng.randint(-4, 4)
        sc = 2.0 ** ke
        base = 2.0 ** math.floor(math.log2(size))
        t = [base * rng.randint(-8, 8) / 2 ** rng.randint(0, 3) for _ in range(3)]

        def fn(p):
            return (sg[0] * p[perm[0]] * sc + t[0], sg[1] * p[perm[1]] * sc + t[1],
                    sg[2] * p[perm[2]] * sc + t[2])
        desc = 'dyadic(perm=%d%d%d,sign=%s,scale=2^%d,t=%r,%r,%r)' % (
            perm[0], perm[1], perm[2], ''.join('+' if s > 0 else '-' for s in sg), ke,
            t[0], t[1], t[2])
        return desc, fn
    M = rand_rot(rng)
    t = [rng.uniform(-1, 1) * size for _ in range(3)]

    def fn(p):
        q = mat_apply(M, p)
        return (q[0] + t[0], q[1] + t[1], q[2] + t[2])
    return 'rotate', fn


def check(m):
    """None if the mesh respects all limits, else a reason string."""
    nf = len(m.f)
    if not 1 <= nf <= MAX_TRI:
        return 'ntri=%d' % nf
    nv = len(m.v)
    for p in m.v:
        if len(p) != 3 or not all(isinstance(x, float) and math.isfinite(x) for x in p):
            return 'nonfinite'
    cnt = [0] * nv
    ccnt = {}
    for f in m.f:
        if len(f) != 3:
            return 'face'
        for i in set(f):
            if not (0 <= i < nv):
                return 'index'
            cnt[i] += 1
        for key in {m.v[i] for i in f}:
            ccnt[key] = ccnt.get(key, 0) + 1
    if min(cnt) == 0:
        return 'unused'
    if max(cnt) > MAX_VAL:
        return 'valence_idx'
    if max(ccnt.values()) > MAX_VAL:
        return 'valence_coord'
    return None


def make_pair(seed):
    rng = random.Random(seed)
    kind = KINDS[seed % len(KINDS)]
    fn = KIND_FN[kind]
    reasons = []
    for attempt in range(500):
        r = fn(rng, seed)
        A, B = r['a'], r['b']
        if A.f and B.f:
            pname, pfn = draw_placement(rng, r['place'], size_of([A, B]))
            if pfn:
                A, B = A.mapped(pfn), B.mapped(pfn)
            P = list(r['p'])
            if r['post']:
                A, B = r['post'](rng, A, B, P)
            A, B = compact(A), compact(B)
            ea, eb = check(A), check(B)
            if ea is None and eb is None:
                _SCALE_RNG.pop(seed, None)
                P += ['place=' + pname, 'attempt=%d' % attempt]
                return kind, A, B, ' '.join(P)
            reasons.append((ea, eb))
        else:
            reasons.append(('empty', 'empty'))
    raise RuntimeError('seed %d kind %s: no valid draw (%r)' % (seed, kind, reasons[-5:]))


def write_obj(path, header, m):
    lines = [header]
    lines += ['v %r %r %r' % p for p in m.v]
    lines += ['f %d %d %d' % (a + 1, b + 1, c + 1) for a, b, c in m.f]
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: python3 generate_pairs17.py OUTDIR FROM TO\n')
        return 2
    outdir, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    counts = []
    n = 0
    for s in range(lo, hi):
        kind, A, B, params = make_pair(s)
        for tag, m in (('a', A), ('b', B)):
            hdr = '# gen17 seed=%d kind=%s mesh=%s %s' % (s, kind, tag, params)
            write_obj(os.path.join(outdir, '%06d_%s_%s.obj' % (s, kind, tag)), hdr, m)
            counts.append(len(m.f))
        n += 1
    if counts:
        med = statistics.median(counts)
        med = int(med) if med == int(med) else med
        stats = '%d/%s/%d' % (min(counts), med, max(counts))
    else:
        stats = '0/0/0'
    print('gen17: %d pairs written to %s; triangles per mesh min/median/max = %s'
          % (n, outdir, stats))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
