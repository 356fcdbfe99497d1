#!/usr/bin/env python3
"""Eleventh independent pair generator: adversarial coverage for the cover bound.

Written blind to the other generators.  Every pair (A, B) puts a nearly flat or
flat mesh B made of many triangles with tricky coverage (holes, T-junctions,
cracks, overlaps, folds, duplicated / zero-area / sliver triangles, fans,
non-planar lifts, tilted pieces, steep pieces, ragged rims) under a mesh A that
lies within 0 .. 1e-3 of the size of B (sometimes exactly coplanar), so that the
true one-sided distance A->B is attained in a tricky spot.  A is one of: a
triangle, a grid (also of thin triangles), a fan or cone of thin triangles,
needles, a fan of separate needles, or several of these, flat, lifted, tilted
or jittered.  Afterwards both meshes get the same random similarity transform
(rotation, scale 1e-6..1e6, translation up to 1e8 times the size), or none.

Usage:  python3 generate_pairs11.py OUTDIR SEED_FROM SEED_TO
writes OUTDIR/%06d_KIND_a.obj and OUTDIR/%06d_KIND_b.obj for each seed s in
[SEED_FROM, SEED_TO); KIND = KINDS[s % len(KINDS)], randomness from
random.Random(s).  Standard library only.

Kinds:
  hole_poly         grid of B with one to three tiny polygonal holes (1e-9..1e-1)
                    stitched into cells by a zipper of thin triangles
  hole_removed      grid of B with one to four triangles removed under A
  hole_fan_center   fan of B (many thin triangles) with a tiny hole or a missing
                    wedge at its apex; A a cone / fan over it
  hole_layers       two superimposed layers of B (0 .. 1e-6 apart), each with its
                    own hole; the holes overlap partly or not at all
  tjunction_quadtree  non-conforming quadtree triangulation (T-junctions everywhere)
  tjunction_offset  hanging vertices moved 1e-15..1e-6 off the edge they hang on
                    (tiny gaps or overlaps), sometimes lifted
  crack_dup         two patches meeting along a (slanted) edge with different or
                    duplicated, unshared vertices on it
  crack_gap         two patches separated by a gap of 1e-15..1e-6 (parallel or a
                    wedge), sometimes with a step
  crack_overlap_step  two patches overlapping by 1e-15..1e-6 with a tiny step
  overlap_retri     two triangulations of one region superimposed (grid, fan,
                    strip), the second exactly coplanar, lifted or tilted
  fold_edge         B folded back onto itself along an edge (a flap sharing the
                    fold edge's vertices); A ends at, before or past the fold
  zfold             Z-shaped fold: three layers sharing two fold edges
  dup_faces         duplicated faces (same, reversed, rotated indices, or copied
                    vertices), and a removed triangle whose neighbour is doubled
  zero_area_rim     zero-area triangles on B's rim (collinear third vertex) and
                    inside; A's boundary along B's or sticking out 1e-15..1e-3
  zero_area_fill    a removed triangle whose edges are each "closed" by a
                    zero-area triangle, so every edge has two faces by index
  slivers_strip     strip triangulation with clustered vertices: slivers
                    1e-13..1e-5 thin, sometimes one sliver missing
  fan_rim           fan from a rim vertex (corner or edge point) of many thin
                    triangles, sometimes a wedge missing, zero-area spokes kept
  fan_point         fan of many (clustered) thin triangles round an interior
                    point, lifted centre, sometimes a wedge missing
  nonplanar_lift    grid or fan of B with vertices lifted by 1e-12..1e-4
  tilted_pieces     separate blocks of B each tilted by 1e-10..1e-2 rad
  steep_mix         flat B with tents / spikes / vertical fins (steep pieces)
  boundary_exact    A re-triangulates B's region or a part sharing B's rim,
                    coplanar or lifted, or sticking out by 1e-15..1e-3
  a_needles         A made of needles (1e-12..1e-2 wide) over a holed / T-junction B
  a_cone_over_fan   A a cone of thin triangles over a fan of B with other spokes
  a_coplanar_mix    A copies part of B exactly (coplanar) plus lifted parts over a hole
  nonmanifold_book  pages hinged on B's edges at tiny angles (edges of 3+ faces),
                    some covering a hole
  rim_sliver_out    slivers 1e-13..1e-6 wide hanging out of B's rim; A sticks out by
                    about as much
  combo             several defects at once (hole, T-junctions, jitter, duplicates,
                    flipped orientations) in one B
"""

import math
import os
import random
import sys

TWO_PI = 2.0 * math.pi


# ----------------------------------------------------------------------------
# mesh helpers
# ----------------------------------------------------------------------------

class Mesh:
    def __init__(self):
        self.V = []
        self.F = []

    def v(self, x, y, z=0.0):
        self.V.append((float(x), float(y), float(z)))
        return len(self.V) - 1

    def vp(self, p):
        if len(p) == 2:
            return self.v(p[0], p[1], 0.0)
        return self.v(p[0], p[1], p[2])

    def f(self, a, b, c):
        self.F.append((a, b, c))
        return len(self.F) - 1

    def tri(self, p, q, s):
        return self.f(self.vp(p), self.vp(q), self.vp(s))

    def extend(self, other):
        off = len(self.V)
        self.V.extend(other.V)
        for (a, b, c) in other.F:
            self.F.append((a + off, b + off, c + off))


def lerp(a, b, t):
    if t == 0.0:
        return a
    if t == 1.0:
        return b
    return a + (b - a) * t


def bil(P00, P10, P11, P01, u, v):
    out = []
    for k in range(3):
        out.append((1.0 - u) * (1.0 - v) * P00[k] + u * (1.0 - v) * P10[k]
                   + u * v * P11[k] + (1.0 - u) * v * P01[k])
    return out


def p3(p):
    return (p[0], p[1], p[2] if len(p) > 2 else 0.0)


def quad_patch(m, P00, P10, P11, P01, nx, ny, zf=None, diag='alt', r=None,
               skip=None, us=None, vs=None):
    """Bilinear quad patch. Returns (idx, faces) with faces = list of
    (face_index, i, j, k). skip(i, j, k) -> True drops that triangle."""
    P00, P10, P11, P01 = p3(P00), p3(P10), p3(P11), p3(P01)
    if us is None:
        us = [i / nx for i in range(nx + 1)]
    if vs is None:
        vs = [j / ny for j in range(ny + 1)]
    nx = len(us) - 1
    ny = len(vs) - 1
    idx = [[0] * (ny + 1) for _ in range(nx + 1)]
    for i in range(nx + 1):
        for j in range(ny + 1):
            x, y, z = bil(P00, P10, P11, P01, us[i], vs[j])
            if zf is not None:
                z = z + zf(x, y)
            idx[i][j] = m.v(x, y, z)
    faces = []
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = idx[i][j], idx[i + 1][j], idx[i + 1][j + 1], idx[i][j + 1]
            if diag == 'a':
                dd = 0
            elif diag == 'b':
                dd = 1
            elif diag == 'rand':
                dd = r.randint(0, 1)
            else:
                dd = (i + j) & 1
            tris = [(a, b, c), (a, c, d)] if dd == 0 else [(a, b, d), (b, c, d)]
            for k, t in enumerate(tris):
                if skip is not None and skip(i, j, k):
                    continue
                faces.append((m.f(*t), i, j, k))
    return idx, faces


def zipper(m, c, outer, inner):
    """Triangulate the annulus between two star-shaped polygons (vertex index
    lists, CCW around the 2D point c)."""
    def ang(k):
        p = m.V[k]
        return math.atan2(p[1] - c[1], p[0] - c[0])

    def prep(lst):
        a0 = ang(lst[0])
        rel = [((ang(k) - a0) % TWO_PI) for k in lst]
        rel[0] = 0.0
        return rel

    rel_o = prep(outer)
    base = ang(outer[0])
    # inner start: the vertex with the smallest angle relative to outer[0]
    rin = [((ang(k) - base) % TWO_PI) for k in inner]
    s = min(range(len(inner)), key=lambda q: rin[q])
    inner = inner[s:] + inner[:s]
    rel_i = rin[s:] + rin[:s]
    O = outer + [outer[0]]
    ro = rel_o + [TWO_PI + rel_o[0]]
    I = inner + [inner[0]]
    ri = rel_i + [TWO_PI + rel_i[0]]
    no, ni = len(outer), len(inner)
    i = j = 0
    out = []
    while i < no or j < ni:
        if i == no:
            adv_o = False
        elif j == ni:
            adv_o = True
        else:
            adv_o = ro[i + 1] <= ri[j + 1]
        if adv_o:
            out.append(m.f(O[i], O[i + 1], I[j]))
            i += 1
        else:
            out.append(m.f(O[i], I[j + 1], I[j]))
            j += 1
    return out


def chain_strip(m, bottom, top, r=None, mode='x'):
    """Triangulate between a bottom chain and a top chain (vertex index lists,
    increasing x).  Returns face indices."""
    i = j = 0
    nb, nt = len(bottom) - 1, len(top) - 1
    out = []
    while i < nb or j < nt:
        if i == nb:
            adv_b = False
        elif j == nt:
            adv_b = True
        elif mode == 'rand':
            adv_b = r.random() < 0.5
        else:
            adv_b = m.V[bottom[i + 1]][0] <= m.V[top[j + 1]][0]
        if adv_b:
            out.append(m.f(bottom[i], bottom[i + 1], top[j]))
            i += 1
        else:
            out.append(m.f(bottom[i], top[j + 1], top[j]))
            j += 1
    return out


def square_pt(t):
    k = int(math.floor(t)) % 4
    f = t - math.floor(t)
    if k == 0:
        return (f, 0.0)
    if k == 1:
        return (1.0, f)
    if k == 2:
        return (1.0 - f, 1.0)
    return (0.0, 1.0 - f)


def perimeter_params(r, n, clustered=False):
    """Sorted parameters in [0, 4) along the unit square's perimeter, always
    containing the four corners."""
    ts = set([0.0, 1.0, 2.0, 3.0])
    mode = r.random()
    while len(ts) < n:
        if clustered and r.random() < 0.4 and len(ts) > 4:
            t0 = r.choice(sorted(ts))
            t = t0 + 10 ** r.uniform(-13, -5) * (1 if r.random() < 0.5 else -1)
            if 0.0 < t < 4.0 and abs(t - round(t)) > 1e-3:
                ts.add(t)
            continue
        if mode < 0.5:
            t = 4.0 * r.randint(1, 4 * n) / (4 * n)
        else:
            t = r.uniform(0.0, 4.0)
        if t < 4.0:
            ts.add(t)
    return sorted(ts)


def polygon(r, c, rad, k, irregular=True):
    th = r.uniform(0.0, TWO_PI)
    pts = []
    for q in range(k):
        a = th + TWO_PI * q / k
        if irregular:
            a += r.uniform(-0.3, 0.3) * TWO_PI / k
        rr = rad * (r.uniform(0.4, 1.0) if irregular else 1.0)
        pts.append((c[0] + rr * math.cos(a), c[1] + rr * math.sin(a)))
    return pts


def centroid(m, fi):
    a, b, c = m.F[fi]
    return ((m.V[a][0] + m.V[b][0] + m.V[c][0]) / 3.0,
            (m.V[a][1] + m.V[b][1] + m.V[c][1]) / 3.0)


def remove_faces(m, drop):
    drop = set(drop)
    m.F = [f for q, f in enumerate(m.F) if q not in drop]


def tiny(r, lo, hi):
    return 10 ** r.uniform(lo, hi)


def sgn(r):
    return 1.0 if r.random() < 0.5 else -1.0


# ----------------------------------------------------------------------------
# A builders (local frame: B lies near z = 0 over roughly [0,1]^2)
# ----------------------------------------------------------------------------

def pick_dz(r):
    u = r.random()
    if u < 0.2:
        return 0.0
    s = tiny(r, -15, -3)
    return s if r.random() < 0.75 else -s


def make_zf(r, cx, cy, flat_only=False, dz=None):
    if dz is None:
        dz = pick_dz(r)
    gx = gy = 0.0
    if not flat_only and r.random() < 0.35:
        g = tiny(r, -12, -3)
        a = r.uniform(0.0, TWO_PI)
        gx, gy = g * math.cos(a), g * math.sin(a)
    jit = 0.0
    if not flat_only and r.random() < 0.15:
        jit = tiny(r, -13, -5)

    def zf(x, y):
        z = dz + gx * (x - cx) + gy * (y - cy)
        if jit:
            z += r.uniform(-jit, jit)
        return z
    return zf


def clamp(p, box):
    return (min(max(p[0], box[0]), box[2]), min(max(p[1], box[1]), box[3]))


def a_triangle(r, m, c, rad, box, zf):
    th = r.uniform(0.0, TWO_PI)
    pts = []
    for k in range(3):
        a = th + TWO_PI * k / 3 + r.uniform(-0.5, 0.5)
        rr = rad * r.uniform(0.6, 1.5)
        pts.append(clamp((c[0] + rr * math.cos(a), c[1] + rr * math.sin(a)), box))
    m.tri(*[(p[0], p[1], zf(p[0], p[1])) for p in pts])


def a_grid(r, m, box, zf):
    u = r.random()
    if u < 0.25:
        nx, ny = 1, r.randint(10, 60)       # strips of thin triangles
        if r.random() < 0.5:
            nx, ny = ny, nx
    elif u < 0.4:
        nx = ny = 1
    else:
        nx, ny = r.randint(1, 9), r.randint(1, 9)
    x0, y0, x1, y1 = box
    quad_patch(m, (x0, y0, 0), (x1, y0, 0), (x1, y1, 0), (x0, y1, 0), nx, ny,
               zf=zf, diag=r.choice(['a', 'b', 'alt', 'rand']), r=r)


def a_fan(r, m, c, rad, box, zf, lift=0.0):
    n = r.choice([3, 4, 6, 8, r.randint(5, 40), r.randint(40, 90)])
    th = r.uniform(0.0, TWO_PI)
    ring = []
    square = r.random() < 0.3
    for k in range(n):
        a = th + TWO_PI * k / n
        if square:
            s = max(abs(math.cos(a)), abs(math.sin(a)))
            p = (c[0] + rad * math.cos(a) / s, c[1] + rad * math.sin(a) / s)
        else:
            p = (c[0] + rad * math.cos(a), c[1] + rad * math.sin(a))
        p = clamp(p, box)
        ring.append(m.v(p[0], p[1], zf(p[0], p[1])))
    cc = clamp(c, box)
    ap = m.v(cc[0], cc[1], zf(cc[0], cc[1]) + lift)
    for k in range(n):
        m.f(ap, ring[k], ring[(k + 1) % n])


def a_needles(r, m, c, box, zf, fan=False):
    k = r.randint(1, 12) if fan else r.randint(1, 25)
    size = max(box[2] - box[0], box[3] - box[1])
    for q in range(k):
        if fan or q == 0:
            p = c
        else:
            p = (r.uniform(box[0], box[2]), r.uniform(box[1], box[3]))
        a = r.uniform(0.0, TWO_PI)
        d = (math.cos(a), math.sin(a))
        n = (-d[1], d[0])
        L = size * r.uniform(0.05, 1.0)
        w = L * tiny(r, -12, -2)
        if fan:
            p0 = p
            e = (p[0] + L * d[0], p[1] + L * d[1])
        else:
            p0 = (p[0] - 0.5 * L * d[0], p[1] - 0.5 * L * d[1])
            e = (p[0] + 0.5 * L * d[0], p[1] + 0.5 * L * d[1])
        q1 = clamp((e[0] + w * n[0], e[1] + w * n[1]), box)
        q2 = clamp((e[0] - w * n[0], e[1] - w * n[1]), box)
        p0 = clamp(p0, box)
        m.tri(*[(pp[0], pp[1], zf(pp[0], pp[1])) for pp in (p0, q1, q2)])


def build_A(r, hot, dom=(0.0, 0.0, 1.0, 1.0), rad_exp=(-4.0, 0.0), out=0.0,
            shapes=None, rad=None):
    """A near the hot points.  out > 0 lets A stick out of dom by out."""
    m = Mesh()
    c = r.choice(hot)
    if r.random() < 0.3:
        e = tiny(r, -14, -4)
        c = (c[0] + e * sgn(r), c[1] + e * sgn(r))
    if rad is None:
        rad = tiny(r, rad_exp[0], rad_exp[1])
    dbox = (dom[0] - out, dom[1] - out, dom[2] + out, dom[3] + out)
    box = (max(dbox[0], c[0] - rad), max(dbox[1], c[1] - rad),
           min(dbox[2], c[0] + rad), min(dbox[3], c[1] + rad))
    if box[2] <= box[0] or box[3] <= box[1]:
        box = dbox
    c = clamp(c, box)
    zf = make_zf(r, c[0], c[1])
    if shapes is None:
        shapes = ['tri', 'grid', 'grid', 'fan', 'cone', 'needles', 'needle_fan', 'multi']
    shape = r.choice(shapes)
    parts = [shape] if shape != 'multi' else r.sample(['tri', 'grid', 'fan', 'needles'], 2)
    for s in parts:
        if s == 'tri':
            a_triangle(r, m, c, rad, box, zf)
        elif s == 'grid':
            a_grid(r, m, box, zf)
        elif s == 'fan':
            a_fan(r, m, c, rad, box, zf)
        elif s == 'cone':
            lift = 0.0 if r.random() < 0.2 else sgn(r) * tiny(r, -15, -3)
            a_fan(r, m, c, rad, box, zf, lift)
        elif s == 'needles':
            a_needles(r, m, c, box, zf)
        elif s == 'needle_fan':
            a_needles(r, m, c, box, zf, fan=True)
    return m


# ----------------------------------------------------------------------------
# B kinds: each returns (A, B) in the local frame
# ----------------------------------------------------------------------------

def unit_grid(r, m, n, ny=None, zf=None, skip=None, diag=None):
    if ny is None:
        ny = n
    if diag is None:
        diag = r.choice(['a', 'b', 'alt', 'rand'])
    return quad_patch(m, (0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), n, ny,
                      zf=zf, diag=diag, r=r, skip=skip)


def k_hole_poly(r):
    B = Mesh()
    h = tiny(r, -9, -1)
    nmax = max(1, min(8, int(0.3 / h)))
    n = r.randint(1, nmax)
    cell = 1.0 / n
    nh = min(n * n, r.randint(1, 3))
    cells = set()
    while len(cells) < nh:
        cells.add((r.randrange(n), r.randrange(n)))
    idx, _ = unit_grid(r, B, n, skip=lambda i, j, k: (i, j) in cells)
    hot = []
    for (ci, cj) in sorted(cells):
        c = ((ci + 0.5 + r.uniform(-0.2, 0.2)) * cell, (cj + 0.5 + r.uniform(-0.2, 0.2)) * cell)
        if r.random() < 0.2:
            c = ((ci + 0.5) * cell, (cj + 0.5) * cell)
        hh = min(h, 0.25 * cell)
        k = r.choice([3, 3, 4, 5, 6, 8, 12])
        pts = polygon(r, c, hh, k, irregular=r.random() < 0.6)
        zlift = 0.0 if r.random() < 0.7 else sgn(r) * tiny(r, -12, -6)
        inner = [B.v(p[0], p[1], zlift) for p in pts]
        outer = [idx[ci][cj], idx[ci + 1][cj], idx[ci + 1][cj + 1], idx[ci][cj + 1]]
        if r.random() < 0.3:
            # extra ring points on the cell's edges -> T-junctions with neighbours
            ring = []
            for q in range(4):
                ring.append(outer[q])
                a, b = B.V[outer[q]], B.V[outer[(q + 1) % 4]]
                t = r.uniform(0.2, 0.8)
                ring.append(B.v(lerp(a[0], b[0], t), lerp(a[1], b[1], t), 0.0))
            outer = ring
        zipper(B, c, outer, inner)
        hot.append(c)
    A = build_A(r, hot, rad_exp=(math.log10(h) - 0.5, 0.0))
    return A, B


def k_hole_removed(r):
    B = Mesh()
    n = r.randint(2, 12)
    _, faces = unit_grid(r, B, n, ny=r.randint(2, 12))
    k = r.randint(1, 4)
    first = r.randrange(len(faces))
    drop = [faces[first][0]]
    while len(drop) < k:
        if r.random() < 0.6:
            q = min(len(faces) - 1, max(0, first + r.randint(-3, 3)))
        else:
            q = r.randrange(len(faces))
        if faces[q][0] not in drop:
            drop.append(faces[q][0])
    hot = [centroid(B, fi) for fi in drop]
    if r.random() < 0.3:
        a, b, c = B.F[drop[0]]
        hot.append((B.V[a][0], B.V[a][1]))
    remove_faces(B, drop)
    A = build_A(r, hot, rad_exp=(-2.5, 0.0))
    return A, B


def fan_ring(r, B, n, clustered):
    ts = perimeter_params(r, n, clustered)
    return ts, [B.v(*square_pt(t)) for t in ts]


def k_hole_fan_center(r):
    B = Mesh()
    n = r.randint(12, 90)
    ts, ring = fan_ring(r, B, n, r.random() < 0.4)
    c = (r.uniform(0.3, 0.7), r.uniform(0.3, 0.7))
    hot = [c]
    if r.random() < 0.5:
        h = tiny(r, -9, -1)
        pts = polygon(r, c, h, r.choice([3, 4, 5, 8]), irregular=r.random() < 0.5)
        inner = [B.v(p[0], p[1]) for p in pts]
        zipper(B, c, ring, inner)
        rad_lo = math.log10(h) - 0.5
    else:
        zc = 0.0 if r.random() < 0.6 else sgn(r) * tiny(r, -13, -6)
        ap = B.v(c[0], c[1], zc)
        nn = len(ring)
        miss = set()
        start = r.randrange(nn)
        for q in range(r.randint(1, 3)):
            miss.add((start + q) % nn)
        for q in range(nn):
            if q in miss:
                a, b = B.V[ring[q]], B.V[ring[(q + 1) % nn]]
                hot.append(((c[0] + a[0] + b[0]) / 3, (c[1] + a[1] + b[1]) / 3))
                continue
            B.f(ap, ring[q], ring[(q + 1) % nn])
        rad_lo = -3.0
    A = build_A(r, hot, rad_exp=(rad_lo, 0.0),
                shapes=['cone', 'cone', 'fan', 'tri', 'grid', 'needle_fan'])
    return A, B


def k_hole_layers(r):
    B = Mesh()
    n1, n2 = r.randint(2, 8), r.randint(2, 8)
    _, f1 = unit_grid(r, B, n1)
    d1 = r.choice(f1)[0]
    delta = 0.0 if r.random() < 0.4 else sgn(r) * tiny(r, -15, -6)
    base2 = len(B.F)
    _, f2 = quad_patch(B, (0, 0, delta), (1, 0, delta), (1, 1, delta), (0, 1, delta),
                       n2, n2, diag=r.choice(['a', 'b', 'alt']), r=r)
    c1 = centroid(B, d1)
    # choose a face of layer 2 near the hole of layer 1 (overlap) or a random one
    if r.random() < 0.6:
        d2 = min((f[0] for f in f2),
                 key=lambda fi: (centroid(B, fi)[0] - c1[0]) ** 2 + (centroid(B, fi)[1] - c1[1]) ** 2)
    else:
        d2 = r.choice(f2)[0]
    hot = [c1, centroid(B, d2)]
    remove_faces(B, [d1, d2])
    A = build_A(r, hot, rad_exp=(-2.0, 0.0))
    return A, B


def k_tjunction_quadtree(r):
    B = Mesh()
    vid = {}

    def V(x, y):
        key = (x, y)
        if key not in vid:
            vid[key] = B.v(x, y)
        return vid[key]

    leaves = []
    maxdepth = r.randint(2, 6)
    pr = r.uniform(0.3, 0.7)

    def rec(x0, y0, s, d):
        if d < maxdepth and (d == 0 or r.random() < pr) and len(leaves) < 120:
            h = s / 2
            for (dx, dy) in ((0, 0), (h, 0), (0, h), (h, h)):
                rec(x0 + dx, y0 + dy, h, d + 1)
        else:
            leaves.append((x0, y0, s))

    rec(0.0, 0.0, 1.0, 0)
    hot = []
    share = r.random() < 0.7
    for (x0, y0, s) in leaves:
        if share:
            a, b, c, d = V(x0, y0), V(x0 + s, y0), V(x0 + s, y0 + s), V(x0, y0 + s)
        else:
            a, b, c, d = B.v(x0, y0), B.v(x0 + s, y0), B.v(x0 + s, y0 + s), B.v(x0, y0 + s)
        u = r.random()
        if u < 0.45:
            B.f(a, b, c); B.f(a, c, d)
        elif u < 0.9:
            B.f(a, b, d); B.f(b, c, d)
        else:
            e = V(x0 + s / 2, y0 + s / 2) if share else B.v(x0 + s / 2, y0 + s / 2)
            B.f(a, b, e); B.f(b, c, e); B.f(c, d, e); B.f(d, a, e)
        if s < 0.5:
            hot.append((x0 + s, y0 + s / 2))
            hot.append((x0 + s / 2, y0))
    if not hot:
        hot = [(0.5, 0.5)]
    A = build_A(r, hot, rad_exp=(-3.0, 0.0))
    return A, B


def k_tjunction_offset(r):
    B = Mesh()
    xm = r.choice([0.5, r.uniform(0.2, 0.8)])
    nl = r.randint(1, 4)
    nr = r.randint(2, 20)
    # left patch: coarse, right patch: fine with hanging vertices on x = xm
    idxl, _ = quad_patch(B, (0, 0), (xm, 0), (xm, 1), (0, 1), r.randint(1, 4), nl,
                         diag=r.choice(['a', 'b']), r=r)
    us = [i / 3 for i in range(4)] if r.random() < 0.5 else [0.0, 1.0]
    right = Mesh()
    idxr, _ = quad_patch(right, (xm, 0), (1, 0), (1, 1), (xm, 1), 1, nr,
                         diag=r.choice(['a', 'b', 'alt']), r=r, us=us)
    mode = r.random()
    hot = []
    for j in range(1, nr):
        vi = idxr[0][j]
        x, y, z = right.V[vi]
        if j * nl % nr == 0:
            continue  # coincides with a left vertex (welded)
        if mode < 0.3:
            dx = 0.0
        else:
            dx = sgn(r) * tiny(r, -15, -6) if mode < 0.65 else tiny(r, -15, -6) * (1 if mode < 0.85 else -1)
        dz = 0.0 if r.random() < 0.6 else sgn(r) * tiny(r, -15, -7)
        right.V[vi] = (x + dx, y, z + dz)
        hot.append((xm, y))
    B.extend(right)
    if not hot:
        hot = [(xm, 0.5)]
    A = build_A(r, hot, rad_exp=(-4.0, -0.3))
    return A, B


def two_patches(r, gap=0.0, wedge=False, step=0.0, same_sub=False):
    B = Mesh()
    xm0 = r.uniform(0.3, 0.7)
    xm1 = xm0 if r.random() < 0.5 else r.uniform(0.3, 0.7)
    nyl = r.randint(1, 12)
    nyr = nyl if same_sub else r.randint(1, 12)
    quad_patch(B, (0, 0), (xm0, 0), (xm1, 1), (0, 1), r.randint(1, 6), nyl,
               diag=r.choice(['a', 'b', 'alt', 'rand']), r=r)
    g0 = 0.0 if wedge else gap
    g1 = gap
    quad_patch(B, (xm0 + g0, 0, step), (1, 0, step), (1, 1, step), (xm1 + g1, 1, step),
               r.randint(1, 6), nyr, diag=r.choice(['a', 'b', 'alt', 'rand']), r=r)
    hot = [(lerp(xm0, xm1, t), t) for t in (0.0, 0.25, 0.5, 0.75, 1.0, r.random())]
    return B, hot


def k_crack_dup(r):
    B, hot = two_patches(r, same_sub=r.random() < 0.4)
    A = build_A(r, hot, rad_exp=(-5.0, 0.0))
    return A, B


def k_crack_gap(r):
    g = tiny(r, -15, -6)
    step = 0.0 if r.random() < 0.6 else sgn(r) * tiny(r, -15, -6)
    B, hot = two_patches(r, gap=g, wedge=r.random() < 0.4, step=step,
                         same_sub=r.random() < 0.5)
    A = build_A(r, hot, rad_exp=(-6.0, 0.0))
    return A, B


def k_crack_overlap_step(r):
    g = -tiny(r, -15, -6)
    step = 0.0 if r.random() < 0.3 else sgn(r) * tiny(r, -15, -5)
    B, hot = two_patches(r, gap=g, wedge=r.random() < 0.3, step=step,
                         same_sub=r.random() < 0.5)
    A = build_A(r, hot, rad_exp=(-6.0, 0.0))
    return A, B


def some_triangulation(r, m, box, zf=None):
    """A triangulation of a box: grid, fan from an interior point, or a strip."""
    x0, y0, x1, y1 = box
    u = r.random()
    if u < 0.4:
        quad_patch(m, (x0, y0), (x1, y0), (x1, y1), (x0, y1), r.randint(1, 9), r.randint(1, 9),
                   zf=zf, diag=r.choice(['a', 'b', 'alt', 'rand']), r=r)
    elif u < 0.75:
        ts = perimeter_params(r, r.randint(4, 60), r.random() < 0.3)
        ring = []
        for t in ts:
            p = square_pt(t)
            x, y = lerp(x0, x1, p[0]), lerp(y0, y1, p[1])
            ring.append(m.v(x, y, zf(x, y) if zf else 0.0))
        c = (r.uniform(x0, x1), r.uniform(y0, y1))
        ap = m.v(c[0], c[1], zf(c[0], c[1]) if zf else 0.0)
        for q in range(len(ring)):
            m.f(ap, ring[q], ring[(q + 1) % len(ring)])
    else:
        nb, nt = r.randint(1, 40), r.randint(1, 40)
        xb = sorted(set([0.0, 1.0] + [r.random() for _ in range(nb)]))
        xt = sorted(set([0.0, 1.0] + [r.random() for _ in range(nt)]))
        bot = [m.v(lerp(x0, x1, t), y0, zf(lerp(x0, x1, t), y0) if zf else 0.0) for t in xb]
        top = [m.v(lerp(x0, x1, t), y1, zf(lerp(x0, x1, t), y1) if zf else 0.0) for t in xt]
        chain_strip(m, bot, top, r, mode=r.choice(['x', 'rand']))


def k_overlap_retri(r):
    B = Mesh()
    some_triangulation(r, B, (0.0, 0.0, 1.0, 1.0))
    u = r.random()
    if u < 0.4:
        box = (0.0, 0.0, 1.0, 1.0)
    else:
        xa, xb = sorted([r.random(), r.random()])
        ya, yb = sorted([r.random(), r.random()])
        box = (xa, ya, max(xb, xa + 0.05), max(yb, ya + 0.05))
    w = r.random()
    if w < 0.4:
        zf = None
    elif w < 0.7:
        d = sgn(r) * tiny(r, -15, -5)
        zf = lambda x, y: d
    else:
        g = sgn(r) * tiny(r, -12, -4)
        zf = lambda x, y: g * (x - box[0])
    some_triangulation(r, B, box, zf)
    hot = [((box[0] + box[2]) / 2, (box[1] + box[3]) / 2), (box[0], box[1]), (box[2], box[3])]
    A = build_A(r, hot, rad_exp=(-3.0, 0.0))
    return A, B


def k_fold_edge(r):
    B = Mesh()
    xf = r.uniform(0.4, 0.9)
    ny = r.randint(1, 10)
    idx, _ = quad_patch(B, (0, 0), (xf, 0), (xf, 1), (0, 1), r.randint(1, 6), ny,
                        diag=r.choice(['a', 'b', 'alt', 'rand']), r=r)
    w = r.uniform(0.05, xf)
    delta = 0.0 if r.random() < 0.35 else sgn(r) * tiny(r, -15, -4)
    nfx = r.randint(1, 5)
    # flap: columns from the fold edge (shared) back to x = xf - w at z = delta
    same_rows = r.random() < 0.6
    fny = ny if same_rows else r.randint(1, 10)
    cols = [[idx[-1][j] for j in range(ny + 1)]] if same_rows else None
    if not same_rows:
        # the flap has its own rows; fold edge vertices are new ones (crack + fold)
        cols = [[B.v(xf, j / fny, 0.0) for j in range(fny + 1)]]
    for i in range(1, nfx + 1):
        t = i / nfx
        x = xf - w * t
        cols.append([B.v(x, j / fny, delta * t) for j in range(fny + 1)])
    for i in range(nfx):
        for j in range(fny):
            a, b, c, d = cols[i][j], cols[i + 1][j], cols[i + 1][j + 1], cols[i][j + 1]
            if r.random() < 0.5:
                B.f(a, b, c); B.f(a, c, d)
            else:
                B.f(a, b, d); B.f(b, c, d)
    u = r.random()
    e = 0.0 if u < 0.25 else (tiny(r, -15, -3) if u < 0.8 else -tiny(r, -15, -3))
    ya, yb = sorted([r.uniform(0, 1), r.uniform(0, 1)])
    if r.random() < 0.4:
        ya, yb = 0.0, 1.0
    yb = max(yb, ya + 0.02)
    xa = r.uniform(xf - w, xf - 1e-3) if r.random() < 0.7 else r.uniform(0.0, xf - 1e-3)
    zf = make_zf(r, xf, (ya + yb) / 2)
    A = Mesh()
    s = r.random()
    if s < 0.5:
        quad_patch(A, (xa, ya), (xf + e, ya), (xf + e, yb), (xa, yb), r.randint(1, 6),
                   r.randint(1, 12), zf=zf, diag=r.choice(['a', 'b', 'alt']), r=r)
    elif s < 0.75:
        c = (xf + e, r.uniform(ya, yb))
        a_fan(r, A, c, r.uniform(0.01, 0.3), (xa, ya, xf + e, yb), zf)
    else:
        a_needles(r, A, (xf + e, r.uniform(ya, yb)), (xa, ya, xf + e, yb), zf,
                  fan=r.random() < 0.5)
    return A, B


def k_zfold(r):
    B = Mesh()
    a = r.uniform(0.5, 0.9)
    b = r.uniform(0.1, a - 0.05)
    ny = r.randint(1, 8)
    delta = 0.0 if r.random() < 0.35 else sgn(r) * tiny(r, -15, -4)
    diag = r.choice(['a', 'b', 'alt', 'rand'])
    idx1, _ = quad_patch(B, (0, 0, 0), (a, 0, 0), (a, 1, 0), (0, 1, 0), r.randint(1, 5), ny,
                         diag=diag, r=r)
    n2 = r.randint(1, 5)
    cols = [[idx1[-1][j] for j in range(ny + 1)]]
    for i in range(1, n2 + 1):
        t = i / n2
        cols.append([B.v(lerp(a, b, t), j / ny, delta * t) for j in range(ny + 1)])
    for i in range(n2):
        for j in range(ny):
            p, q, s, u = cols[i][j], cols[i + 1][j], cols[i + 1][j + 1], cols[i][j + 1]
            B.f(p, q, s); B.f(p, s, u)
    n3 = r.randint(1, 5)
    cols3 = [cols[-1]]
    for i in range(1, n3 + 1):
        x = lerp(b, 1.0, i / n3)
        cols3.append([B.v(x, j / ny, delta) for j in range(ny + 1)])
    for i in range(n3):
        for j in range(ny):
            p, q, s, u = cols3[i][j], cols3[i + 1][j], cols3[i + 1][j + 1], cols3[i][j + 1]
            B.f(p, q, u); B.f(q, s, u)
    hot = [(a, r.random()), (b, r.random()), (1.0, r.random()), (0.0, r.random())]
    u = r.random()
    out = 0.0 if u < 0.6 else tiny(r, -15, -3)
    A = build_A(r, hot, rad_exp=(-3.0, 0.2), out=out)
    return A, B


def k_dup_faces(r):
    B = Mesh()
    n = r.randint(2, 9)
    _, faces = unit_grid(r, B, n)
    fl = [f[0] for f in faces]
    nd = r.randint(1, max(1, len(fl) // 3))
    for fi in r.sample(fl, nd):
        a, b, c = B.F[fi]
        u = r.random()
        if u < 0.25:
            B.f(a, b, c)
        elif u < 0.5:
            B.f(a, c, b)
        elif u < 0.75:
            B.f(b, c, a)
        else:
            B.f(B.vp(B.V[a]), B.vp(B.V[b]), B.vp(B.V[c]))
    # fake adjacency: remove a triangle, double a neighbour (reversed)
    t = r.choice(fl)
    ta = set(B.F[t])
    nb = [fi for fi in fl if fi != t and len(ta & set(B.F[fi])) == 2]
    hot = [centroid(B, t)]
    if nb:
        for fi in r.sample(nb, r.randint(1, len(nb))):
            a, b, c = B.F[fi]
            B.f(c, b, a)
    tc = set(B.V[k] for k in ta)
    remove_faces(B, [q for q, f in enumerate(B.F) if set(B.V[k] for k in f) == tc])
    A = build_A(r, hot, rad_exp=(-2.5, 0.0))
    return A, B


def k_zero_area_rim(r):
    B = Mesh()
    n = r.randint(1, 8)
    idx, _ = unit_grid(r, B, n, ny=r.randint(1, 8))
    nx1 = len(idx) - 1
    # bottom boundary y = 0: zero-area triangles on edges
    bottom = [idx[i][0] for i in range(nx1 + 1)]
    for i in range(nx1):
        p, q = bottom[i], bottom[i + 1]
        u = r.random()
        if u < 0.35:
            x = lerp(B.V[p][0], B.V[q][0], r.random())
            B.f(q, p, B.v(x, 0.0))               # collinear point on the edge
        elif u < 0.6:
            x = B.V[q][0] + r.uniform(0.01, 0.3)
            B.f(q, p, B.v(x, 0.0))               # collinear point beyond the edge
        elif u < 0.75:
            B.f(q, p, B.vp(B.V[p]))              # coincident copy of a vertex
    # a few interior zero-area faces
    for _ in range(r.randint(0, 4)):
        i, j = r.randint(0, nx1 - 1), r.randint(0, len(idx[0]) - 1)
        p, q = idx[i][j], idx[i + 1][j]
        B.f(p, q, B.v(lerp(B.V[p][0], B.V[q][0], 0.5), B.V[p][1]))
    u = r.random()
    out = 0.0 if u < 0.35 else tiny(r, -15, -3)
    hot = [(r.random(), 0.0), (0.5, 0.0), (0.0, 0.0), (1.0, 0.0)]
    A = Mesh()
    xa, xb = sorted([r.uniform(-out, 1 + out), r.uniform(-out, 1 + out)])
    xb = max(xb, xa + 0.01)
    yb = tiny(r, -3, 0)
    zf = make_zf(r, 0.5, 0.0)
    s = r.random()
    if s < 0.5:
        quad_patch(A, (xa, -out), (xb, -out), (xb, yb), (xa, yb), r.randint(1, 8),
                   r.randint(1, 4), zf=zf, diag=r.choice(['a', 'b', 'alt']), r=r)
    elif s < 0.75:
        a_fan(r, A, (r.uniform(xa, xb), -out), r.uniform(0.01, 0.5), (xa, -out, xb, yb), zf)
    else:
        a_needles(r, A, (r.uniform(xa, xb), -out), (xa, -out, xb, yb), zf, fan=r.random() < 0.5)
    return A, B


def k_zero_area_fill(r):
    B = Mesh()
    n = r.randint(2, 9)
    _, faces = unit_grid(r, B, n)
    nrem = r.randint(1, 3)
    hot = []
    for fi, _, _, _ in r.sample(faces, nrem):
        a, b, c = B.F[fi]
        hot.append(centroid(B, fi))
        for (p, q) in ((a, b), (b, c), (c, a)):
            u = r.random()
            if u < 0.5:
                t = r.choice([0.5, r.random()])
                P, Q = B.V[p], B.V[q]
                mid = B.v(lerp(P[0], Q[0], t), lerp(P[1], Q[1], t), 0.0)
                B.f(p, q, mid)
            elif u < 0.75:
                B.f(p, q, B.vp(B.V[q]))
            else:
                B.f(q, p, B.vp(B.V[p]))
        B.F[fi] = None
    B.F = [f for f in B.F if f is not None]
    A = build_A(r, hot, rad_exp=(-2.5, 0.0))
    return A, B


def clustered_xs(r, n):
    xs = set([0.0, 1.0])
    while len(xs) < n:
        if r.random() < 0.4 and len(xs) > 2:
            x0 = r.choice(sorted(xs))
            x = x0 + sgn(r) * tiny(r, -13, -5)
            if 0.0 < x < 1.0:
                xs.add(x)
        else:
            xs.add(r.random())
    return sorted(xs)


def k_slivers_strip(r):
    B = Mesh()
    xb = clustered_xs(r, r.randint(3, 60))
    xt = clustered_xs(r, r.randint(2, 60))
    h = r.choice([1.0, tiny(r, -3, 0)])
    bot = [B.v(x, 0.0) for x in xb]
    top = [B.v(x, h) for x in xt]
    fl = chain_strip(B, bot, top, r, mode=r.choice(['x', 'x', 'rand']))
    hot = [(0.5, h / 2)]
    if r.random() < 0.5:
        # drop the thinnest triangle: a thin wedge hole
        def area(fi):
            a, b, c = [B.V[k] for k in B.F[fi]]
            return abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))
        thin = min(fl, key=area)
        hot = [centroid(B, thin)]
        a, b, c = B.F[thin]
        hot += [((B.V[a][0] + B.V[b][0]) / 2, (B.V[a][1] + B.V[b][1]) / 2)]
        remove_faces(B, [thin])
    A = build_A(r, hot, dom=(0.0, 0.0, 1.0, h), rad_exp=(-5.0, 0.0),
                shapes=['needles', 'needle_fan', 'grid', 'tri', 'fan'])
    return A, B


def k_fan_rim(r):
    B = Mesh()
    n = r.randint(20, 90)
    ts = perimeter_params(r, n, r.random() < 0.4)
    ta = r.choice([0.0, 0.0, r.uniform(0.0, 1.0), 1.0 + r.uniform(0.0, 1.0)])
    if ta in ts:
        ts.remove(ta)
    order = sorted([t for t in ts if t > ta]) + sorted([t for t in ts if t < ta])
    ap_p = square_pt(ta)
    lift = 0.0 if r.random() < 0.7 else sgn(r) * tiny(r, -13, -5)
    ap = B.v(ap_p[0], ap_p[1], lift)
    ring = [B.v(*square_pt(t)) for t in order]
    keep_deg = r.random() < 0.5
    miss = r.randrange(len(ring) - 1) if r.random() < 0.4 else -1
    hot = [ap_p]
    for q in range(len(ring) - 1):
        P, Q = B.V[ring[q]], B.V[ring[q + 1]]
        cr = (P[0] - ap_p[0]) * (Q[1] - ap_p[1]) - (Q[0] - ap_p[0]) * (P[1] - ap_p[1])
        if cr == 0.0 and not keep_deg:
            continue
        if q == miss:
            hot = [((ap_p[0] + P[0] + Q[0]) / 3, (ap_p[1] + P[1] + Q[1]) / 3), (P[0], P[1])]
            continue
        B.f(ap, ring[q], ring[q + 1])
    A = build_A(r, hot, rad_exp=(-4.0, 0.2),
                shapes=['needles', 'needle_fan', 'fan', 'cone', 'grid', 'tri'])
    return A, B


def k_fan_point(r):
    B = Mesh()
    n = r.randint(16, 90)
    _, ring = fan_ring(r, B, n, r.random() < 0.5)
    c = (r.uniform(0.1, 0.9), r.uniform(0.1, 0.9))
    if r.random() < 0.3:
        c = (0.5, 0.5)
    zc = 0.0 if r.random() < 0.6 else sgn(r) * tiny(r, -13, -4)
    ap = B.v(c[0], c[1], zc)
    nn = len(ring)
    miss = r.randrange(nn) if r.random() < 0.35 else -1
    hot = [c]
    for q in range(nn):
        if q == miss:
            P, Q = B.V[ring[q]], B.V[ring[(q + 1) % nn]]
            hot.append(((c[0] + P[0] + Q[0]) / 3, (c[1] + P[1] + Q[1]) / 3))
            continue
        B.f(ap, ring[q], ring[(q + 1) % nn])
    A = build_A(r, hot, rad_exp=(-4.0, 0.0),
                shapes=['cone', 'cone', 'fan', 'needle_fan', 'grid', 'tri', 'multi'])
    return A, B


def k_nonplanar_lift(r):
    B = Mesh()
    amp = tiny(r, -12, -4)
    p = r.uniform(0.2, 1.0)

    def zf(x, y):
        return sgn(r) * amp * r.random() if r.random() < p else 0.0
    if r.random() < 0.6:
        n = r.randint(2, 14)
        unit_grid(r, B, n, ny=r.randint(2, 14), zf=zf)
        hot = [(r.random(), r.random()) for _ in range(3)]
    else:
        _, ring = fan_ring(r, B, r.randint(8, 90), r.random() < 0.3)
        for k in ring:
            x, y, _ = B.V[k]
            B.V[k] = (x, y, zf(x, y))
        c = (r.uniform(0.2, 0.8), r.uniform(0.2, 0.8))
        ap = B.v(c[0], c[1], zf(*c))
        for q in range(len(ring)):
            B.f(ap, ring[q], ring[(q + 1) % len(ring)])
        hot = [c]
    A = build_A(r, hot, rad_exp=(-3.0, 0.0))
    return A, B


def rot_about_axis(p, c, axis, ang):
    # Rodrigues rotation of p about the line through c with unit direction axis
    x, y, z = p[0] - c[0], p[1] - c[1], p[2] - c[2]
    kx, ky, kz = axis
    co, si = math.cos(ang), math.sin(ang)
    dot = kx * x + ky * y + kz * z
    cx, cy, cz = ky * z - kz * y, kz * x - kx * z, kx * y - ky * x
    return (c[0] + x * co + cx * si + kx * dot * (1 - co),
            c[1] + y * co + cy * si + ky * dot * (1 - co),
            c[2] + z * co + cz * si + kz * dot * (1 - co))


def k_tilted_pieces(r):
    B = Mesh()
    kx, ky = r.randint(1, 4), r.randint(1, 4)
    hot = []
    for i in range(kx):
        for j in range(ky):
            piece = Mesh()
            x0, x1, y0, y1 = i / kx, (i + 1) / kx, j / ky, (j + 1) / ky
            quad_patch(piece, (x0, y0), (x1, y0), (x1, y1), (x0, y1), r.randint(1, 5),
                       r.randint(1, 5), diag=r.choice(['a', 'b', 'alt', 'rand']), r=r)
            if r.random() < 0.75:
                a = r.uniform(0.0, TWO_PI)
                axis = (math.cos(a), math.sin(a), 0.0)
                ang = sgn(r) * tiny(r, -10, -2)
                c = (r.uniform(x0, x1), r.uniform(y0, y1), 0.0)
                if r.random() < 0.3:
                    c = (x0, y0, 0.0)
                piece.V = [rot_about_axis(p, c, axis, ang) for p in piece.V]
            B.extend(piece)
            hot.append((x1, y1))
            hot.append((x0, (y0 + y1) / 2))
    A = build_A(r, hot, rad_exp=(-4.0, 0.0))
    return A, B


def k_steep_mix(r):
    B = Mesh()
    n = r.randint(2, 10)
    idx, faces = unit_grid(r, B, n)
    hot = []
    cell = 1.0 / n
    for _ in range(r.randint(1, 3)):
        u = r.random()
        i, j = r.randint(0, n), r.randint(0, n)
        vi = idx[i][j]
        x, y, z = B.V[vi]
        hot.append((x, y))
        if u < 0.6:
            L = cell * tiny(r, -3, 1) * sgn(r)
            B.V[vi] = (x, y, L)          # tent / spike
        else:
            # a vertical (or nearly vertical) fin standing on a grid edge
            i2 = min(n, i + 1)
            p, q = idx[i][j], idx[i2][j] if i2 != i else idx[i][min(n, j + 1)]
            if p == q:
                continue
            P, Q = B.V[p], B.V[q]
            hgt = cell * tiny(r, -3, 0)
            lean = r.choice([0.0, tiny(r, -8, -1)])
            B.f(p, q, B.v((P[0] + Q[0]) / 2 + lean * hgt, (P[1] + Q[1]) / 2 + lean * hgt, hgt))
    A = build_A(r, hot, rad_exp=(-3.0, 0.0))
    return A, B


def k_boundary_exact(r):
    B = Mesh()
    some_triangulation(r, B, (0.0, 0.0, 1.0, 1.0))
    u = r.random()
    if u < 0.4:
        box = [0.0, 0.0, 1.0, 1.0]
    else:
        box = [0.0, 0.0, r.uniform(0.1, 1.0), r.uniform(0.1, 1.0)]
        if r.random() < 0.5:
            box = [1.0 - box[2], 1.0 - box[3], 1.0, 1.0]
    out = 0.0 if r.random() < 0.4 else tiny(r, -15, -3)
    side = r.randrange(4)
    if out:
        if side == 0:
            box[0] -= out
        elif side == 1:
            box[1] -= out
        elif side == 2:
            box[2] += out
        else:
            box[3] += out
    dz = 0.0 if r.random() < 0.4 else None
    zf = make_zf(r, box[0], box[1], dz=dz) if dz is None else (lambda x, y: 0.0)
    A = Mesh()
    if r.random() < 0.7:
        some_triangulation(r, A, tuple(box), zf)
    else:
        c = (r.uniform(box[0], box[2]), r.uniform(box[1], box[3]))
        a_needles(r, A, c, tuple(box), zf, fan=r.random() < 0.5)
    return A, B


def holed_or_tj_B(r):
    u = r.random()
    if u < 0.4:
        _, B = k_hole_removed(r)
    elif u < 0.7:
        _, B = k_tjunction_quadtree(r)
    else:
        _, B = k_hole_poly(r)
    return B


def k_a_needles(r):
    B = holed_or_tj_B(r)
    hot = [(r.random(), r.random()) for _ in range(3)]
    # bias one hot point onto a face centroid of B
    hot.append(centroid(B, r.randrange(len(B.F))))
    A = build_A(r, hot, rad_exp=(-3.0, 0.0), shapes=['needles', 'needle_fan'])
    return A, B


def k_a_cone_over_fan(r):
    B = Mesh()
    _, ring = fan_ring(r, B, r.randint(8, 90), r.random() < 0.4)
    c = (r.uniform(0.2, 0.8), r.uniform(0.2, 0.8))
    ap = B.v(c[0], c[1], 0.0)
    for q in range(len(ring)):
        B.f(ap, ring[q], ring[(q + 1) % len(ring)])
    A = Mesh()
    cc = c if r.random() < 0.6 else (c[0] + sgn(r) * tiny(r, -12, -3), c[1] + sgn(r) * tiny(r, -12, -3))
    rad = tiny(r, -4, 0)
    zf = make_zf(r, cc[0], cc[1])
    lift = 0.0 if r.random() < 0.25 else sgn(r) * tiny(r, -15, -3)
    a_fan(r, A, cc, rad, (0.0, 0.0, 1.0, 1.0), zf, lift)
    return A, B


def k_a_coplanar_mix(r):
    B = Mesh()
    n = r.randint(2, 8)
    _, faces = unit_grid(r, B, n)
    fl = [f[0] for f in faces]
    hole = r.choice(fl)
    hc = centroid(B, hole)
    hole_tri = B.F[hole]
    A = Mesh()
    for fi in r.sample(fl, r.randint(1, len(fl))):
        if fi == hole:
            continue
        A.tri(*[B.V[k] for k in B.F[fi]])
    u = r.random()
    P = [B.V[k] for k in hole_tri]
    if u < 0.4:
        A.tri(*P)                                  # exactly coplanar over the hole
    elif u < 0.7:
        dz = sgn(r) * tiny(r, -15, -3)
        A.tri(*[(p[0], p[1], dz) for p in P])
    else:
        sub = build_A(r, [hc], rad_exp=(-3.0, -0.5))
        A.extend(sub)
    remove_faces(B, [hole])
    return A, B


def k_nonmanifold_book(r):
    B = Mesh()
    n = r.randint(2, 8)
    idx, faces = unit_grid(r, B, n)
    hot = []
    fl = [f[0] for f in faces]
    hole = r.choice(fl) if r.random() < 0.5 else None
    for _ in range(r.randint(1, 4)):
        i, j = r.randint(0, n - 1), r.randint(0, n)
        p, q = idx[i][j], idx[i + 1][j]
        P, Q = B.V[p], B.V[q]
        cell = 1.0 / n
        for _pg in range(r.randint(1, 4)):
            ang = sgn(r) * tiny(r, -12, -2)
            side = sgn(r)
            third = ((P[0] + Q[0]) / 2 + r.uniform(-0.5, 0.5) * cell, P[1] + side * cell * r.uniform(0.3, 1.5), 0.0)
            third = rot_about_axis(third, P, (1.0, 0.0, 0.0), ang)
            B.f(p, q, B.vp(third))
        hot.append(((P[0] + Q[0]) / 2, P[1]))
    if hole is not None:
        hc = centroid(B, hole)
        a, b, c = B.F[hole]
        # a page over the hole, hinged on one of its edges, nearly flat
        ang = sgn(r) * tiny(r, -12, -3)
        C = B.V[c]
        A_, B_ = B.V[a], B.V[b]
        ax = (B_[0] - A_[0], B_[1] - A_[1], 0.0)
        ln = math.hypot(ax[0], ax[1])
        ax = (ax[0] / ln, ax[1] / ln, 0.0)
        third = rot_about_axis(C, A_, ax, ang)
        if r.random() < 0.5:
            third = (third[0] + tiny(r, -13, -4), third[1], third[2])   # page slightly short
        B.f(a, b, B.vp(third))
        remove_faces(B, [hole])
        hot.append(hc)
    A = build_A(r, hot, rad_exp=(-3.0, 0.0))
    return A, B


def k_rim_sliver_out(r):
    B = Mesh()
    n = r.randint(1, 8)
    idx, _ = unit_grid(r, B, n, ny=r.randint(1, 8))
    nx1 = len(idx) - 1
    w = tiny(r, -13, -6)
    hot = []
    for i in range(nx1):
        if r.random() < 0.7:
            p, q = idx[i][0], idx[i + 1][0]
            P, Q = B.V[p], B.V[q]
            t = r.random()
            B.f(q, p, B.v(lerp(P[0], Q[0], t), -w * r.uniform(0.5, 1.0), 0.0))
            hot.append((lerp(P[0], Q[0], t), 0.0))
    if not hot:
        hot = [(0.5, 0.0)]
    out = w * r.choice([0.5, 1.0, 2.0, 10.0, r.uniform(0.0, 3.0)])
    A = Mesh()
    c = r.choice(hot)
    xa, xb = max(0.0, c[0] - tiny(r, -3, 0)), min(1.0, c[0] + tiny(r, -3, 0))
    yb = tiny(r, -4, 0)
    zf = make_zf(r, c[0], 0.0)
    s = r.random()
    if s < 0.5:
        quad_patch(A, (xa, -out), (xb, -out), (xb, yb), (xa, yb), r.randint(1, 10),
                   r.randint(1, 3), zf=zf, diag=r.choice(['a', 'b', 'alt']), r=r)
    elif s < 0.75:
        a_fan(r, A, (c[0], -out), yb, (xa, -out, xb, yb), zf)
    else:
        a_needles(r, A, (c[0], -out), (xa, -out, xb, yb), zf, fan=True)
    return A, B


def k_combo(r):
    B = Mesh()
    n = r.randint(3, 10)
    amp = tiny(r, -12, -5) if r.random() < 0.5 else 0.0
    zf = (lambda x, y: amp * r.uniform(-1, 1)) if amp else None
    idx, faces = unit_grid(r, B, n, zf=zf)
    fl = [f[0] for f in faces]
    hot = []
    # hole
    hole = r.choice(fl)
    hot.append(centroid(B, hole))
    # T-junction: split one triangle's edge on one side only
    tj = r.choice(fl)
    if tj != hole:
        a, b, c = B.F[tj]
        P, Q = B.V[a], B.V[b]
        t = r.uniform(0.2, 0.8)
        mv = B.v(lerp(P[0], Q[0], t), lerp(P[1], Q[1], t), 0.0)
        B.F[tj] = (a, mv, c)
        B.f(mv, b, c)
        hot.append((lerp(P[0], Q[0], t), lerp(P[1], Q[1], t)))
    # duplicates
    for fi in r.sample(fl, min(len(fl), r.randint(0, 5))):
        if fi != hole:
            a, b, c = B.F[fi]
            B.f(a, c, b)
    remove_faces(B, [hole])
    A = build_A(r, hot, rad_exp=(-3.0, 0.0))
    return A, B


KINDS = [
    ('hole_poly', k_hole_poly),
    ('hole_removed', k_hole_removed),
    ('hole_fan_center', k_hole_fan_center),
    ('hole_layers', k_hole_layers),
    ('tjunction_quadtree', k_tjunction_quadtree),
    ('tjunction_offset', k_tjunction_offset),
    ('crack_dup', k_crack_dup),
    ('crack_gap', k_crack_gap),
    ('crack_overlap_step', k_crack_overlap_step),
    ('overlap_retri', k_overlap_retri),
    ('fold_edge', k_fold_edge),
    ('zfold', k_zfold),
    ('dup_faces', k_dup_faces),
    ('zero_area_rim', k_zero_area_rim),
    ('zero_area_fill', k_zero_area_fill),
    ('slivers_strip', k_slivers_strip),
    ('fan_rim', k_fan_rim),
    ('fan_point', k_fan_point),
    ('nonplanar_lift', k_nonplanar_lift),
    ('tilted_pieces', k_tilted_pieces),
    ('steep_mix', k_steep_mix),
    ('boundary_exact', k_boundary_exact),
    ('a_needles', k_a_needles),
    ('a_cone_over_fan', k_a_cone_over_fan),
    ('a_coplanar_mix', k_a_coplanar_mix),
    ('nonmanifold_book', k_nonmanifold_book),
    ('rim_sliver_out', k_rim_sliver_out),
    ('combo', k_combo),
]


# ----------------------------------------------------------------------------
# transform, post-processing, output
# ----------------------------------------------------------------------------

def random_rotation(r):
    u = r.random()
    if u < 0.25:
        # exact axis permutation with signs
        perm = [0, 1, 2]
        r.shuffle(perm)
        sg = [sgn(r) for _ in range(3)]
        R = [[0.0] * 3 for _ in range(3)]
        for i in range(3):
            R[i][perm[i]] = sg[i]
        return R
    if u < 0.4:
        # tiny rotation
        a = tiny(r, -12, -3)
        axis = [r.gauss(0, 1) for _ in range(3)]
        ln = math.sqrt(sum(t * t for t in axis)) or 1.0
        axis = [t / ln for t in axis]
        w, s = math.cos(a / 2), math.sin(a / 2)
        q = (w, axis[0] * s, axis[1] * s, axis[2] * s)
    else:
        q = [r.gauss(0, 1) for _ in range(4)]
        ln = math.sqrt(sum(t * t for t in q)) or 1.0
        q = [t / ln for t in q]
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def random_transform(r):
    u = r.random()
    if u < 0.25:
        return None
    R = random_rotation(r)
    if u < 0.4:
        s, t = 1.0, (0.0, 0.0, 0.0)
    else:
        s = 10 ** r.uniform(-6, 6)
        if r.random() < 0.3:
            s = 2.0 ** r.randint(-20, 20)
        v = r.random()
        if v < 0.2:
            mag = 0.0
        else:
            mag = s * 10 ** r.uniform(-1, 8)
        d = [r.gauss(0, 1) for _ in range(3)]
        ln = math.sqrt(sum(c * c for c in d)) or 1.0
        t = tuple(mag * c / ln for c in d)
    return (R, s, t)


def apply_transform(m, T):
    if T is None:
        return
    R, s, t = T
    out = []
    for (x, y, z) in m.V:
        out.append((s * (R[0][0] * x + R[0][1] * y + R[0][2] * z) + t[0],
                    s * (R[1][0] * x + R[1][1] * y + R[1][2] * z) + t[1],
                    s * (R[2][0] * x + R[2][1] * y + R[2][2] * z) + t[2]))
    m.V = out


def finalize(r, m):
    """Drop unused vertices; sometimes shuffle vertex / face order, rotate or
    flip index order."""
    used = sorted(set(k for f in m.F for k in f))
    if r.random() < 0.4:
        r.shuffle(used)
    remap = {old: new for new, old in enumerate(used)}
    m.V = [m.V[k] for k in used]
    F = [tuple(remap[k] for k in f) for f in m.F]
    u = r.random()
    if u < 0.3:
        r.shuffle(F)
    elif u < 0.4:
        F.reverse()
    if r.random() < 0.3:
        F = [f[1:] + f[:1] if r.random() < 0.5 else f for f in F]
    if r.random() < 0.2:
        F = [(f[0], f[2], f[1]) if r.random() < 0.5 else f for f in F]
    m.F = F


def write_obj(path, m):
    n = len(m.V)
    lines = []
    for (x, y, z) in m.V:
        lines.append('v %.17g %.17g %.17g' % (x, y, z))
    for (a, b, c) in m.F:
        assert 0 <= a < n and 0 <= b < n and 0 <= c < n
        lines.append('f %d %d %d' % (a + 1, b + 1, c + 1))
    with open(path, 'w') as fh:
        fh.write('\n'.join(lines) + '\n')


def make_pair(s):
    r = random.Random(s)
    name, fn = KINDS[s % len(KINDS)]
    A, B = fn(r)
    if not A.F:
        A.tri((0.25, 0.25, 1e-6), (0.75, 0.25, 1e-6), (0.5, 0.75, 1e-6))
    if not B.F:
        B.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    T = random_transform(r)
    apply_transform(A, T)
    apply_transform(B, T)
    finalize(r, A)
    finalize(r, B)
    return name, A, B


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: generate_pairs11.py OUTDIR SEED_FROM SEED_TO\n')
        return 2
    outdir, s0, s1 = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    for s in range(s0, s1):
        name, A, B = make_pair(s)
        write_obj(os.path.join(outdir, '%06d_%s_a.obj' % (s, name)), A)
        write_obj(os.path.join(outdir, '%06d_%s_b.obj' % (s, name)), B)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
