#!/usr/bin/env python3
"""Generator of degenerate / near-degenerate triangle-mesh pairs for the exact
Hausdorff distance tool.

Written blind (independently of the other generators and of the
implementation).  Standard library only, deterministic per seed.

Usage:
    python3 generate_pairs12.py OUTDIR FROM TO

For every integer seed s in [FROM, TO) it writes
    OUTDIR/NNNNNN_KIND_a.obj  and  OUTDIR/NNNNNN_KIND_b.obj
where NNNNNN is the zero-padded seed and KIND = KINDS[s % len(KINDS)].
All other choices come from random.Random(s).

Kinds whose name ends in "_far" are pairs of nearly coincident meshes placed
1e4..1e8 times their size away from the origin; no other kind uses that
suffix.
"""

import math
import os
import random
import struct
import sys

MAX_TRIS = 300


# --------------------------------------------------------------------------
# small vector helpers (tuples of 3 floats)
# --------------------------------------------------------------------------

def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    if n == 0.0 or not math.isfinite(n):
        return (1.0, 0.0, 0.0)
    return (a[0] / n, a[1] / n, a[2] / n)


def lerp(a, b, t):
    """a + (b - a) t; exactly a for t == 0 (use the endpoint itself for t == 1)."""
    if t == 1.0:
        return b
    return (a[0] + (b[0] - a[0]) * t,
            a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t)


def mid(a, b):
    return ((a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5, (a[2] + b[2]) * 0.5)


def centroid(pts):
    n = float(len(pts))
    return (sum(p[0] for p in pts) / n,
            sum(p[1] for p in pts) / n,
            sum(p[2] for p in pts) / n)


def rand_unit(rng):
    while True:
        g = (rng.gauss(0.0, 1.0), rng.gauss(0.0, 1.0), rng.gauss(0.0, 1.0))
        n = norm(g)
        if n > 1e-6:
            return mul(g, 1.0 / n)


def perp_frame(n):
    """Two unit vectors u, v with (u, v, n) orthonormal."""
    n = unit(n)
    a = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = unit(cross(n, a))
    v = cross(n, u)
    return u, v


def matvec(m, p):
    return (m[0][0] * p[0] + m[0][1] * p[1] + m[0][2] * p[2],
            m[1][0] * p[0] + m[1][1] * p[1] + m[1][2] * p[2],
            m[2][0] * p[0] + m[2][1] * p[1] + m[2][2] * p[2])


def rot_axis_angle(axis, ang):
    """Rodrigues rotation matrix, accurate for tiny angles (uses 2 sin^2(a/2))."""
    x, y, z = unit(axis)
    s = math.sin(ang)
    c1 = 2.0 * math.sin(0.5 * ang) ** 2          # 1 - cos(ang)
    return ((1.0 - c1 * (y * y + z * z), -s * z + c1 * x * y, s * y + c1 * x * z),
            (s * z + c1 * x * y, 1.0 - c1 * (x * x + z * z), -s * x + c1 * y * z),
            (-s * y + c1 * x * z, s * x + c1 * y * z, 1.0 - c1 * (x * x + y * y)))


def rand_rotation(rng):
    """Uniformly random rotation (from a random unit quaternion)."""
    while True:
        q = [rng.gauss(0.0, 1.0) for _ in range(4)]
        n = math.sqrt(sum(c * c for c in q))
        if n > 1e-6:
            break
    w, x, y, z = (c / n for c in q)
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)),
            (2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)),
            (2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)))


def rand_signed_perm(rng):
    """Random signed permutation matrix: an exact (rounding-free) rotation/reflection."""
    perm = [0, 1, 2]
    rng.shuffle(perm)
    m = [[0.0, 0.0, 0.0] for _ in range(3)]
    for i in range(3):
        m[i][perm[i]] = rng.choice((-1.0, 1.0))
    return tuple(tuple(r) for r in m)


def rotate_about(p, c, m):
    return add(c, matvec(m, sub(p, c)))


# --------------------------------------------------------------------------
# floating point helpers
# --------------------------------------------------------------------------

def next_float(x, up):
    """The neighbouring double of x towards +inf (up) or -inf."""
    if x != x or math.isinf(x):
        return x
    if x == 0.0:
        return 5e-324 if up else -5e-324
    bits = struct.unpack('<q', struct.pack('<d', x))[0]
    bits += 1 if (x > 0.0) == up else -1
    return struct.unpack('<d', struct.pack('<q', bits))[0]


def ulp_move(x, k):
    """Move x by k ulps (k may be negative).  Zero is left alone (no subnormals)."""
    if x == 0.0:
        return x
    for _ in range(abs(k)):
        x = next_float(x, k > 0)
    return x


def to_f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


# --------------------------------------------------------------------------
# mesh container and generic shapes
# --------------------------------------------------------------------------

class Mesh(object):
    def __init__(self, verts=None, faces=None):
        self.v = list(verts) if verts else []
        self.f = list(faces) if faces else []

    def vert(self, p):
        self.v.append((float(p[0]), float(p[1]), float(p[2])))
        return len(self.v) - 1

    def face(self, i, j, k):
        self.f.append((i, j, k))

    def tri(self, a, b, c):
        self.face(self.vert(a), self.vert(b), self.vert(c))

    def append(self, other):
        off = len(self.v)
        self.v.extend(other.v)
        self.f.extend((i + off, j + off, k + off) for (i, j, k) in other.f)
        return self

    def copy(self):
        return Mesh(self.v, self.f)

    def mapped(self, fn):
        return Mesh([tuple(float(c) for c in fn(p)) for p in self.v], self.f)

    def quad(self, a, b, c, d, diag_ac=True):
        """Quad a,b,c,d (index form), split along a-c or along b-d."""
        if diag_ac:
            self.face(a, b, c)
            self.face(a, c, d)
        else:
            self.face(a, b, d)
            self.face(b, c, d)


def merge(*meshes):
    m = Mesh()
    for x in meshes:
        m.append(x)
    return m


def weld(mesh):
    """Merge vertices with bit-identical coordinates (what a seam welder does)."""
    index = {}
    out = Mesh()
    remap = []
    for p in mesh.v:
        if p not in index:
            index[p] = out.vert(p)
        remap.append(index[p])
    out.f = [(remap[i], remap[j], remap[k]) for (i, j, k) in mesh.f]
    return out


def rand_diag(rng):
    """A function (i, j) -> bool choosing the diagonal of quad (i, j)."""
    mode = rng.choice(['ac', 'bd', 'checker', 'random'])
    bits = [rng.random() < 0.5 for _ in range(97)]
    if mode == 'ac':
        return lambda i, j: True
    if mode == 'bd':
        return lambda i, j: False
    if mode == 'checker':
        return lambda i, j: (i + j) % 2 == 0
    return lambda i, j: bits[(i * 31 + j * 7) % 97]


def grid_mesh(nx, ny, x0=0.0, y0=0.0, w=1.0, h=1.0, zf=None, diag=None):
    """(nx x ny)-quad height field over [x0, x0+w] x [y0, y0+h]; vertex (i, j) has index j*(nx+1)+i."""
    m = Mesh()
    for j in range(ny + 1):
        for i in range(nx + 1):
            x = x0 + w * i / nx
            y = y0 + h * j / ny
            z = zf(i, j, x, y) if zf else 0.0
            m.vert((x, y, z))

    def vid(i, j):
        return j * (nx + 1) + i
    for j in range(ny):
        for i in range(nx):
            m.quad(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1),
                   True if diag is None else diag(i, j))
    return m


def regular_polygon(n, r=1.0, phase=0.0, z=0.0):
    """Regular n-gon, made exactly mirror-symmetric about the x axis when phase == 0."""
    pts = []
    for k in range(n):
        a = phase + 2.0 * math.pi * k / n
        c, s = math.cos(a), math.sin(a)
        if abs(c) < 1e-15:
            c = 0.0
        if abs(s) < 1e-15:
            s = 0.0
        pts.append([r * c, r * s, z])
    if phase == 0.0:
        for k in range(1, n):
            if 2 * k > n:
                pts[k][0] = pts[n - k][0]
                pts[k][1] = -pts[n - k][1]
    return [tuple(p) for p in pts]


def random_convex_polygon(rng, n, rx=1.0, ry=1.0):
    angs = sorted(rng.uniform(0.0, 2.0 * math.pi) for _ in range(n))
    return [(rx * math.cos(a), ry * math.sin(a), 0.0) for a in angs]


def polygon_mesh(poly, method, rng, k=None):
    """Triangulate a convex polygon: 'fan' from vertex k, 'strip' (zig-zag), or 'centroid' fan."""
    m = Mesh()
    idx = [m.vert(p) for p in poly]
    n = len(idx)
    if k is None:
        k = rng.randrange(n)
    if method == 'fan':
        for i in range(1, n - 1):
            m.face(idx[k], idx[(k + i) % n], idx[(k + i + 1) % n])
    elif method == 'strip':
        r = idx[k:] + idx[:k]
        lo, hi = 0, n - 1
        left = True
        while hi - lo >= 2:
            if left:
                m.face(r[lo], r[lo + 1], r[hi])
                lo += 1
            else:
                m.face(r[lo], r[hi - 1], r[hi])
                hi -= 1
            left = not left
    else:  # centroid
        c = m.vert(centroid(poly))
        for i in range(n):
            m.face(c, idx[i], idx[(i + 1) % n])
    return m


def icosahedron(r=1.0):
    t = (1.0 + math.sqrt(5.0)) / 2.0
    vs = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
          (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    fs = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9),
          (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2),
          (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
          (8, 6, 7), (9, 8, 1)]
    return Mesh([mul(unit(v), r) for v in vs], fs)


def icosphere(sub_levels, r=1.0):
    m = icosahedron(r)
    for _ in range(sub_levels):
        m = subdivide_1to4(m, project_radius=r)
    return m


def uv_sphere(nu, nv, r=1.0, phase=0.0):
    m = Mesh()
    top = m.vert((0.0, 0.0, r))
    rings = []
    for k in range(1, nv):
        th = math.pi * k / nv
        rings.append([m.vert((r * math.sin(th) * math.cos(phase + 2 * math.pi * i / nu),
                              r * math.sin(th) * math.sin(phase + 2 * math.pi * i / nu),
                              r * math.cos(th))) for i in range(nu)])
    bot = m.vert((0.0, 0.0, -r))
    for i in range(nu):
        m.face(top, rings[0][i], rings[0][(i + 1) % nu])
    for a, b in zip(rings, rings[1:]):
        for i in range(nu):
            m.quad(a[i], b[i], b[(i + 1) % nu], a[(i + 1) % nu])
    for i in range(nu):
        m.face(bot, rings[-1][(i + 1) % nu], rings[-1][i])
    return m


def cylinder(n, segs, r=1.0, h=2.0, phase=0.0, caps=True):
    m = Mesh()
    rings = []
    for s in range(segs + 1):
        z = -h / 2 + h * s / segs
        rings.append([m.vert((r * math.cos(phase + 2 * math.pi * i / n),
                              r * math.sin(phase + 2 * math.pi * i / n), z)) for i in range(n)])
    for a, b in zip(rings, rings[1:]):
        for i in range(n):
            m.quad(a[i], a[(i + 1) % n], b[(i + 1) % n], b[i])
    if caps:
        for i in range(1, n - 1):
            m.face(rings[0][0], rings[0][i + 1], rings[0][i])
            m.face(rings[-1][0], rings[-1][i], rings[-1][i + 1])
    return m


def box_mesh(lo, hi, rng=None):
    """Axis-aligned box, 12 outward-oriented triangles, random diagonals if rng given."""
    m = Mesh()
    c = [m.vert((hi[0] if b & 1 else lo[0], hi[1] if b & 2 else lo[1], hi[2] if b & 4 else lo[2]))
         for b in range(8)]
    for q in ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)):
        m.quad(c[q[0]], c[q[1]], c[q[2]], c[q[3]], rng.random() < 0.5 if rng else True)
    return m


def subdivide_1to4(mesh, project_radius=None):
    m = Mesh(mesh.v, [])
    cache = {}

    def midpoint(i, j):
        key = (min(i, j), max(i, j))
        if key not in cache:
            p = mid(m.v[i], m.v[j])
            if project_radius is not None:
                p = mul(unit(p), project_radius)
            cache[key] = m.vert(p)
        return cache[key]
    for (a, b, c) in mesh.f:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        m.f += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return m


def subdivide_centroid(mesh):
    m = Mesh(mesh.v, [])
    for (a, b, c) in mesh.f:
        g = m.vert(centroid([m.v[a], m.v[b], m.v[c]]))
        m.f += [(a, b, g), (b, c, g), (c, a, g)]
    return m


def bisect_longest(mesh, rng, prob=0.5):
    """Split some faces at the midpoint of their longest edge (creates T-junctions)."""
    m = Mesh(mesh.v, [])
    for f in mesh.f:
        if rng.random() >= prob:
            m.f.append(f)
            continue
        a, b, c = f
        lens = [norm(sub(m.v[b], m.v[a])), norm(sub(m.v[c], m.v[b])), norm(sub(m.v[a], m.v[c]))]
        k = lens.index(max(lens))
        a, b, c = (f[k], f[(k + 1) % 3], f[(k + 2) % 3])
        g = m.vert(mid(m.v[a], m.v[b]))
        m.f += [(a, g, c), (g, b, c)]
    return m


def vertex_normals(mesh):
    acc = [(0.0, 0.0, 0.0)] * len(mesh.v)
    for (a, b, c) in mesh.f:
        n = cross(sub(mesh.v[b], mesh.v[a]), sub(mesh.v[c], mesh.v[a]))
        for i in (a, b, c):
            acc[i] = add(acc[i], n)
    return [unit(n) if norm(n) > 0 else (0.0, 0.0, 1.0) for n in acc]


def base_surface(rng, max_tris=80):
    """A small generic 'part' of size about 1 (height field, sphere, box, soup or planar fan)."""
    opts = ['grid', 'ico', 'uv', 'box', 'soup', 'fan']
    c = rng.choice(opts)
    if c == 'grid':
        nx, ny = rng.randint(1, 6), rng.randint(1, 6)
        amp = 10 ** rng.uniform(-3, 0)
        fx, fy = rng.uniform(0.5, 4), rng.uniform(0.5, 4)
        return grid_mesh(nx, ny, -1.0, -1.0, 2.0, 2.0,
                         lambda i, j, x, y: amp * math.sin(fx * x) * math.cos(fy * y),
                         rand_diag(rng))
    if c == 'ico':
        return icosphere(1 if (max_tris >= 80 and rng.random() < 0.5) else 0, 1.0)
    if c == 'uv':
        return uv_sphere(rng.randint(3, 8), rng.randint(2, 5), 1.0)
    if c == 'box':
        return box_mesh((-rng.uniform(0.1, 1), -rng.uniform(0.1, 1), -rng.uniform(0.1, 1)),
                        (rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1)), rng)
    if c == 'soup':
        m = Mesh()
        for _ in range(rng.randint(1, 20)):
            m.tri(*[tuple(rng.uniform(-1, 1) for _ in range(3)) for _ in range(3)])
        return m
    n = rng.randint(3, 30)
    return polygon_mesh(random_convex_polygon(rng, n, 1.0, 10 ** rng.uniform(-2, 0)),
                        rng.choice(['fan', 'strip', 'centroid']), rng)


def base_plane(rng):
    """A few large triangles in the plane z = 0 spanning about [-1, 1]^2."""
    c = rng.choice(['square', 'triangle', 'fan', 'grid'])
    if c == 'square':
        m = Mesh([(-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (1.0, 1.0, 0.0), (-1.0, 1.0, 0.0)])
        m.quad(0, 1, 2, 3, rng.random() < 0.5)
        return m
    if c == 'triangle':
        m = Mesh()
        m.tri((rng.uniform(-1.5, -0.5), rng.uniform(-1.5, -0.5), 0.0),
              (rng.uniform(0.5, 1.5), rng.uniform(-1.5, 0.0), 0.0),
              (rng.uniform(-1.0, 1.0), rng.uniform(0.5, 1.5), 0.0))
        return m
    if c == 'fan':
        return polygon_mesh(regular_polygon(rng.randint(3, 8), 1.2), 'centroid', rng)
    n = rng.randint(1, 4)
    return grid_mesh(n, n, -1.0, -1.0, 2.0, 2.0, None, rand_diag(rng))


def make_sliver(rng, p, q, w, u, style):
    """Thin triangle with long edge p-q and height about w in direction u."""
    if style == 'cap':          # third vertex just beside the middle of p-q
        return (p, q, add(lerp(p, q, rng.uniform(0.05, 0.95)), mul(u, w)))
    if style == 'needle':       # two vertices very close together at one end
        return (p, q, add(q, mul(u, w)))
    # 'spike': third vertex on the segment itself, very close to q: collinear
    return (p, q, lerp(p, q, 1.0 - 10 ** -rng.uniform(3, 14)))


def rand_scale(rng):
    r = rng.random()
    if r < 0.2:
        return 1.0
    if r < 0.4:
        return 2.0 ** rng.randint(-20, 20)
    return 10.0 ** rng.uniform(-6, 6)


def place(rng, meshes, exact_bias=0.3):
    """Apply one common similarity transform to all meshes.

    With probability exact_bias the transform is rounding-free (signed
    permutation, power-of-two scale, no translation) so exact ties survive."""
    if rng.random() < exact_bias:
        m = rand_signed_perm(rng)
        s = 2.0 ** rng.randint(-20, 20) if rng.random() < 0.7 else 1.0
        t = (0.0, 0.0, 0.0)
    else:
        m = rand_rotation(rng) if rng.random() < 0.75 else rand_signed_perm(rng)
        s = rand_scale(rng)
        t = (0.0, 0.0, 0.0)
        if rng.random() < 0.5:
            t = mul(rand_unit(rng), s * 10 ** rng.uniform(-1, 3))

    def fn(p):
        return add(mul(matvec(m, p), s), t)
    return tuple(x.mapped(fn) for x in meshes)


def maybe_swap(rng, a, b):
    return (b, a) if rng.random() < 0.5 else (a, b)


def far_transform(rng, meshes):
    """Similarity placing the given meshes so that their largest coordinate is
    1e4..1e8 times the diameter of their union (only the meshes' own geometry
    is used to measure that, nothing else is moved)."""
    size = 10 ** rng.uniform(-3, 3)
    m = rand_rotation(rng) if rng.random() < 0.6 else rand_signed_perm(rng)
    pts = [mul(matvec(m, p), size) for x in meshes for p in x.v]
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    diam = norm(sub(tuple(hi), tuple(lo)))
    if rng.random() < 0.6:
        d = rand_unit(rng)
    else:
        d = [0.0, 0.0, 0.0]
        d[rng.randrange(3)] = rng.choice((-1.0, 1.0))
        d = tuple(d)
    ratio = 10 ** rng.uniform(4.15, 7.85)
    off = mul(d, ratio * diam / max(abs(c) for c in d))

    def fn(p):
        return add(mul(matvec(m, p), size), off)
    return fn


# --------------------------------------------------------------------------
# kinds: coplanar overlapping triangulations
# --------------------------------------------------------------------------

def k_coplanar_fan_strip(rng):
    """CAD tessellators triangulate the same planar face as a fan, a strip, or around a Steiner point."""
    n = rng.randint(3, 60)
    if rng.random() < 0.5:
        poly = regular_polygon(n, 1.0, 0.0 if rng.random() < 0.5 else rng.uniform(0, 2 * math.pi))
    else:
        poly = random_convex_polygon(rng, n, 1.0, 10 ** rng.uniform(-4, 0))
    A = polygon_mesh(poly, rng.choice(['fan', 'strip']), rng)
    mb = rng.choice(['fan', 'strip', 'centroid', 'edge_point'])
    if mb == 'edge_point':
        # extra vertex on a boundary edge: a T-junction-like vertex on A's edge
        e = rng.randrange(n)
        t = rng.choice([0.5, 0.25, rng.uniform(0.01, 0.99)])
        p = lerp(poly[e], poly[(e + 1) % n], t)
        B = polygon_mesh(poly[:e + 1] + [p] + poly[e + 1:], 'fan', rng, k=e + 1)
    else:
        B = polygon_mesh(poly, mb, rng)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.5)


def k_coplanar_tjunction(rng):
    """Rectangle meshed uniformly in A, and as two differently refined blocks with T-junctions in B."""
    H = 10 ** rng.uniform(-3, 0.5)
    xm = rng.choice([0.5, 1.0 / 3.0, 0.1, rng.uniform(0.05, 0.95)])
    A = grid_mesh(rng.randint(1, 8), rng.randint(1, 8), 0.0, 0.0, 1.0, H, None, rand_diag(rng))
    n1 = rng.randint(1, 7)
    n2 = rng.randint(1, 7)
    if n2 == n1:
        n2 += 1
    left = grid_mesh(rng.randint(1, 6), n1, 0.0, 0.0, xm, H, None, rand_diag(rng))
    right = grid_mesh(rng.randint(1, 6), n2, xm, 0.0, 1.0 - xm, H, None, rand_diag(rng))
    B = merge(left, right)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.5)


def k_quad_diagonal_flip(rng):
    """A quad-dominant mesh (planar or warped quads) split along different diagonals by two exporters."""
    nx, ny = rng.randint(1, 9), rng.randint(1, 9)
    amp = 0.0 if rng.random() < 0.25 else 10 ** rng.uniform(-14, 0)
    style = rng.choice(['random', 'saddle', 'wave'])
    heights = {}
    for j in range(ny + 1):
        for i in range(nx + 1):
            heights[i, j] = amp * rng.uniform(-1, 1)
    if style == 'random':
        zf = lambda i, j, x, y: heights[i, j]
    elif style == 'saddle':
        zf = lambda i, j, x, y: amp * 4.0 * (x - 0.5) * (y - 0.5)
    else:
        zf = lambda i, j, x, y: amp * math.sin(3.0 * x) * math.cos(2.0 * y)
    aspect = 10 ** rng.uniform(-2, 0)
    A = grid_mesh(nx, ny, 0.0, 0.0, 1.0, aspect, zf, lambda i, j: True)
    bmode = rng.choice(['flip', 'checker', 'random'])
    bits = [rng.random() < 0.5 for _ in range(97)]
    if bmode == 'flip':
        db = lambda i, j: False
    elif bmode == 'checker':
        db = lambda i, j: (i + j) % 2 == 1
    else:
        db = lambda i, j: bits[(i * 31 + j * 7) % 97]
    B = grid_mesh(nx, ny, 0.0, 0.0, 1.0, aspect, zf, db)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_coplanar_partial_overlap(rng):
    """Two faces of one plane from different parts / patches that overlap, nest or abut along an edge."""
    nA = rng.randint(3, 30)
    polyA = random_convex_polygon(rng, nA, 1.0, 10 ** rng.uniform(-1, 0))
    mode = rng.choice(['shifted', 'rotated', 'mirrored_edge', 'nested'])
    if mode == 'shifted':
        dx, dy = rng.uniform(-1, 1), rng.uniform(-1, 1)
        polyB = [(p[0] + dx, p[1] + dy, 0.0)
                 for p in random_convex_polygon(rng, rng.randint(3, 30), rng.uniform(0.3, 1.5),
                                                rng.uniform(0.3, 1.5))]
    elif mode == 'rotated':
        c = polyA[rng.randrange(nA)]
        ang = rng.choice([math.pi / 2, math.pi / 3, math.pi, 10 ** -rng.uniform(1, 10)])
        ca, sa = math.cos(ang), math.sin(ang)
        polyB = [(c[0] + ca * (p[0] - c[0]) - sa * (p[1] - c[1]),
                  c[1] + sa * (p[0] - c[0]) + ca * (p[1] - c[1]), 0.0) for p in polyA]
    elif mode == 'mirrored_edge':
        e = rng.randrange(nA)
        p, q = polyA[e], polyA[(e + 1) % nA]
        d = unit(sub(q, p))
        nrm = (-d[1], d[0], 0.0)
        polyB = []
        for x in polyA:
            s = dot(sub(x, p), nrm)
            polyB.append((x[0] - 2 * s * nrm[0], x[1] - 2 * s * nrm[1], 0.0))
        polyB[e], polyB[(e + 1) % nA] = p, q     # keep the shared edge bit-identical
        polyB.reverse()
    else:
        g = centroid(polyA)
        f = 10 ** -rng.uniform(0.01, 6)
        polyB = [(g[0] + f * (p[0] - g[0]), g[1] + f * (p[1] - g[1]), 0.0) for p in polyA]
    A = polygon_mesh(polyA, rng.choice(['fan', 'strip', 'centroid']), rng)
    B = polygon_mesh(polyB, rng.choice(['fan', 'strip', 'centroid']), rng)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.5)


def k_coplanar_foldover(rng):
    """Smoothing/remeshing pushed interior vertices past their neighbours: coplanar fold-overs vs the clean grid."""
    nx, ny = rng.randint(2, 7), rng.randint(2, 7)
    diag = rand_diag(rng)
    B = grid_mesh(nx, ny, 0.0, 0.0, 1.0, 1.0, None, diag)
    A = B.copy()
    for _ in range(rng.randint(1, 3)):
        i, j = rng.randint(1, nx - 1), rng.randint(1, ny - 1)
        k = j * (nx + 1) + i
        ang = rng.uniform(0, 2 * math.pi)
        r = rng.uniform(1.0, 2.5) / max(nx, ny)
        z = 0.0 if rng.random() < 0.6 else rng.choice((-1, 1)) * 10 ** -rng.uniform(3, 15)
        p = A.v[k]
        A.v[k] = (p[0] + r * math.cos(ang), p[1] + r * math.sin(ang), z)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


# --------------------------------------------------------------------------
# kinds: nearly coplanar
# --------------------------------------------------------------------------

def planar_patch_pair(rng, same_prob=0.3):
    """Two triangulations of the same planar region in z = 0."""
    if rng.random() < 0.5:
        n = rng.randint(3, 40)
        if rng.random() < 0.5:
            poly = regular_polygon(n, 1.0)
        else:
            poly = random_convex_polygon(rng, n, 1.0, 10 ** rng.uniform(-2, 0))
        A = polygon_mesh(poly, rng.choice(['fan', 'strip', 'centroid']), rng)
        if rng.random() < same_prob:
            B = A.copy()
        else:
            B = polygon_mesh(poly, rng.choice(['fan', 'strip', 'centroid']), rng)
    else:
        h = 10 ** rng.uniform(-2, 0)
        A = grid_mesh(rng.randint(1, 8), rng.randint(1, 8), 0.0, 0.0, 1.0, h, None, rand_diag(rng))
        if rng.random() < same_prob:
            B = A.copy()
        else:
            B = grid_mesh(rng.randint(1, 8), rng.randint(1, 8), 0.0, 0.0, 1.0, h, None, rand_diag(rng))
    return A, B


def k_near_coplanar_tilt(rng):
    """Two exports of one planar face whose plane fits differ by a tiny rotation (1e-12..1e-3 rad)."""
    A, B = planar_patch_pair(rng)
    theta = rng.choice((-1, 1)) * 10 ** -rng.uniform(3, 12)
    phi = rng.choice([0.0, math.pi / 2, rng.uniform(0, math.pi)])
    axis = (math.cos(phi), math.sin(phi), 0.0)
    where = rng.choice(['vertex', 'edge', 'centroid', 'outside'])
    if where == 'vertex':
        c = A.v[rng.randrange(len(A.v))]
    elif where == 'edge':
        f = A.f[rng.randrange(len(A.f))]
        c = mid(A.v[f[0]], A.v[f[1]])
    elif where == 'centroid':
        c = centroid(A.v)
    else:
        c = (rng.uniform(-3, 3), rng.uniform(-3, 3), 0.0)
    m = rot_axis_angle(axis, theta)
    B = B.mapped(lambda p: rotate_about(p, c, m))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.3)


def k_near_coplanar_offset(rng):
    """A face and its copy offset along the normal by 1e-15..1e-3 (thin shell / duplicated skin)."""
    A, B = planar_patch_pair(rng)
    delta = rng.choice((-1, 1)) * 10 ** -rng.uniform(3, 15)
    shift = (0.0, 0.0) if rng.random() < 0.6 else (rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5))
    B = B.mapped(lambda p: (p[0] + shift[0], p[1] + shift[1], p[2] + delta))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_near_coplanar_bump(rng):
    """A flat patch vs a remeshed copy whose vertices picked up tiny out-of-plane noise or curvature."""
    nx, ny = rng.randint(2, 8), rng.randint(2, 8)
    eps = 10 ** -rng.uniform(3, 14)
    mode = rng.choice(['single', 'random', 'curved', 'edge'])
    bumped = {}
    if mode == 'single':
        bumped[rng.randint(1, nx - 1), rng.randint(1, ny - 1)] = rng.choice((-1, 1)) * eps
    elif mode == 'random':
        for j in range(1, ny):
            for i in range(1, nx):
                bumped[i, j] = eps * rng.uniform(-1, 1)
    elif mode == 'edge':
        bumped[rng.randint(0, nx), 0] = rng.choice((-1, 1)) * eps
    if mode == 'curved':
        zf = lambda i, j, x, y: eps * ((x - 0.5) ** 2 + (y - 0.5) ** 2)
    else:
        zf = lambda i, j, x, y: bumped.get((i, j), 0.0)
    A = grid_mesh(nx, ny, 0.0, 0.0, 1.0, 1.0, None, rand_diag(rng))
    B = grid_mesh(nx, ny, 0.0, 0.0, 1.0, 1.0, zf, rand_diag(rng))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


# --------------------------------------------------------------------------
# kinds: slivers and needles
# --------------------------------------------------------------------------

def k_sliver_over_plane(rng):
    """Sliver/needle triangles (aspect 1e3..1e14) lying in, just above, or standing on a large face."""
    A = base_plane(rng)
    B = Mesh()
    orient = rng.choice(['inplane', 'standing', 'tilted', 'mixed'])
    for _ in range(rng.randint(1, 20)):
        p = (rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), 0.0)
        q = (rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), 0.0)
        d = sub(q, p)
        if norm(d) < 1e-3:
            continue
        o = orient if orient != 'mixed' else rng.choice(['inplane', 'standing', 'tilted'])
        if o == 'inplane':
            u = unit((-d[1], d[0], 0.0))
        elif o == 'standing':
            u = (0.0, 0.0, 1.0)
        else:
            a, b = perp_frame(d)
            ang = rng.uniform(0, 2 * math.pi)
            u = add(mul(a, math.cos(ang)), mul(b, math.sin(ang)))
        z0 = 0.0 if rng.random() < 0.6 else rng.choice((-1, 1)) * 10 ** -rng.uniform(2, 15)
        p, q = (p[0], p[1], z0), (q[0], q[1], z0)
        w = norm(d) * 10 ** -rng.uniform(3, 14)
        B.tri(*make_sliver(rng, p, q, w, u, rng.choice(['cap', 'needle', 'spike'])))
    if not B.f:
        B.tri((-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1e-9, 0.0))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def face_target(rng, m):
    """A point of mesh m: a vertex, a point of an edge, or a face interior point."""
    f = m.f[rng.randrange(len(m.f))]
    a, b, c = (m.v[i] for i in f)
    w = rng.choice(['vertex', 'edge', 'edge_mid', 'interior'])
    if w == 'vertex':
        return a
    if w == 'edge':
        return lerp(a, b, rng.uniform(0.01, 0.99))
    if w == 'edge_mid':
        return mid(a, b)
    r1, r2 = rng.random(), rng.random()
    if r1 + r2 > 1:
        r1, r2 = 1 - r1, 1 - r2
    return add(a, add(mul(sub(b, a), r1), mul(sub(c, a), r2)))


def k_needle_crossing(rng):
    """Needles (fibres, thin feature lines) piercing a face at an interior point, an edge or a vertex."""
    A = base_plane(rng)
    B = Mesh()
    for _ in range(rng.randint(1, 10)):
        t = face_target(rng, A)
        dm = rng.choice(['perp', 'oblique', 'grazing'])
        if dm == 'perp':
            d = (0.0, 0.0, 1.0)
        elif dm == 'oblique':
            d = unit((rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0.2, 1)))
        else:
            al = 10 ** -rng.uniform(1, 8)
            ph = rng.uniform(0, 2 * math.pi)
            d = (math.cos(al) * math.cos(ph), math.cos(al) * math.sin(ph), math.sin(al))
        L = 10 ** rng.uniform(-1, 0.5)
        s = rng.choice([0.5, rng.random(), 0.0, 1.0])
        p = t if s == 0.0 else sub(t, mul(d, L * s))
        q = t if s == 1.0 else add(t, mul(d, L * (1 - s)))
        u, v = perp_frame(d)
        ang = rng.uniform(0, 2 * math.pi)
        u = add(mul(u, math.cos(ang)), mul(v, math.sin(ang)))
        w = L * 10 ** -rng.uniform(3, 14)
        B.tri(*make_sliver(rng, p, q, w, u, rng.choice(['cap', 'needle'])))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_needle_in_plane(rng):
    """Needles lying in the plane of a face: through its vertices, along (parts of) its edges, across it."""
    A = base_plane(rng)
    B = Mesh()
    for _ in range(rng.randint(1, 10)):
        mode = rng.choice(['through_vertex', 'along_edge', 'shared_edge', 'crossing'])
        f = A.f[rng.randrange(len(A.f))]
        e0, e1 = A.v[f[0]], A.v[f[1]]
        if mode == 'through_vertex':
            ph = rng.uniform(0, 2 * math.pi)
            d = (math.cos(ph), math.sin(ph), 0.0)
            p = sub(e0, mul(d, rng.uniform(0.1, 1)))
            q = add(e0, mul(d, rng.uniform(0.1, 1)))
        elif mode == 'along_edge':
            p = lerp(e0, e1, rng.uniform(-0.5, 0.5))
            q = lerp(e0, e1, rng.uniform(0.55, 1.5))
        elif mode == 'shared_edge':
            p, q = e0, e1
        else:
            p = (rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), 0.0)
            q = (rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), 0.0)
        d = sub(q, p)
        if norm(d) == 0.0:
            continue
        u = unit((-d[1], d[0], 0.0))
        if rng.random() < 0.3:
            u = unit((u[0], u[1], rng.choice((-1, 1)) * 10 ** -rng.uniform(0, 8)))
        w = norm(d) * 10 ** -rng.uniform(3, 14)
        B.tri(*make_sliver(rng, p, q, w, u, rng.choice(['cap', 'needle', 'spike'])))
    if not B.f:
        B.tri(A.v[0], A.v[1], lerp(A.v[0], A.v[1], 0.5))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.5)


def k_sliver_strip_both(rng):
    """A very thin rectangle (a fillet/chamfer strip, aspect 1e3..1e14) triangulated differently on both sides."""
    w = 10 ** -rng.uniform(3, 14)
    k1 = rng.randint(1, 40)
    k2 = k1 if rng.random() < 0.4 else rng.randint(1, 40)
    bend = 0.0 if rng.random() < 0.6 else rng.choice((-1, 1)) * w * 10 ** rng.uniform(-3, 1)
    A = grid_mesh(k1, 1, 0.0, 0.0, 1.0, w, None, rand_diag(rng))
    B = grid_mesh(k2, 1, 0.0, 0.0, 1.0, w,
                  lambda i, j, x, y: bend * math.sin(math.pi * x), rand_diag(rng))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_flat_kite_diagonals(rng):
    """Chains of extremely flat kites split along the long diagonal (caps) in one mesh, the short one (needles) in the other."""
    m = rng.randint(1, 12)
    base = Mesh()
    a_idx = [base.vert((2.0 * i, 0.0, 0.0)) for i in range(m + 1)]
    kites = []
    for i in range(m):
        h1 = 10 ** -rng.uniform(3, 14)
        h2 = h1 if rng.random() < 0.5 else 10 ** -rng.uniform(3, 14)
        t1 = 0.0 if rng.random() < 0.3 else rng.uniform(-0.9, 0.9)
        t2 = t1 if rng.random() < 0.5 else rng.uniform(-0.9, 0.9)
        z1 = 0.0 if rng.random() < 0.6 else rng.choice((-1, 1)) * 10 ** -rng.uniform(3, 15)
        c = base.vert((2.0 * i + 1.0 + t1, h1, z1))
        d = base.vert((2.0 * i + 1.0 + t2, -h2, 0.0))
        kites.append((a_idx[i], a_idx[i + 1], c, d))
    A = Mesh(base.v)
    B = Mesh(base.v)
    mix = rng.random() < 0.3
    for (a, b, c, d) in kites:
        for mesh, long_diag in ((A, True), (B, False)):
            ld = long_diag if not mix else rng.random() < 0.5
            if ld:
                mesh.f += [(a, b, c), (b, a, d)]
            else:
                mesh.f += [(a, d, c), (d, b, c)]
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


# --------------------------------------------------------------------------
# kinds: perpendicular and dihedral configurations
# --------------------------------------------------------------------------

def k_fin_on_triangle(rng):
    """Ribs/fins standing perpendicular on a face, on its edges, from its vertices, or just off it."""
    A = base_plane(rng)
    B = Mesh()
    for _ in range(rng.randint(1, 8)):
        mode = rng.choice(['inside', 'edge', 'sub_edge', 'from_vertex'])
        f = A.f[rng.randrange(len(A.f))]
        v0, v1 = A.v[f[0]], A.v[f[1]]
        if mode == 'inside':
            p = (rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), 0.0)
            q = (rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), 0.0)
        elif mode == 'edge':
            p, q = v0, v1
        elif mode == 'sub_edge':
            p, q = lerp(v0, v1, rng.uniform(0, 0.5)), lerp(v0, v1, rng.uniform(0.5, 1))
        else:
            p, q = v0, (rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0)
        zb = 0.0 if rng.random() < 0.6 else rng.choice((-1, 1)) * 10 ** -rng.uniform(3, 15)
        p, q = (p[0], p[1], zb), (q[0], q[1], zb)
        hgt = rng.choice((-1, 1)) * 10 ** rng.uniform(-2, 0.3)
        over = rng.choice(['p', 'mid', 'random'])
        foot = p if over == 'p' else (mid(p, q) if over == 'mid' else lerp(p, q, rng.uniform(-0.5, 1.5)))
        apex = (foot[0], foot[1], zb + hgt)
        shape = rng.choice(['tri', 'wall', 'crossing'])
        if shape == 'tri':
            B.tri(p, q, apex)
        elif shape == 'wall':
            up = (0.0, 0.0, hgt)
            i0, i1, i2, i3 = B.vert(p), B.vert(q), B.vert(add(q, up)), B.vert(add(p, up))
            B.quad(i0, i1, i2, i3, rng.random() < 0.5)
        else:   # fin passing through the plane
            dz = abs(hgt) * rng.uniform(0.1, 1)
            B.tri((p[0], p[1], -dz), (q[0], q[1], -dz), (foot[0], foot[1], abs(hgt)))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.5)


_S45 = math.sqrt(0.5)
_C30 = math.sqrt(3.0) / 2.0
EXACT_DIRS = {0: (1.0, 0.0), 90: (0.0, 1.0), 180: (-1.0, 0.0), 270: (0.0, -1.0),
              45: (_S45, _S45), 135: (-_S45, _S45), 30: (_C30, 0.5), 60: (0.5, _C30),
              120: (-0.5, _C30), 150: (-_C30, 0.5)}


def angle_dir(deg):
    if deg in EXACT_DIRS:
        return EXACT_DIRS[deg]
    r = math.radians(deg)
    return (math.cos(r), math.sin(r))


def rand_hinge_angle(rng):
    c = rng.random()
    if c < 0.6:
        return rng.choice(sorted(EXACT_DIRS))
    if c < 0.75:
        return 180.0 - 10 ** -rng.uniform(1, 10)
    if c < 0.9:
        return 10 ** -rng.uniform(1, 10)
    return 90.0 + rng.choice((-1, 1)) * 10 ** -rng.uniform(1, 10)


def k_hinge_angles(rng):
    """Faces hinged on a common (or almost common) edge at exact angles 0/30/45/.../180 and near 0, 90, 180."""
    p0, p1 = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)
    ax = rng.choice([0.5, 0.0, 1.0, rng.uniform(-0.5, 1.5)])
    r = rng.choice([1.0, 10 ** rng.uniform(-1, 1)])

    def apex(deg, x):
        c, s = angle_dir(deg)
        return (x, r * c, r * s)
    A = Mesh()
    A.tri(p0, p1, apex(rand_hinge_angle(rng), ax))
    if rng.random() < 0.4:
        A.tri(p1, p0, apex(rand_hinge_angle(rng), ax))
    emode = rng.choice(['shared', 'shared', 'near', 'sub', 'super'])
    if emode == 'shared':
        q0, q1 = p0, p1
    elif emode == 'near':
        q0 = add(p0, mul(rand_unit(rng), 10 ** -rng.uniform(6, 15)))
        q1 = add(p1, mul(rand_unit(rng), 10 ** -rng.uniform(6, 15))) if rng.random() < 0.5 else p1
    elif emode == 'sub':
        q0, q1 = lerp(p0, p1, rng.uniform(0.1, 0.4)), lerp(p0, p1, rng.uniform(0.6, 0.9))
    else:
        q0, q1 = lerp(p0, p1, -rng.uniform(0.1, 1)), lerp(p0, p1, 1 + rng.uniform(0.1, 1))
    bx = ax if rng.random() < 0.5 else rng.uniform(-0.5, 1.5)
    B = Mesh()
    beta = rand_hinge_angle(rng)
    B.tri(q0, q1, apex(beta, bx))
    if rng.random() < 0.4:     # leaf mirrored about z=0: points of that plane tie between both leaves
        c, s = angle_dir(beta)
        B.tri(q1, q0, (bx, r * c, -r * s))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.6)


def k_roof_bisector(rng):
    """A symmetric roof/valley (two slopes on a ridge) and geometry in its plane of symmetry: exact distance ties."""
    c, s = angle_dir(rng.choice([30, 45, 60, 90, 0]) if rng.random() < 0.6 else rng.uniform(1, 89))
    r = rng.choice([1.0, rng.uniform(0.2, 3)])
    sign = rng.choice((-1.0, 1.0))                     # roof (-1: slopes go down) or valley
    R0, R1 = (0.0, 0.0, 0.0), (1.0, 0.0, 0.0)
    L0, L1 = (0.0, -r * c, sign * r * s), (1.0, -r * c, sign * r * s)
    Q0, Q1 = (0.0, r * c, sign * r * s), (1.0, r * c, sign * r * s)
    A = Mesh()
    iR0, iR1, iL0, iL1, iQ0, iQ1 = (A.vert(p) for p in (R0, R1, L0, L1, Q0, Q1))
    dg = rng.random() < 0.5
    A.quad(iR0, iL0, iL1, iR1, dg)
    A.quad(iR0, iR1, iQ1, iQ0, dg if rng.random() < 0.5 else not dg)
    B = Mesh()
    mode = rng.choice(['points', 'fin', 'symmetric_tri', 'ridge_line'])
    for _ in range(rng.randint(1, 6)):
        x0, x1 = rng.uniform(-0.3, 1.3), rng.uniform(-0.3, 1.3)
        z0 = rng.choice([0.0, rng.uniform(-2, 2), 10 ** -rng.uniform(1, 12)])
        z1 = rng.uniform(-2, 2)
        if mode == 'points':
            i = B.vert((x0, 0.0, z0))
            B.face(i, i, i)
        elif mode == 'fin':
            B.tri((x0, 0.0, z0), (x1, 0.0, z0), (0.5 * (x0 + x1), 0.0, z1))
        elif mode == 'symmetric_tri':
            a = rng.uniform(0.01, 1)
            B.tri((x0, -a, z0), (x0, a, z0), (x1, 0.0, z1))
        else:
            i, j = B.vert((x0, 0.0, z0)), B.vert((x1, 0.0, z0))
            B.face(i, j, j)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.6)


# --------------------------------------------------------------------------
# kinds: zero-area triangles, duplicates, orientation
# --------------------------------------------------------------------------

def k_degenerate_faces_mixed(rng):
    """Mesh polluted with zero-area faces (points, segments, collinear triples, repeated indices) vs a clean/near copy."""
    base = base_surface(rng, 60)
    A = base.copy()
    nv = len(base.v)
    for _ in range(rng.randint(1, 12)):
        t = rng.choice(['point_on_vertex', 'point_new', 'edge_dup', 'chord', 'collinear',
                        'dup_vertex', 'collinear_ext'])
        i, j = rng.randrange(nv), rng.randrange(nv)
        if t == 'point_on_vertex':
            A.face(i, i, i)
        elif t == 'point_new':
            k = A.vert(add(base.v[i], mul(rand_unit(rng), 10 ** -rng.uniform(0, 12))))
            A.face(k, k, k)
        elif t == 'edge_dup':
            f = base.f[rng.randrange(len(base.f))]
            A.face(*rng.choice([(f[0], f[1], f[1]), (f[0], f[1], f[0]), (f[1], f[2], f[2])]))
        elif t == 'chord':
            A.face(i, j, j)
        elif t == 'collinear':
            k = A.vert(mid(base.v[i], base.v[j]))
            A.face(i, k, j)
        elif t == 'dup_vertex':
            k = A.vert(base.v[i])
            A.face(i, k, i)
        else:
            k = A.vert(lerp(base.v[i], base.v[j], rng.uniform(1.0, 2.0)))
            A.face(i, j, k)
    bmode = rng.choice(['same', 'jitter', 'rotated'])
    if bmode == 'same':
        B = base.copy()
    elif bmode == 'jitter':
        ns = vertex_normals(base)
        eps = 10 ** -rng.uniform(3, 14)
        B = Mesh([add(p, mul(n, eps * rng.uniform(-1, 1))) for p, n in zip(base.v, ns)], base.f)
    else:
        m = rot_axis_angle(rand_unit(rng), 10 ** -rng.uniform(3, 12))
        B = base.mapped(lambda p: matvec(m, p))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_duplicate_faces_orientation(rng):
    """Exporter artefacts: duplicated faces, rotated/flipped index order, split (unwelded) vertices, shuffled order."""
    A = base_surface(rng, 80)
    B = Mesh(A.v, [])
    for f in A.f:
        op = rng.choice(['keep', 'rotate', 'flip', 'dup', 'dup_flip', 'split_verts'])
        if op == 'keep':
            B.f.append(f)
        elif op == 'rotate':
            B.f.append((f[1], f[2], f[0]))
        elif op == 'flip':
            B.f.append((f[0], f[2], f[1]))
        elif op == 'dup':
            B.f += [f, f]
        elif op == 'dup_flip':
            B.f += [f, (f[2], f[1], f[0])]
        else:
            B.f.append(tuple(B.vert(A.v[i]) for i in f))
    if rng.random() < 0.5:
        rng.shuffle(B.f)
    if rng.random() < 0.5:
        perm = list(range(len(B.v)))
        rng.shuffle(perm)
        nv = [None] * len(B.v)
        for old, new in enumerate(perm):
            nv[new] = B.v[old]
        B = Mesh(nv, [(perm[a], perm[b], perm[c]) for (a, b, c) in B.f])
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_degenerate_only(rng):
    """Wireframes, point clouds and polylines stored as zero-area triangles, against triangles or each other."""
    mode = rng.choice(['wireframe', 'points', 'polylines', 'collinear_triples'])
    A = Mesh()
    B = Mesh()
    if mode in ('wireframe', 'points'):
        n = rng.randint(3, 8)
        poly = regular_polygon(n, 1.0) if rng.random() < 0.6 else random_convex_polygon(rng, n)
        A = polygon_mesh(poly, rng.choice(['fan', 'centroid']), rng)
        B = Mesh(poly) if mode == 'wireframe' else Mesh()
        if mode == 'wireframe':
            for i in range(n):
                j = (i + 1) % n
                B.face(i, j, j) if rng.random() < 0.5 else B.face(i, j, i)
        else:
            g = centroid(poly)
            for p in [g] + poly:
                k = B.vert((p[0], p[1], rng.choice([0.0, rng.uniform(-1, 1), 10 ** -rng.uniform(1, 12)])))
                B.face(k, k, k)
    elif mode == 'polylines':
        rel = rng.choice(['parallel', 'skew', 'crossing', 'collinear'])
        pa = [(x, 0.0, 0.0) for x in sorted(rng.uniform(-1, 1) for _ in range(rng.randint(2, 8)))]
        d = rng.choice([1.0, 10 ** -rng.uniform(0, 12)])
        if rel == 'parallel':
            pb = [(x, d, 0.0) for x in sorted(rng.uniform(-1, 1) for _ in range(rng.randint(2, 8)))]
        elif rel == 'skew':
            pb = [(0.3, y, d) for y in sorted(rng.uniform(-1, 1) for _ in range(rng.randint(2, 8)))]
        elif rel == 'crossing':
            pb = [(y * 0.7, y, 0.0) for y in sorted(rng.uniform(-1, 1) for _ in range(rng.randint(2, 8)))]
        else:
            pb = [(x, 0.0, 0.0) for x in sorted(rng.uniform(-2, 2) for _ in range(rng.randint(2, 8)))]
        for pts, m in ((pa, A), (pb, B)):
            idx = [m.vert(p) for p in pts]
            for i in range(len(idx) - 1):
                m.face(idx[i], idx[i + 1], idx[i + 1])
    else:
        for m in (A, B):
            for _ in range(rng.randint(1, 6)):
                ax = rng.randrange(3)
                o = [rng.uniform(-1, 1) for _ in range(3)]
                if rng.random() < 0.5:
                    o[(ax + 1) % 3] = 0.0
                ts = sorted(rng.uniform(-1, 1) for _ in range(3))
                pts = []
                for t in ts:
                    p = list(o)
                    p[ax] = t
                    pts.append(tuple(p))
                rng.shuffle(pts)
                m.tri(*pts)
        if rng.random() < 0.5:
            B = base_plane(rng)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.5)


# --------------------------------------------------------------------------
# kinds: near-coincident copies (near the origin)
# --------------------------------------------------------------------------

def jitter_ulps(rng, mesh, kmax, frac=1.0):
    out = []
    for p in mesh.v:
        if rng.random() < frac:
            out.append(tuple(ulp_move(c, rng.randint(-kmax, kmax)) for c in p))
        else:
            out.append(p)
    return Mesh(out, mesh.f)


def k_ulp_jitter(rng):
    """The same part written by two tools whose arithmetic differs in the last few bits."""
    A, = place(rng, [base_surface(rng)], 0.3)
    B = jitter_ulps(rng, A, rng.randint(1, 4), rng.choice([1.0, 0.5, 0.1]))
    return maybe_swap(rng, A, B)


def k_float32_round(rng):
    """A double-precision mesh and its copy stored in a single-precision (float32) file format."""
    A, = place(rng, [base_surface(rng)], 0.3)
    B = A.mapped(lambda p: tuple(to_f32(c) for c in p))
    return maybe_swap(rng, A, B)


def k_subdivided_copy(rng):
    """A mesh vs its refinement (1-to-4, centroid split, longest-edge bisection with T-junctions)."""
    A, = place(rng, [base_surface(rng, 75)], 0.4)
    mode = rng.choice(['1to4', 'centroid', 'bisect'])
    if mode == '1to4':
        B = subdivide_1to4(A)
    elif mode == 'centroid':
        B = subdivide_centroid(A)
    else:
        B = bisect_longest(A, rng, rng.uniform(0.2, 1.0))
    return maybe_swap(rng, A, B)


def k_tiny_rotation(rng):
    """Two registrations of one part differing by a tiny rotation (1e-15..1e-4 rad)."""
    A, = place(rng, [base_surface(rng)], 0.3)
    theta = rng.choice((-1, 1)) * 10 ** -rng.uniform(4, 15)
    axis = rand_unit(rng) if rng.random() < 0.6 else [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)][rng.randrange(3)]
    where = rng.choice(['centroid', 'vertex', 'origin'])
    c = centroid(A.v) if where == 'centroid' else (A.v[rng.randrange(len(A.v))] if where == 'vertex'
                                                     else (0.0, 0.0, 0.0))
    m = rot_axis_angle(axis, theta)
    B = A.mapped(lambda p: rotate_about(p, c, m))
    return maybe_swap(rng, A, B)


# --------------------------------------------------------------------------
# kinds: near-coincident copies far from the origin ("_far")
# --------------------------------------------------------------------------

def k_jitter_far(rng):
    """Georeferenced / plant-coordinate part re-exported with a few ulps of noise, 1e4..1e8 sizes from the origin."""
    base = base_surface(rng)
    A = base.mapped(far_transform(rng, [base]))
    B = jitter_ulps(rng, A, rng.randint(1, 4), rng.choice([1.0, 0.5]))
    return maybe_swap(rng, A, B)


def k_retriangulated_far(rng):
    """The same far-away surface triangulated differently (coplanar patch or warped quads)."""
    if rng.random() < 0.5:
        A, B = planar_patch_pair(rng, 0.0)
    else:
        nx, ny = rng.randint(1, 8), rng.randint(1, 8)
        amp = 10 ** -rng.uniform(0, 8)
        hs = [amp * rng.uniform(-1, 1) for _ in range((nx + 1) * (ny + 1))]
        zf = lambda i, j, x, y: hs[j * (nx + 1) + i]
        A = grid_mesh(nx, ny, 0.0, 0.0, 1.0, 1.0, zf, lambda i, j: True)
        B = grid_mesh(nx, ny, 0.0, 0.0, 1.0, 1.0, zf, rand_diag(rng))
    T = far_transform(rng, [A, B])
    return maybe_swap(rng, A.mapped(T), B.mapped(T))


def k_rotated_far(rng):
    """Far-away part and a copy rotated by a tiny angle about its own centre (re-registration)."""
    base = base_surface(rng)
    A = base.mapped(far_transform(rng, [base]))
    c = centroid(A.v)
    m = rot_axis_angle(rand_unit(rng), rng.choice((-1, 1)) * 10 ** -rng.uniform(6, 15))
    B = A.mapped(lambda p: rotate_about(p, c, m))
    return maybe_swap(rng, A, B)


def k_subdivided_far(rng):
    """Far-away part and its refinement with midpoints computed in the far coordinates."""
    base = base_surface(rng, 75)
    A = base.mapped(far_transform(rng, [base]))
    mode = rng.choice(['1to4', 'centroid', 'bisect'])
    if mode == '1to4':
        B = subdivide_1to4(A)
    elif mode == 'centroid':
        B = subdivide_centroid(A)
    else:
        B = bisect_longest(A, rng, rng.uniform(0.2, 1.0))
    return maybe_swap(rng, A, B)


# --------------------------------------------------------------------------
# kinds: clusters near one point
# --------------------------------------------------------------------------

def k_high_valence_fan(rng):
    """A pole / cone tip of very high valence (16..250 triangles) vs a copy with the pole moved 1e-12..1e-7."""
    n = rng.randint(16, 250)
    wave = 0.0 if rng.random() < 0.5 else 10 ** -rng.uniform(0, 6)
    kw = rng.randint(1, 7)
    hc = 0.0 if rng.random() < 0.5 else rng.uniform(-1, 1)

    def ring(nn, r=1.0, phase=0.0):
        return [(r * math.cos(phase + 2 * math.pi * i / nn), r * math.sin(phase + 2 * math.pi * i / nn),
                 wave * math.sin(kw * (phase + 2 * math.pi * i / nn))) for i in range(nn)]

    def fan(center, pts):
        m = Mesh()
        c = m.vert(center)
        idx = [m.vert(p) for p in pts]
        for i in range(len(idx)):
            m.face(c, idx[i], idx[(i + 1) % len(idx)])
        return m
    C = (0.0, 0.0, hc)
    pts = ring(n)
    A = fan(C, pts)
    mode = rng.choice(['moved_center', 'resampled', 'point', 'small_fan'])
    dlt = 10 ** -rng.uniform(7, 12)
    if mode == 'moved_center':
        d = rand_unit(rng) if rng.random() < 0.5 else (math.cos(rng.uniform(0, 7)), math.sin(rng.uniform(0, 7)), 0.0)
        B = fan(add(C, mul(d, dlt)), pts)
    elif mode == 'resampled':
        B = fan(C, ring(rng.randint(16, 250), 1.0, rng.choice([0.0, math.pi / n])))
    elif mode == 'point':
        B = Mesh()
        k = B.vert(add(C, mul(rand_unit(rng), dlt)))
        B.face(k, k, k)
    else:
        B = fan(C, [add(C, (p[0] * dlt, p[1] * dlt, p[2] * dlt)) for p in ring(rng.randint(3, 60))])
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_sliver_cluster(rng):
    """Many slivers whose sharp corners all lie within 1e-12..1e-7 of one point (collapsed edges after decimation)."""
    P = (0.0, 0.0, 0.0)
    planar = rng.random() < 0.5
    A = Mesh()
    for _ in range(rng.randint(3, 100)):
        e = (0.0, 0.0, 0.0) if rng.random() < 0.2 else mul(rand_unit(rng), 10 ** -rng.uniform(7, 12))
        if planar:
            e = (e[0], e[1], 0.0)
            ph = rng.uniform(0, 2 * math.pi)
            d = (math.cos(ph), math.sin(ph), 0.0)
            axis = (0.0, 0.0, 1.0)
        else:
            d = rand_unit(rng)
            axis = perp_frame(d)[0]
        R = rng.uniform(0.3, 1)
        m = rot_axis_angle(axis, 10 ** -rng.uniform(3, 12))
        A.tri(add(P, e), mul(d, R), mul(matvec(m, d), R))
    mode = rng.choice(['plane', 'point', 'cluster', 'line'])
    B = Mesh()
    if mode == 'plane':
        where = rng.choice(['interior', 'edge', 'vertex'])
        if where == 'interior':
            B.tri((-1.0, -1.0, 0.0), (1.0, -1.0, 0.0), (0.0, 1.0, 0.0))
        elif where == 'edge':
            B.tri((-1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
        else:
            B.tri((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    elif mode == 'point':
        k = B.vert(P)
        B.face(k, k, k)
    elif mode == 'cluster':
        for _ in range(rng.randint(3, 60)):
            e = mul(rand_unit(rng), 10 ** -rng.uniform(7, 12))
            d = rand_unit(rng)
            m = rot_axis_angle(perp_frame(d)[0], 10 ** -rng.uniform(3, 12))
            B.tri(e, d, matvec(m, d))
    else:
        d = rand_unit(rng)
        u = perp_frame(d)[0]
        off = mul(u, 10 ** -rng.uniform(7, 12))
        B.tri(add(off, mul(d, -1.0)), add(off, d), add(off, add(d, mul(u, 1e-9))))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.3)


def k_snapped_corners(rng):
    """Several parts' corners snapped (imperfectly) to one point, split between the two meshes."""
    P = (0.0, 0.0, 0.0)
    pieces = []
    for _ in range(rng.randint(3, 8)):
        c = P if rng.random() < 0.25 else mul(rand_unit(rng), 10 ** -rng.uniform(7, 12))
        m = Mesh()
        ci = m.vert(c)
        d0 = rand_unit(rng)
        prev = m.vert(add(c, mul(d0, rng.uniform(0.3, 1))))
        for _ in range(rng.randint(1, 4)):
            ax = perp_frame(d0)[0] if rng.random() < 0.5 else rand_unit(rng)
            d0 = matvec(rot_axis_angle(ax, rng.uniform(0.3, 2.5)), d0)
            nxt = m.vert(add(c, mul(d0, rng.uniform(0.3, 1))))
            m.face(ci, prev, nxt)
            prev = nxt
        pieces.append(m)
    A, B = Mesh(), Mesh()
    A.append(pieces[0])
    B.append(pieces[1])
    for p in pieces[2:]:
        (A if rng.random() < 0.5 else B).append(p)
    if rng.random() < 0.4:   # the same piece imported from A's source, snapped differently
        e = mul(rand_unit(rng), 10 ** -rng.uniform(7, 12))
        B.append(pieces[0].mapped(lambda p: add(p, e)))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.3)


# --------------------------------------------------------------------------
# kinds: symmetric configurations with exact ties
# --------------------------------------------------------------------------

def k_regular_pyramid_ties(rng):
    """Regular n-gon pyramids / cones (turned parts): points on the axis are equidistant from all side faces."""
    n = rng.randint(3, 64)
    h = 0.0 if rng.random() < 0.2 else 10 ** rng.uniform(-6, 1)
    ring = regular_polygon(n, 1.0)
    A = Mesh()
    ap = A.vert((0.0, 0.0, h))
    idx = [A.vert(p) for p in ring]
    for i in range(n):
        A.face(ap, idx[i], idx[(i + 1) % n])
    if rng.random() < 0.4:
        A.append(polygon_mesh(ring, rng.choice(['fan', 'centroid']), rng))
    mode = rng.choice(['axis_points', 'rotated', 'ring', 'inverted'])
    B = Mesh()
    if mode == 'axis_points':
        for _ in range(rng.randint(1, 5)):
            k = B.vert((0.0, 0.0, rng.choice([0.0, h * 0.5, -rng.uniform(0, 2), rng.uniform(0, 2)])))
            B.face(k, k, k)
    elif mode == 'rotated':
        ring2 = regular_polygon(n, 1.0, math.pi / n)
        a2 = B.vert((0.0, 0.0, h))
        i2 = [B.vert(p) for p in ring2]
        for i in range(n):
            B.face(a2, i2[i], i2[(i + 1) % n])
    elif mode == 'ring':
        m = rng.choice([n, 2 * n, 3])
        B = polygon_mesh(regular_polygon(m, rng.uniform(0.1, 2), 0.0, rng.uniform(-1, 1) * max(h, 1.0)),
                         'centroid', rng)
    else:
        a2 = B.vert((0.0, 0.0, -h))
        i2 = [B.vert(p) for p in ring]
        for i in range(n):
            B.face(a2, i2[(i + 1) % n], i2[i])
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.6)


def k_polyhedron_center_ties(rng):
    """Cube/octahedron/tetrahedron with probes at symmetric positions: many faces at exactly equal distance."""
    shape = rng.choice(['cube', 'octahedron', 'tetrahedron', 'icosahedron'])
    if shape == 'cube':
        A = box_mesh((-1.0, -1.0, -1.0), (1.0, 1.0, 1.0), rng)
    elif shape == 'octahedron':
        vs = [(1.0, 0.0, 0.0), (-1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]
        fs = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
        A = Mesh(vs, fs)
    elif shape == 'tetrahedron':
        A = Mesh([(1.0, 1.0, 1.0), (1.0, -1.0, -1.0), (-1.0, 1.0, -1.0), (-1.0, -1.0, 1.0)],
                 [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)])
    else:
        A = icosahedron(1.0)
    mode = rng.choice(['center', 'axis_points', 'scaled', 'symmetry_image'])
    if mode == 'symmetry_image' and shape not in ('cube', 'octahedron'):
        mode = 'scaled'
    B = Mesh()
    if mode == 'center':
        k = B.vert((0.0, 0.0, 0.0))
        B.face(k, k, k)
    elif mode == 'axis_points':
        for _ in range(rng.randint(1, 6)):
            t = rng.choice([0.5, 0.25, rng.uniform(-1.5, 1.5)])
            d = rng.choice([(1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (1.0, 1.0, 1.0), (1.0, -1.0, 0.0)])
            k = B.vert(mul(d, t))
            B.face(k, k, k)
    elif mode == 'scaled':
        f = rng.choice([0.5, 0.25, 2.0, 1.0 - 10 ** -rng.uniform(3, 15), 1.0 + 10 ** -rng.uniform(3, 15)])
        B = A.mapped(lambda p: mul(p, f))
    else:
        m = rand_signed_perm(rng)
        B = A.mapped(lambda p: matvec(m, p))
        if shape == 'cube':    # re-triangulate so the image differs from A
            B = box_mesh((-1.0, -1.0, -1.0), (1.0, 1.0, 1.0), rng).mapped(lambda p: matvec(m, p))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.6)


def k_mirror_pair(rng):
    """Mirror-symmetric parts (left/right halves, a mirrored instance) and geometry on the mirror plane."""
    M = Mesh()
    for _ in range(rng.randint(1, 12)):
        M.tri(*[(rng.uniform(-0.3, 1.0), rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(3)])
    mirror = lambda m: Mesh([(-p[0], p[1], p[2]) for p in m.v], [(a, c, b) for (a, b, c) in m.f])
    mode = rng.choice(['mirror', 'symmetric_vs_plane', 'both_symmetric'])
    if mode == 'mirror':
        A, B = M, mirror(M)
    elif mode == 'symmetric_vs_plane':
        A = merge(M, mirror(M))
        B = Mesh()
        for _ in range(rng.randint(1, 6)):
            B.tri(*[(0.0, rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(3)])
    else:
        N = Mesh()
        for _ in range(rng.randint(1, 8)):
            N.tri(*[(rng.uniform(0.0, 1.0), rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(3)])
        A, B = merge(M, mirror(M)), merge(N, mirror(N))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.6)


# --------------------------------------------------------------------------
# kinds: mixed scales
# --------------------------------------------------------------------------

def k_tiny_near_huge(rng):
    """A tiny part (1e-6..1) next to, on, or far from a huge face (1e2..1e6): scale ratios up to 1e12."""
    S = 10 ** rng.uniform(2, 6)
    H = Mesh()
    H.tri((-S, -S, 0.0), (S * rng.uniform(0.5, 1.5), -S * rng.uniform(0.5, 1.5), 0.0),
          (S * rng.uniform(-0.5, 0.5), S * rng.uniform(0.5, 1.5), 0.0))
    if rng.random() < 0.3:
        H.tri((-S, -S, 0.0), (S * rng.uniform(-0.5, 0.5), S * rng.uniform(0.5, 1.5), 0.0),
              (-S * rng.uniform(0.5, 1.5), S * rng.uniform(-0.5, 0.5), 0.0))
    t = 10 ** -rng.uniform(0, 6)
    shape = rng.choice(['ico', 'tri', 'fan'])
    if shape == 'ico':
        T = icosahedron(t)
    elif shape == 'tri':
        T = Mesh()
        T.tri((0.0, 0.0, 0.0), (t, 0.0, 0.0), (0.0, t, t * rng.uniform(-1, 1)))
    else:
        T = polygon_mesh(regular_polygon(rng.randint(3, 12), t), 'centroid', rng)
    loc = rng.choice(['interior', 'edge', 'vertex', 'far'])
    a, b = H.v[0], H.v[1]
    if loc == 'interior':
        c = (0.0, 0.0, rng.choice([0.0, t * rng.uniform(-3, 3), 10 ** -rng.uniform(0, 12)]))
    elif loc == 'edge':
        c = add(mid(a, b), (0.0, 0.0, rng.choice([0.0, t])))
    elif loc == 'vertex':
        c = add(a, mul(rand_unit(rng), t * rng.uniform(0, 3)))
    else:
        c = mul(rand_unit(rng), S * rng.uniform(0.5, 3))
    T = T.mapped(lambda p: add(p, c))
    A, B = maybe_swap(rng, H, T)
    return place(rng, [A, B], 0.3)


def k_tiny_features_big_coords(rng):
    """Survey/plant-scale coordinates (~1e7..3e8) carrying millimetre features, vs a simplified/perturbed version."""
    feat = 10 ** rng.uniform(-4, -2)
    W = 10 ** rng.uniform(0, 2)
    nx, ny = rng.randint(2, 8), rng.randint(2, 8)
    bumpsA = {(rng.randint(0, nx), rng.randint(0, ny)): feat * rng.uniform(-1, 1) for _ in range(rng.randint(1, 10))}
    mode = rng.choice(['flattened', 'moved_bumps', 'scaled_bumps', 'comb'])
    if mode == 'comb':
        A = Mesh()
        B = Mesh()
        for i in range(rng.randint(1, 15)):
            x = W * i / 15.0
            hgt = feat * rng.uniform(1, 10)
            for m, th in ((A, feat), (B, feat * (1 + 10 ** -rng.uniform(1, 6)))):
                q = [m.vert(p) for p in ((x, 0.0, 0.0), (x + th, 0.0, 0.0), (x + th, 0.0, hgt), (x, 0.0, hgt))]
                m.quad(q[0], q[1], q[2], q[3], rng.random() < 0.5)
                if rng.random() < 0.5:
                    m.face(q[0], q[1], q[2])      # duplicate facet from sloppy export
        base = grid_mesh(1, 1, 0.0, -W * 0.1, W, W * 0.2, None, None)
        A.append(base)
        B.append(base)
    else:
        A = grid_mesh(nx, ny, 0.0, 0.0, W, W, lambda i, j, x, y: bumpsA.get((i, j), 0.0), rand_diag(rng))
        if mode == 'flattened':
            zb = lambda i, j, x, y: 0.0
        elif mode == 'moved_bumps':
            bumpsB = {(rng.randint(0, nx), rng.randint(0, ny)): feat * rng.uniform(-1, 1)
                      for _ in range(rng.randint(1, 10))}
            zb = lambda i, j, x, y: bumpsB.get((i, j), 0.0)
        else:
            f = 1 + rng.choice((-1, 1)) * 10 ** -rng.uniform(1, 6)
            zb = lambda i, j, x, y: bumpsA.get((i, j), 0.0) * f
        B = grid_mesh(nx, ny, 0.0, 0.0, W, W, zb, rand_diag(rng))
    m = rand_rotation(rng) if rng.random() < 0.5 else rand_signed_perm(rng)
    off = mul(rand_unit(rng), 10 ** rng.uniform(7, 8.5))
    T = lambda p: add(matvec(m, p), off)
    return maybe_swap(rng, A.mapped(T), B.mapped(T))


# --------------------------------------------------------------------------
# kinds: other pipeline artefacts
# --------------------------------------------------------------------------

def k_boolean_union_boxes(rng):
    """Two stacked boxes as separate shells (coincident facets) vs their boolean union (face with a hole)."""
    a, b, h = rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.2, 2)
    x0 = 0.0 if rng.random() < 0.15 else rng.uniform(0.05, 0.45) * a
    x1 = a if rng.random() < 0.3 else rng.uniform(0.55, 0.95) * a
    y0 = 0.0 if rng.random() < 0.15 else rng.uniform(0.05, 0.45) * b
    y1 = b if rng.random() < 0.3 else rng.uniform(0.55, 0.95) * b
    h2 = h + rng.uniform(0.1, 1.5)
    sink = 0.0 if rng.random() < 0.6 else rng.choice((-1, 1)) * 10 ** -rng.uniform(3, 14)
    A = merge(box_mesh((0.0, 0.0, 0.0), (a, b, h), rng), box_mesh((x0, y0, h + sink), (x1, y1, h2), rng))
    B = Mesh()
    o = [B.vert(p) for p in ((0.0, 0.0, 0.0), (a, 0.0, 0.0), (a, b, 0.0), (0.0, b, 0.0))]
    ot = [B.vert(p) for p in ((0.0, 0.0, h), (a, 0.0, h), (a, b, h), (0.0, b, h))]
    it = [B.vert(p) for p in ((x0, y0, h), (x1, y0, h), (x1, y1, h), (x0, y1, h))]
    tt = [B.vert(p) for p in ((x0, y0, h2), (x1, y0, h2), (x1, y1, h2), (x0, y1, h2))]
    d = lambda: rng.random() < 0.5
    B.quad(o[0], o[3], o[2], o[1], d())                      # bottom
    for i in range(4):                                          # lower sides
        j = (i + 1) % 4
        B.quad(o[i], o[j], ot[j], ot[i], d())
    for i in range(4):                                          # top ring (zero-area if flush)
        j = (i + 1) % 4
        B.quad(ot[i], ot[j], it[j], it[i], d())
    for i in range(4):                                          # upper sides
        j = (i + 1) % 4
        B.quad(it[i], it[j], tt[j], tt[i], d())
    B.quad(tt[0], tt[1], tt[2], tt[3], d())                  # top
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_stitched_seam(rng):
    """Two patches stitched along a seam: duplicated seam vertices, T-junction cracks or tiny gaps vs the welded mesh."""
    amp = rng.choice([0.0, 10 ** -rng.uniform(0, 4)])
    fx, fy = rng.uniform(0.5, 3), rng.uniform(0.5, 3)
    zf = lambda i, j, x, y: amp * math.sin(fx * x) * math.sin(fy * y + 0.3)
    mode = rng.choice(['duplicate', 'tjunction', 'gap'])
    ny = rng.randint(1, 8)
    n1x, n2x = rng.randint(1, 6), rng.randint(1, 6)
    ny2 = ny if mode != 'tjunction' else (ny % 8) + 1
    gap = 0.0 if mode != 'gap' else rng.choice((-1, 1)) * 10 ** -rng.uniform(4, 12)
    P1 = grid_mesh(n1x, ny, 0.0, 0.0, 1.0, 1.0, zf, rand_diag(rng))
    P2 = grid_mesh(n2x, ny2, 1.0 + gap, 0.0, 1.0, 1.0, zf, rand_diag(rng))
    A = merge(P1, P2)
    if mode == 'duplicate' and rng.random() < 0.5:
        B = weld(A)
        if rng.random() < 0.5:
            B.f = [(f[1], f[2], f[0]) for f in B.f]
    else:
        B = grid_mesh(n1x + n2x, ny, 0.0, 0.0, 2.0, 1.0, zf, rand_diag(rng))
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.4)


def k_offset_surface(rng):
    """A surface and its offset (shelling/thickening) by 1e-12..1e-1 along vertex normals: many near-ties."""
    c = rng.choice(['ico', 'uv', 'box', 'grid'])
    if c == 'ico':
        A = icosphere(rng.randint(0, 1), 1.0)
    elif c == 'uv':
        A = uv_sphere(rng.randint(3, 12), rng.randint(2, 8), 1.0)
    elif c == 'box':
        A = box_mesh((-1.0, -1.0, -1.0), (1.0, 1.0, 1.0), rng)
    else:
        amp = 10 ** -rng.uniform(0, 3)
        A = grid_mesh(rng.randint(1, 8), rng.randint(1, 8), -1.0, -1.0, 2.0, 2.0,
                      lambda i, j, x, y: amp * (x * x - y * y), rand_diag(rng))
    d = rng.choice((-1, 1)) * 10 ** -rng.uniform(1, 12)
    if c in ('ico', 'uv') and rng.random() < 0.5:
        ns = [unit(p) for p in A.v]
    else:
        ns = vertex_normals(A)
    B = Mesh([add(p, mul(n, d)) for p, n in zip(A.v, ns)], A.f)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.3)


def k_different_tessellations(rng):
    """One analytic surface (sphere/cylinder) tessellated by two different tools: vertices on the surface, ties."""
    if rng.random() < 0.6:
        nu = rng.randint(3, 14)
        nv = rng.randint(2, 10)
        A = uv_sphere(nu, nv, 1.0)
        mode = rng.choice(['ico', 'uv', 'half_step'])
        if mode == 'ico':
            B = icosphere(rng.randint(0, 1), 1.0)
        elif mode == 'uv':
            B = uv_sphere(rng.randint(3, 14), rng.randint(2, 10), 1.0)
        else:
            B = uv_sphere(nu, nv, 1.0, math.pi / nu)
    else:
        def segs_for(k):   # keep 2*k*segs side + 2*(k-2) cap triangles <= MAX_TRIS
            return max(1, min(rng.randint(1, 5), (MAX_TRIS - 2 * (k - 2)) // (2 * k)))
        n = rng.randint(3, 24)
        A = cylinder(n, segs_for(n), 1.0, 2.0, 0.0, rng.random() < 0.5)
        n2 = rng.choice([n, 2 * n, rng.randint(3, 24)])
        B = cylinder(n2, segs_for(n2), 1.0, 2.0, rng.choice([0.0, math.pi / n]), rng.random() < 0.5)
    A, B = maybe_swap(rng, A, B)
    return place(rng, [A, B], 0.3)


# --------------------------------------------------------------------------
# registry and driver
# --------------------------------------------------------------------------

KINDS = [
    ('coplanar_fan_strip', k_coplanar_fan_strip),
    ('coplanar_tjunction', k_coplanar_tjunction),
    ('quad_diagonal_flip', k_quad_diagonal_flip),
    ('coplanar_partial_overlap', k_coplanar_partial_overlap),
    ('coplanar_foldover', k_coplanar_foldover),
    ('near_coplanar_tilt', k_near_coplanar_tilt),
    ('near_coplanar_offset', k_near_coplanar_offset),
    ('near_coplanar_bump', k_near_coplanar_bump),
    ('sliver_over_plane', k_sliver_over_plane),
    ('needle_crossing', k_needle_crossing),
    ('needle_in_plane', k_needle_in_plane),
    ('sliver_strip_both', k_sliver_strip_both),
    ('flat_kite_diagonals', k_flat_kite_diagonals),
    ('fin_on_triangle', k_fin_on_triangle),
    ('hinge_angles', k_hinge_angles),
    ('roof_bisector', k_roof_bisector),
    ('degenerate_faces_mixed', k_degenerate_faces_mixed),
    ('duplicate_faces_orientation', k_duplicate_faces_orientation),
    ('degenerate_only', k_degenerate_only),
    ('ulp_jitter', k_ulp_jitter),
    ('float32_round', k_float32_round),
    ('subdivided_copy', k_subdivided_copy),
    ('tiny_rotation', k_tiny_rotation),
    ('jitter_far', k_jitter_far),
    ('retriangulated_far', k_retriangulated_far),
    ('rotated_far', k_rotated_far),
    ('subdivided_far', k_subdivided_far),
    ('high_valence_fan', k_high_valence_fan),
    ('sliver_cluster', k_sliver_cluster),
    ('snapped_corners', k_snapped_corners),
    ('regular_pyramid_ties', k_regular_pyramid_ties),
    ('polyhedron_center_ties', k_polyhedron_center_ties),
    ('mirror_pair', k_mirror_pair),
    ('tiny_near_huge', k_tiny_near_huge),
    ('tiny_features_big_coords', k_tiny_features_big_coords),
    ('boolean_union_boxes', k_boolean_union_boxes),
    ('stitched_seam', k_stitched_seam),
    ('offset_surface', k_offset_surface),
    ('different_tessellations', k_different_tessellations),
]


def check_mesh(mesh, what):
    if not mesh.f:
        raise ValueError('%s: no triangles' % what)
    if len(mesh.f) > MAX_TRIS:
        raise ValueError('%s: %d triangles > %d' % (what, len(mesh.f), MAX_TRIS))
    n = len(mesh.v)
    for f in mesh.f:
        if len(f) != 3 or not all(0 <= i < n for i in f):
            raise ValueError('%s: bad face %r' % (what, f))
    for p in mesh.v:
        if len(p) != 3 or not all(math.isfinite(c) for c in p):
            raise ValueError('%s: bad vertex %r' % (what, p))


def write_obj(path, mesh, seed, kind, which):
    out = ['# generate_pairs12.py seed %d kind %s mesh %s' % (seed, kind, which)]
    for p in mesh.v:
        out.append('v %s %s %s' % (repr(float(p[0])), repr(float(p[1])), repr(float(p[2]))))
    for (i, j, k) in mesh.f:
        out.append('f %d %d %d' % (i + 1, j + 1, k + 1))
    with open(path, 'w') as fh:
        fh.write('\n'.join(out) + '\n')


def compact(mesh):
    """Drop vertices no face refers to (keeps the meaning of the OBJ unambiguous)."""
    used = sorted(set(i for f in mesh.f for i in f))
    remap = dict((old, new) for new, old in enumerate(used))
    return Mesh([mesh.v[i] for i in used], [(remap[a], remap[b], remap[c]) for (a, b, c) in mesh.f])


def generate(seed):
    kind, fn = KINDS[seed % len(KINDS)]
    rng = random.Random(seed)
    A, B = fn(rng)
    A, B = compact(A), compact(B)
    check_mesh(A, 'seed %d %s A' % (seed, kind))
    check_mesh(B, 'seed %d %s B' % (seed, kind))
    return kind, A, B


def main(argv):
    if len(argv) != 4:
        sys.stderr.write('usage: %s OUTDIR FROM TO\n' % argv[0])
        return 2
    outdir, lo, hi = argv[1], int(argv[2]), int(argv[3])
    os.makedirs(outdir, exist_ok=True)
    for seed in range(lo, hi):
        kind, A, B = generate(seed)
        stem = os.path.join(outdir, '%06d_%s' % (seed, kind))
        write_obj(stem + '_a.obj', A, seed, kind, 'A')
        write_obj(stem + '_b.obj', B, seed, kind, 'B')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
