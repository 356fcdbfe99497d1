// Mesh input/output.
//
// Why OBJ/PLY/STL/OFF are parsed here rather than with OpenMesh: OpenMesh 9's readers parse
// coordinates into float, which loses the double precision an exact Hausdorff distance needs, and its
// PolyMesh silently drops faces that would make the mesh non-manifold (beetle.obj and truck.obj have
// such edges), which would change the surface being measured. glTF/GLB is read with tinygltf: its data
// is binary, so nothing is lost there. The tests cross-check our face counts against OpenMesh on
// manifold meshes.
//
// Every reader fills a Polys (positions + polygon corner lists, indices not yet checked) and hands it
// to finish(), which checks indices and coordinates, triangulates and welds. Binary reads are bounds
// checked and declared counts are checked against the file size before anything is reserved.
#include "mesh_io.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <string_view>

namespace hlens {
namespace {

namespace fs = std::filesystem;
using sv = std::string_view;

[[noreturn]] void fail(const std::string& path, const std::string& msg) {
    std::string m = path + ": " + msg;
    std::replace(m.begin(), m.end(), '\n', ' ');
    std::replace(m.begin(), m.end(), '\r', ' ');
    throw MeshError(m);
}

template <class... A>
std::string fmt(const char* f, A... a) {
    char buf[512];
    std::snprintf(buf, sizeof buf, f, a...);
    return buf;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower((unsigned char)c));
    return s;
}

// ---------------------------------------------------------------- text tokens
// Tokens end at whitespace, '#', '\n' or the terminating '\0' of the std::string buffer, so
// strtod/strtoll can never run past the token they are given.

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

struct Lines {  // splits [p, end) at '\n'
    const char* p;
    const char* end;
    size_t no = 0;  // 1-based number of the line last returned
    bool next(const char*& b, const char*& e) {
        if (p >= end) return false;
        const char* nl = static_cast<const char*>(std::memchr(p, '\n', size_t(end - p)));
        b = p;
        e = nl ? nl : end;
        p = nl ? nl + 1 : end;
        ++no;
        return true;
    }
};

struct Tokens {  // whitespace-separated tokens of [p, e)
    const char* p;
    const char* e;
    bool next(sv& t) {
        while (p < e && (is_space(*p) || *p == '\n')) ++p;
        if (p == e) return false;
        const char* b = p;
        while (p < e && !is_space(*p) && *p != '\n') ++p;
        t = sv(b, size_t(p - b));
        return true;
    }
};

bool to_double(sv t, double& v) {
    if (t.empty()) return false;
    char* end;
    v = std::strtod(t.data(), &end);
    return end == t.data() + t.size();
}

bool to_int(sv t, long long& v, char stop = 0) {  // decimal integer, optionally followed by `stop`
    if (t.empty()) return false;
    char* end;
    errno = 0;
    v = std::strtoll(t.data(), &end, 10);
    if (errno == ERANGE || end == t.data()) return false;
    return end == t.data() + t.size() || (stop && *end == stop);
}

std::string show(sv t) { return std::string(t.substr(0, 40)); }

bool looks_text(const std::string& d) {
    for (unsigned char c : d)
        if ((c < 0x20 && !is_space(char(c)) && c != '\n') || c == 0x7f) return false;
    return true;
}

// little-endian unsigned integer of n bytes
uint64_t get_le(const unsigned char* p, int n) {
    uint64_t u = 0;
    for (int i = 0; i < n; ++i) u |= uint64_t(p[i]) << (8 * i);
    return u;
}
float f32_from_bits(uint32_t w) { float f; std::memcpy(&f, &w, 4); return f; }
double f64_from_bits(uint64_t w) { double d; std::memcpy(&d, &w, 8); return d; }

// ---------------------------------------------------------------- triangulation

// Ear clipping of the CCW polygon q (corners v) into out. Pass 0 takes a strictly convex corner
// whose triangle holds no other corner; pass 1 (only if none exists) removes a straight or spike
// corner as a degenerate triangle. Returns nullptr on success, else the problem.
const char* clip_ears(const std::vector<Vec2>& q, const std::vector<uint32_t>& v, std::vector<Tri>& out) {
    const size_t m = q.size();
    std::vector<size_t> r(m);
    std::iota(r.begin(), r.end(), 0);
    auto orient = [&](size_t i, size_t j, size_t l) { return cross(q[j] - q[i], q[l] - q[i]); };
    while (r.size() > 3) {
        const size_t cnt = r.size();
        bool clipped = false;
        for (int pass = 0; pass < 2 && !clipped; ++pass) {
            for (size_t j = 0; j < cnt && !clipped; ++j) {
                size_t i0 = r[(j + cnt - 1) % cnt], i1 = r[j], i2 = r[(j + 1) % cnt];
                double c = orient(i0, i1, i2);
                if (pass == 0) {
                    if (!(c > 0)) continue;
                    bool blocked = false;
                    for (size_t t : r) {
                        if (q[t] == q[i0] || q[t] == q[i1] || q[t] == q[i2]) continue;
                        if (orient(i0, i1, t) >= 0 && orient(i1, i2, t) >= 0 && orient(i2, i0, t) >= 0) {
                            blocked = true;
                            break;
                        }
                    }
                    if (blocked) continue;
                } else if (c != 0) {
                    continue;
                }
                out.push_back({v[i0], v[i1], v[i2]});
                r.erase(r.begin() + std::ptrdiff_t(j));
                clipped = true;
            }
        }
        if (!clipped) return "polygon cannot be triangulated (self-intersecting)";
    }
    out.push_back({v[r[0]], v[r[1]], v[r[2]]});
    return nullptr;
}

// Triangulates polygon poly[0..n) (indices valid, coordinates finite) into out.
// Returns nullptr on success, else the problem.
const char* triangulate(const std::vector<Vec3>& P, const int64_t* poly, size_t n, std::vector<Tri>& out) {
    if (n == 3) {  // kept as is, even if degenerate: it is still a set of surface points
        out.push_back({uint32_t(poly[0]), uint32_t(poly[1]), uint32_t(poly[2])});
        return nullptr;
    }
    std::vector<uint32_t> v;  // corners without consecutive repeats
    for (size_t i = 0; i < n; ++i)
        if (v.empty() || P[poly[i]] != P[v.back()]) v.push_back(uint32_t(poly[i]));
    while (v.size() > 1 && P[v.front()] == P[v.back()]) v.pop_back();
    {
        std::vector<std::array<double, 3>> d;
        for (uint32_t c : v) d.push_back({P[c].x, P[c].y, P[c].z});
        std::sort(d.begin(), d.end());
        if (std::unique(d.begin(), d.end()) - d.begin() < 3) return "polygon has fewer than 3 distinct corners";
    }
    const size_t m = v.size();
    auto fan = [&] {
        for (size_t i = 1; i + 1 < m; ++i) out.push_back({v[0], v[i], v[i + 1]});
    };
    if (m == 3) return fan(), nullptr;

    // Newell normal; project along its dominant axis (an affine image of the best-fit plane, so
    // convexity and ear tests give the same answers) with coordinates ordered so the polygon is CCW.
    Vec3 N;
    for (size_t i = 0; i < m; ++i) {
        const Vec3 &a = P[v[i]], &b = P[v[(i + 1) % m]];
        N += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    int k = 0;
    for (int j = 1; j < 3; ++j)
        if (std::fabs(N[j]) > std::fabs(N[k])) k = j;
    if (!(std::fabs(N[k]) > 0) || !std::isfinite(N[k])) {
        // Zero area: if all corners are collinear a (degenerate) fan still covers every edge;
        // otherwise the polygon crosses itself (e.g. a bow tie).
        size_t far = 1;
        for (size_t i = 2; i < m; ++i)
            if (norm2(P[v[i]] - P[v[0]]) > norm2(P[v[far]] - P[v[0]])) far = i;
        for (size_t i = 1; i < m; ++i)
            if (cross(P[v[i]] - P[v[0]], P[v[far]] - P[v[0]]) != Vec3())
                return "polygon cannot be triangulated (self-intersecting)";
        return fan(), nullptr;
    }
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const double s = N[k] > 0 ? 1 : -1;
    std::vector<Vec2> q(m);
    for (size_t i = 0; i < m; ++i) q[i] = Vec2(P[v[i]][a], s * P[v[i]][b]);

    // Convex (every turn left and one full turn in total): fan.
    bool convex = true;
    double turn = 0;
    for (size_t i = 0; i < m && convex; ++i) {
        Vec2 e0 = q[i] - q[(i + m - 1) % m], e1 = q[(i + 1) % m] - q[i];
        double c = cross(e0, e1), d = dot(e0, e1);
        convex = c > 0 || (c == 0 && d > 0);
        turn += std::atan2(c, d);
    }
    if (convex && turn < 3 * 3.14159265358979323846) return fan(), nullptr;

    return clip_ears(q, v, out);
}

// ---------------------------------------------------------------- common back end

struct Polys {
    std::vector<Vec3> pos;
    std::vector<int64_t> idx;      // corners of all faces, 0-based, not yet range checked
    std::vector<size_t> start{0};  // face f is idx[start[f] .. start[f+1])
    void end_face() { start.push_back(idx.size()); }
    size_t num_faces() const { return start.size() - 1; }
};

// Merges vertices with identical coordinates (-0 == +0), keeping first-occurrence order.
void weld(TriangleMesh& m) {
    const size_t n = m.positions.size();
    auto key = [&](size_t i) {
        const Vec3& p = m.positions[i];
        auto bits = [](double x) { uint64_t u; x = x == 0 ? 0.0 : x; std::memcpy(&u, &x, 8); return u; };
        return std::array<uint64_t, 3>{bits(p.x), bits(p.y), bits(p.z)};
    };
    std::vector<std::array<uint64_t, 3>> keys(n);
    for (size_t i = 0; i < n; ++i) keys[i] = key(i);
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
    });
    std::vector<uint32_t> rep(n);  // smallest index with the same key
    for (size_t i = 0; i < n; ++i)
        rep[order[i]] = (i > 0 && keys[order[i]] == keys[order[i - 1]]) ? rep[order[i - 1]] : order[i];
    std::vector<uint32_t> remap(n);
    std::vector<Vec3> pos;
    for (size_t i = 0; i < n; ++i) {
        if (rep[i] == i) {
            remap[i] = uint32_t(pos.size());
            pos.push_back(m.positions[i]);
        } else {
            remap[i] = remap[rep[i]];
        }
    }
    if (pos.size() == n) return;
    m.positions = std::move(pos);
    for (Tri& t : m.triangles)
        for (uint32_t& i : t) i = remap[i];
}

// Checks faces and coordinates, triangulates, welds. `base` converts 0-based indices back to the
// file's numbering in messages (1 for OBJ).
TriangleMesh finish(const std::string& path, Polys& s, const LoadOptions& opt, int base = 0) {
    const size_t nv = s.pos.size(), nf = s.num_faces();
    if (nf == 0) fail(path, "no triangles (the file has no faces)");
    if (nv > UINT32_MAX) fail(path, "too many vertices");
    for (size_t f = 0; f < nf; ++f) {
        size_t n = s.start[f + 1] - s.start[f];
        if (n < 3) fail(path, fmt("face %zu has fewer than 3 corners (%zu)", f + 1, n));
        for (size_t c = s.start[f]; c < s.start[f + 1]; ++c)
            if (s.idx[c] < 0 || uint64_t(s.idx[c]) >= nv)
                fail(path, fmt("face %zu: vertex index %lld out of range (%zu vertices)", f + 1,
                               (long long)s.idx[c] + base, nv));
    }
    for (int64_t c : s.idx) {
        const Vec3& p = s.pos[c];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail(path, fmt("vertex %lld has a NaN or infinite coordinate", (long long)c + base));
    }
    TriangleMesh m;
    m.path = path;
    m.triangles.reserve(nf);
    for (size_t f = 0; f < nf; ++f)
        if (const char* err = triangulate(s.pos, &s.idx[s.start[f]], s.start[f + 1] - s.start[f], m.triangles))
            fail(path, fmt("face %zu: %s", f + 1, err));
    m.positions = std::move(s.pos);
    if (opt.weld) weld(m);
    return m;
}

// ---------------------------------------------------------------- OBJ

TriangleMesh read_obj(const std::string& path, const std::string& data, const LoadOptions& opt) {
    Polys s;
    Lines L{data.data(), data.data() + data.size()};
    const char *b, *e;
    size_t face = 0;
    while (L.next(b, e)) {
        if (const char* h = static_cast<const char*>(std::memchr(b, '#', size_t(e - b)))) e = h;
        Tokens T{b, e};
        sv kw, t;
        if (!T.next(kw)) continue;
        if (kw == "v") {
            double c[3];
            for (double& x : c)
                if (!T.next(t) || !to_double(t, x))
                    fail(path, fmt("line %zu: malformed vertex (bad number '%s')", L.no, show(t).c_str()));
            s.pos.emplace_back(c[0], c[1], c[2]);
        } else if (kw == "f") {
            ++face;
            while (T.next(t)) {
                long long i;
                if (!to_int(t, i, '/'))
                    fail(path, fmt("line %zu: malformed face corner '%s'", L.no, show(t).c_str()));
                long long r = i > 0 ? i - 1 : (long long)s.pos.size() + i;  // negative: relative
                if (i == 0 || r < 0)
                    fail(path, fmt("face %zu (line %zu): vertex index %lld out of range (%zu vertices so far)",
                                   face, L.no, i, s.pos.size()));
                s.idx.push_back(r);
            }
            s.end_face();
        }  // vt vn g o s usemtl mtllib l p ...: not part of the surface
    }
    return finish(path, s, opt, 1);
}

// ---------------------------------------------------------------- PLY

enum PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };
const int kPlySize[] = {1, 1, 2, 2, 4, 4, 4, 8};
// The largest list length a count of each type can hold (a float count type is held to uint's).
const double kPlyMaxCount[] = {127, 255, 32767, 65535, 2147483647.0, 4294967295.0, 4294967295.0, 4294967295.0};

bool ply_type(sv n, int& t) {
    static const std::pair<sv, int> names[] = {
        {"char", I8},   {"int8", I8},     {"uchar", U8},  {"uint8", U8},   {"short", I16},
        {"int16", I16}, {"ushort", U16},  {"uint16", U16}, {"int", I32},   {"int32", I32},
        {"uint", U32},  {"uint32", U32},  {"float", F32}, {"float32", F32}, {"double", F64},
        {"float64", F64}};
    for (auto& [name, type] : names)
        if (n == name) return t = type, true;
    return false;
}

double ply_bin(const unsigned char* p, int t, bool big) {
    const int n = kPlySize[t];
    unsigned char le[8];
    for (int i = 0; i < n; ++i) le[i] = big ? p[n - 1 - i] : p[i];
    uint64_t u = get_le(le, n);
    switch (t) {
        case I8: return int8_t(u);
        case U8: return uint8_t(u);
        case I16: return int16_t(u);
        case U16: return uint16_t(u);
        case I32: return int32_t(u);
        case U32: return uint32_t(u);
        case F32: return f32_from_bits(uint32_t(u));
        default: return f64_from_bits(u);
    }
}

struct PlyProp { std::string name; int type = 0; bool list = false; int count_type = 0; };
struct PlyElem { std::string name; uint64_t count = 0; std::vector<PlyProp> props; };

// The PLY header: its elements with their properties, and the format (0 ascii, 1 binary little
// endian, 2 binary big endian). Leaves L at the first line of the data.
int read_ply_header(const std::string& path, Lines& L, std::vector<PlyElem>& elems) {
    const char *b, *e;
    sv t;
    if (!L.next(b, e) || !Tokens{b, e}.next(t) || t != "ply") fail(path, "not a PLY file (no 'ply' magic)");
    int format = -1;  // 0 ascii, 1 binary little endian, 2 binary big endian
    bool header_done = false;
    while (!header_done && L.next(b, e)) {
        Tokens T{b, e};
        sv kw, a, c, d;
        if (!T.next(kw) || kw == "comment" || kw == "obj_info") continue;
        if (kw == "end_header") {
            header_done = true;
        } else if (kw == "format" && T.next(a)) {
            format = a == "ascii" ? 0 : a == "binary_little_endian" ? 1 : a == "binary_big_endian" ? 2 : -2;
            if (format == -2) fail(path, "unknown PLY format '" + show(a) + "'");
        } else if (kw == "element" && T.next(a) && T.next(c)) {
            long long n;
            if (!to_int(c, n) || n < 0) fail(path, fmt("PLY header line %zu: malformed element count", L.no));
            elems.push_back({std::string(a), uint64_t(n), {}});
        } else if (kw == "property" && !elems.empty() && T.next(a) && T.next(c)) {
            PlyProp p;
            if (a == "list") {
                if (!T.next(d) || !ply_type(c, p.count_type) || !ply_type(d, p.type) || !T.next(a))
                    fail(path, fmt("PLY header line %zu: malformed list property", L.no));
                p.list = true;
                p.name = std::string(a);
            } else {
                if (!ply_type(a, p.type)) fail(path, "unknown PLY property type '" + show(a) + "'");
                p.name = std::string(c);
            }
            elems.back().props.push_back(p);
        } else {
            fail(path, fmt("malformed PLY header line %zu", L.no));
        }
    }
    if (!header_done) fail(path, "truncated PLY header (no end_header)");
    if (format < 0) fail(path, "PLY header has no format line");
    return format;
}

// Rejects a binary element that cannot fit in the `left` bytes that follow, and reserves room for
// its items in `s` (no more than the bytes left can hold, whatever the header claims).
void reserve_ply_element(const std::string& path, const PlyElem& E, bool ascii, size_t left, bool is_vertex,
                         bool is_face, Polys& s) {
    size_t min_size = 0;  // bytes per element, at least
    for (const PlyProp& pr : E.props) min_size += ascii ? 2 : size_t(kPlySize[pr.list ? pr.count_type : pr.type]);
    if (!ascii && E.count > left / min_size)
        fail(path, fmt("truncated: PLY header declares %llu '%s' elements (at least %llu bytes) but only %zu "
                       "bytes follow", (unsigned long long)E.count, E.name.c_str(),
                       (unsigned long long)(E.count * min_size), left));
    const size_t n_reserve = size_t(std::min<uint64_t>(E.count, left / min_size + 1));
    if (is_vertex) s.pos.reserve(n_reserve);
    if (is_face) s.start.reserve(n_reserve + 1), s.idx.reserve(std::min(3 * n_reserve, left));
}

// The header, then each element's items: x, y, z of vertices and the vertex_indices lists of
// faces are kept, every other property is read past (ASCII) or skipped (binary).
TriangleMesh read_ply(const std::string& path, const std::string& data, const LoadOptions& opt) {
    Lines L{data.data(), data.data() + data.size()};
    std::vector<PlyElem> elems;
    const int format = read_ply_header(path, L, elems);
    sv t;

    const bool ascii = format == 0, big = format == 2;
    const unsigned char* p = reinterpret_cast<const unsigned char*>(L.p);
    const unsigned char* end = reinterpret_cast<const unsigned char*>(data.data() + data.size());
    Tokens data_tokens{L.p, data.data() + data.size()};
    Polys s;
    for (const PlyElem& E : elems) {
        const bool is_vertex = E.name == "vertex", is_face = E.name == "face";
        int ix = -1, iy = -1, iz = -1, ilist = -1;
        for (int i = 0; i < int(E.props.size()); ++i) {
            const PlyProp& pr = E.props[size_t(i)];
            if (is_vertex && !pr.list && pr.name == "x") ix = i;
            if (is_vertex && !pr.list && pr.name == "y") iy = i;
            if (is_vertex && !pr.list && pr.name == "z") iz = i;
            if (is_face && pr.list && (pr.name == "vertex_indices" || pr.name == "vertex_index")) ilist = i;
        }
        if (is_vertex && (ix < 0 || iy < 0 || iz < 0)) fail(path, "PLY vertex element lacks x, y or z");
        if (is_vertex && E.count > UINT32_MAX) fail(path, "too many vertices");
        if (is_face && ilist < 0) fail(path, "PLY face element has no vertex_indices list");
        if (E.props.empty()) continue;

        reserve_ply_element(path, E, ascii, size_t(end - p), is_vertex, is_face, s);

        uint64_t item = 0;
        auto value = [&](int type) -> double {  // next value of the data section
            if (ascii) {
                double v;
                if (!data_tokens.next(t))
                    fail(path, fmt("truncated: file ends in '%s' element %llu of %llu", E.name.c_str(),
                                   (unsigned long long)item, (unsigned long long)E.count));
                if (!to_double(t, v) || (type < F32 && v != std::floor(v)))
                    fail(path, fmt("malformed number '%s' in '%s' element %llu", show(t).c_str(), E.name.c_str(),
                                   (unsigned long long)item));
                return v;
            }
            if (end - p < kPlySize[type])
                fail(path, fmt("truncated: file ends in '%s' element %llu of %llu", E.name.c_str(),
                               (unsigned long long)item, (unsigned long long)E.count));
            double v = ply_bin(p, type, big);
            p += kPlySize[type];
            return v;
        };
        for (item = 0; item < E.count; ++item) {
            double xyz[3] = {0, 0, 0};
            for (int i = 0; i < int(E.props.size()); ++i) {
                const PlyProp& pr = E.props[size_t(i)];
                if (!pr.list) {
                    double v = value(pr.type);
                    if (i == ix) xyz[0] = v;
                    if (i == iy) xyz[1] = v;
                    if (i == iz) xyz[2] = v;
                    continue;
                }
                double n = value(pr.count_type);  // ASCII numbers are not bounded by their type
                if (!(n >= 0) || n != std::floor(n) || n > kPlyMaxCount[pr.count_type])
                    fail(path, fmt("invalid list length in '%s' element %llu", E.name.c_str(), (unsigned long long)item));
                if (!ascii && n > double(end - p) / kPlySize[pr.type])
                    fail(path, fmt("truncated: file ends in '%s' element %llu of %llu", E.name.c_str(),
                                   (unsigned long long)item, (unsigned long long)E.count));
                if (!ascii && i != ilist) {  // skip the list
                    p += size_t(n) * size_t(kPlySize[pr.type]);
                    continue;
                }
                for (uint64_t j = 0; j < uint64_t(n); ++j) {
                    double v = value(pr.type);
                    if (i == ilist) s.idx.push_back(std::fabs(v) < 9e18 ? int64_t(v) : -1);
                }
            }
            if (is_vertex) s.pos.emplace_back(xyz[0], xyz[1], xyz[2]);
            if (is_face) s.end_face();
        }
    }
    return finish(path, s, opt);
}

// ---------------------------------------------------------------- STL

TriangleMesh read_stl_ascii(const std::string& path, const std::string& data, const LoadOptions& opt) {
    Polys s;
    Lines L{data.data(), data.data() + data.size()};
    const char *b, *e;
    size_t facet = 0, open = 0;  // corners of the facet being read
    while (L.next(b, e)) {
        Tokens T{b, e};
        sv kw, t;
        if (!T.next(kw)) continue;
        std::string k = lower(std::string(kw));
        if (k == "facet") {
            ++facet;
        } else if (k == "vertex") {
            double c[3];
            for (double& x : c)
                if (!T.next(t) || !to_double(t, x))
                    fail(path, fmt("line %zu: malformed vertex (bad number '%s')", L.no, show(t).c_str()));
            s.pos.emplace_back(c[0], c[1], c[2]);
            s.idx.push_back(int64_t(s.pos.size() - 1));
            ++open;
        } else if (k == "endloop" || (k == "endfacet" && open > 0)) {
            s.end_face();
            open = 0;
        }  // solid, endsolid, outer loop, normals: nothing to do
    }
    if (open > 0) fail(path, fmt("truncated: file ends inside facet %zu", facet));
    return finish(path, s, opt);
}

TriangleMesh read_stl(const std::string& path, const std::string& data, const LoadOptions& opt) {
    // Binary iff the size is exactly what the triangle count says: some binary headers start with
    // "solid" and some ASCII files do not.
    const size_t size = data.size();
    const auto* u = reinterpret_cast<const unsigned char*>(data.data());
    const uint64_t n = size >= 84 ? get_le(u + 80, 4) : 0;
    if (!(size >= 84 && 84 + 50 * n == size) && looks_text(data)) return read_stl_ascii(path, data, opt);
    if (size < 84) fail(path, fmt("truncated binary STL: %zu bytes, the header alone needs 84", size));
    if (size < 84 + 50 * n)
        fail(path, fmt("truncated binary STL: header declares %llu triangles (%llu bytes) but the file has %zu bytes",
                       (unsigned long long)n, (unsigned long long)(84 + 50 * n), size));
    Polys s;  // extra bytes after the declared triangles are ignored
    s.pos.reserve(3 * n);
    s.idx.reserve(3 * n);
    s.start.reserve(n + 1);
    for (uint64_t i = 0; i < n; ++i) {
        const unsigned char* r = u + 84 + 50 * i + 12;
        for (int c = 0; c < 3; ++c, r += 12) {
            s.pos.emplace_back(f32_from_bits(uint32_t(get_le(r, 4))), f32_from_bits(uint32_t(get_le(r + 4, 4))),
                               f32_from_bits(uint32_t(get_le(r + 8, 4))));
            s.idx.push_back(int64_t(3 * i + c));
        }
        s.end_face();
    }
    return finish(path, s, opt);
}

// ---------------------------------------------------------------- OFF

TriangleMesh read_off(const std::string& path, const std::string& data, const LoadOptions& opt) {
    Lines L{data.data(), data.data() + data.size()};
    const char *b, *e;
    auto next_line = [&](Tokens& T) {  // next line with a token, comments removed
        while (L.next(b, e)) {
            if (const char* h = static_cast<const char*>(std::memchr(b, '#', size_t(e - b)))) e = h;
            T = Tokens{b, e};
            Tokens peek = T;
            sv t;
            if (peek.next(t)) return true;
        }
        return false;
    };
    Tokens T{nullptr, nullptr};
    sv t;
    if (!next_line(T) || !T.next(t) || t.size() < 3 || lower(std::string(t.substr(t.size() - 3))) != "off")
        fail(path, "not an OFF file (no OFF header)");
    const sv prefix = t.substr(0, t.size() - 3);
    if (prefix.find_first_not_of("STCN4n") != sv::npos) fail(path, "not an OFF file (unknown header '" + show(t) + "')");
    if (prefix.find('4') != sv::npos) fail(path, "4-dimensional OFF is not supported");
    std::vector<sv> head;  // [dimension] vertex-count face-count [edge-count]
    while (T.next(t)) head.push_back(t);
    const size_t need = prefix.find('n') != sv::npos ? 3 : 2;
    while (head.size() < need && next_line(T))
        while (T.next(t)) head.push_back(t);
    for (sv h : head)
        if (lower(std::string(h)) == "binary") fail(path, "binary OFF is not supported");
    long long dim = 3, nv, nf;
    if (head.size() < need || (need == 3 && !to_int(head[0], dim)) || !to_int(head[need - 2], nv) ||
        !to_int(head[need - 1], nf) || nv < 0 || nf < 0)
        fail(path, "malformed OFF counts line");
    if (dim != 3) fail(path, fmt("%lld-dimensional OFF is not supported", dim));

    Polys s;
    const size_t left = size_t(data.data() + data.size() - L.p);
    s.pos.reserve(size_t(std::min<long long>(nv, (long long)left / 5 + 1)));
    s.start.reserve(size_t(std::min<long long>(nf, (long long)left / 5 + 1)) + 1);
    for (long long i = 0; i < nv; ++i) {
        if (!next_line(T)) fail(path, fmt("truncated: header declares %lld vertices, file has %lld", nv, i));
        double c[3];
        for (double& x : c)
            if (!T.next(t) || !to_double(t, x))
                fail(path, fmt("line %zu: malformed vertex (bad number '%s')", L.no, show(t).c_str()));
        s.pos.emplace_back(c[0], c[1], c[2]);
    }
    for (long long f = 0; f < nf; ++f) {
        if (!next_line(T)) fail(path, fmt("truncated: header declares %lld faces, file has %lld", nf, f));
        long long n, i;
        if (!T.next(t) || !to_int(t, n) || n < 0) fail(path, fmt("line %zu: malformed face", L.no));
        for (long long c = 0; c < n; ++c) {
            if (!T.next(t) || !to_int(t, i))
                fail(path, fmt("line %zu: malformed face (expected %lld vertex indices)", L.no, n));
            s.idx.push_back(i);
        }
        s.end_face();  // colours after the indices are ignored
    }
    return finish(path, s, opt);
}

// ---------------------------------------------------------------- glTF / GLB

struct Mat4 {  // column-major, like glTF
    double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    Mat4 operator*(const Mat4& o) const {
        Mat4 r;
        for (int c = 0; c < 4; ++c)
            for (int row = 0; row < 4; ++row) {
                double acc = 0;
                for (int k = 0; k < 4; ++k) acc += m[k * 4 + row] * o.m[c * 4 + k];
                r.m[c * 4 + row] = acc;
            }
        return r;
    }
    Vec3 apply(const Vec3& p) const {
        return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12], m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
                m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
    }
    double det3() const {
        return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
               m[8] * (m[1] * m[6] - m[5] * m[2]);
    }
};

Mat4 node_matrix(const tinygltf::Node& n) {
    Mat4 M;
    if (n.matrix.size() == 16) {
        std::copy(n.matrix.begin(), n.matrix.end(), M.m);
        return M;
    }
    double x = 0, y = 0, z = 0, w = 1;  // T * R * S
    if (n.rotation.size() == 4) {
        x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
        double l = std::sqrt(x * x + y * y + z * z + w * w);
        if (l > 0) x /= l, y /= l, z /= l, w /= l;
    }
    const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int c = 0; c < 3; ++c) {
        double sc = n.scale.size() == 3 ? n.scale[size_t(c)] : 1.0;
        for (int r = 0; r < 3; ++r) M.m[c * 4 + r] = R[r][c] * sc;
    }
    if (n.translation.size() == 3)
        for (int r = 0; r < 3; ++r) M.m[12 + r] = n.translation[size_t(r)];
    return M;
}

struct Accessor {
    const unsigned char* p = nullptr;
    size_t stride = 0, count = 0;
    int ctype = 0, ncomp = 0;
    bool normalized = false;
};

int component_size(int ct) {
    switch (ct) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT: case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
        default: return 0;
    }
}

double component(const unsigned char* p, int ct, bool norm) {
    switch (ct) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: { double v = int8_t(p[0]); return norm ? std::max(v / 127, -1.0) : v; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return norm ? p[0] / 255.0 : p[0];
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            double v = int16_t(get_le(p, 2));
            return norm ? std::max(v / 32767, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return double(get_le(p, 2)) / (norm ? 65535 : 1);
        case TINYGLTF_COMPONENT_TYPE_INT: return int32_t(get_le(p, 4));
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return double(get_le(p, 4));
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return f32_from_bits(uint32_t(get_le(p, 4)));
        default: return f64_from_bits(get_le(p, 8));
    }
}

Accessor get_accessor(const std::string& path, const tinygltf::Model& m, int ai, int want_type) {
    if (ai < 0 || size_t(ai) >= m.accessors.size()) fail(path, fmt("glTF accessor %d does not exist", ai));
    const tinygltf::Accessor& a = m.accessors[size_t(ai)];
    if (a.sparse.isSparse) fail(path, fmt("glTF accessor %d is sparse (not supported)", ai));
    const int cs = component_size(a.componentType);
    const int nc = want_type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
    if (a.type != want_type || cs == 0) fail(path, fmt("glTF accessor %d has an unexpected type", ai));
    Accessor r{nullptr, 0, a.count, a.componentType, nc, a.normalized};
    if (a.count == 0) return r;
    if (a.bufferView < 0 || size_t(a.bufferView) >= m.bufferViews.size())
        fail(path, fmt("glTF accessor %d has no valid bufferView", ai));
    const tinygltf::BufferView& bv = m.bufferViews[size_t(a.bufferView)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= m.buffers.size())
        fail(path, fmt("glTF bufferView %d has no valid buffer", a.bufferView));
    const std::vector<unsigned char>& buf = m.buffers[size_t(bv.buffer)].data;
    const size_t elem = size_t(cs * nc), stride = bv.byteStride ? bv.byteStride : elem;
    if (stride < elem) fail(path, fmt("glTF bufferView %d: byteStride too small", a.bufferView));
    if (bv.byteOffset > buf.size() || bv.byteLength > buf.size() - bv.byteOffset)
        fail(path, fmt("truncated: glTF bufferView %d extends past the end of its buffer", a.bufferView));
    if (a.byteOffset > bv.byteLength || elem > bv.byteLength - a.byteOffset ||
        a.count - 1 > (bv.byteLength - a.byteOffset - elem) / stride)
        fail(path, fmt("truncated: glTF accessor %d extends past the end of its bufferView", ai));
    r.p = buf.data() + bv.byteOffset + a.byteOffset;
    r.stride = stride;
    return r;
}

void add_primitive(const std::string& path, const tinygltf::Model& model, const tinygltf::Primitive& prim,
                   const Mat4& M, Polys& s, int mesh_no) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return;  // points and lines are not part of the surface
    auto it = prim.attributes.find("POSITION");
    if (it == prim.attributes.end()) fail(path, fmt("glTF mesh %d has a triangle primitive without POSITION", mesh_no));
    const Accessor pa = get_accessor(path, model, it->second, TINYGLTF_TYPE_VEC3);
    if (pa.count > UINT32_MAX - s.pos.size()) fail(path, "too many vertices");  // node instancing multiplies
    std::vector<int64_t> ids;
    if (prim.indices >= 0) {
        const Accessor ia = get_accessor(path, model, prim.indices, TINYGLTF_TYPE_SCALAR);
        if (ia.ctype == TINYGLTF_COMPONENT_TYPE_FLOAT || ia.ctype == TINYGLTF_COMPONENT_TYPE_DOUBLE)
            fail(path, fmt("glTF accessor %d: indices must be integers", prim.indices));
        ids.reserve(ia.count);
        for (size_t i = 0; i < ia.count; ++i) {
            double v = component(ia.p + i * ia.stride, ia.ctype, false);
            if (v < 0 || v >= double(pa.count))
                fail(path, fmt("glTF mesh %d: index %.0f out of range (%zu vertices)", mesh_no, v, pa.count));
            ids.push_back(int64_t(v));
        }
    } else {
        ids.resize(pa.count);
        std::iota(ids.begin(), ids.end(), int64_t(0));
    }
    const int64_t base = int64_t(s.pos.size());
    for (size_t i = 0; i < pa.count; ++i) {
        const unsigned char* q = pa.p + i * pa.stride;
        const size_t cs = size_t(component_size(pa.ctype));
        s.pos.push_back(M.apply(Vec3(component(q, pa.ctype, pa.normalized), component(q + cs, pa.ctype, pa.normalized),
                                     component(q + 2 * cs, pa.ctype, pa.normalized))));
    }
    const bool flip = M.det3() < 0;  // a mirroring transform would turn the triangles inside out
    auto tri = [&](int64_t a, int64_t b, int64_t c) {
        s.idx.insert(s.idx.end(), {base + a, base + (flip ? c : b), base + (flip ? b : c)});
        s.end_face();
    };
    const size_t n = ids.size();
    if (mode == TINYGLTF_MODE_TRIANGLES)
        for (size_t i = 0; i + 2 < n; i += 3) tri(ids[i], ids[i + 1], ids[i + 2]);
    else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
        for (size_t i = 0; i + 2 < n; ++i)
            i % 2 ? tri(ids[i], ids[i + 2], ids[i + 1]) : tri(ids[i], ids[i + 1], ids[i + 2]);  // as in the spec
    else
        for (size_t i = 0; i + 2 < n; ++i) tri(ids[i + 1], ids[i + 2], ids[0]);
}

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;  // textures are irrelevant here: do not decode them
}

// File system callbacks for a glTF read from memory: there is no directory to resolve a uri in.
// Every file "exists", so that tinygltf asks no_read for it and the message says why it is not read.
bool every_file_exists(const std::string&, void*) { return true; }
std::string no_expand(const std::string& p, void*) { return p; }
bool no_read(std::vector<unsigned char>*, std::string* err, const std::string& p, void*) {
    if (err) *err += "cannot read external file '" + p + "' when reading from memory";
    return false;
}
bool no_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "cannot write files";
    return false;
}

// external_files: whether buffers may be external files, found next to `path`.
TriangleMesh read_gltf(const std::string& path, const std::string& data, bool binary, bool external_files,
                       const LoadOptions& opt) {
    if (data.size() > UINT32_MAX) fail(path, "file too large for glTF");
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    if (!external_files) loader.SetFsCallbacks({every_file_exists, no_expand, no_read, no_write, nullptr});
    std::string err, warn, base = fs::path(path).parent_path().string();
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(data.data()),
                                                  unsigned(data.size()), base)
                    : loader.LoadASCIIFromString(&model, &err, &warn, data.data(), unsigned(data.size()), base);
    } catch (const std::exception& ex) {
        err = ex.what();
    }
    if (!ok) fail(path, "glTF parse error: " + (err.empty() ? std::string("unknown error") : err));

    // Roots: the default scene (scene 0 if none is marked); without scenes, every parentless node.
    std::vector<int> roots;
    const size_t nn = model.nodes.size();
    if (!model.scenes.empty()) {
        int si = model.defaultScene >= 0 && size_t(model.defaultScene) < model.scenes.size() ? model.defaultScene : 0;
        roots = model.scenes[size_t(si)].nodes;
    } else {
        std::vector<char> child(nn, 0);
        for (const auto& n : model.nodes)
            for (int c : n.children)
                if (c >= 0 && size_t(c) < nn) child[size_t(c)] = 1;
        for (size_t i = 0; i < nn; ++i)
            if (!child[i]) roots.push_back(int(i));
    }
    Polys s;
    std::vector<char> seen(nn, 0);  // nodes form trees: a node met twice means a cycle or bad file
    std::vector<std::pair<int, Mat4>> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, Mat4()});
    while (!stack.empty()) {
        auto [ni, parent] = stack.back();
        stack.pop_back();
        if (ni < 0 || size_t(ni) >= nn) fail(path, fmt("glTF node %d does not exist", ni));
        if (seen[size_t(ni)]) fail(path, fmt("glTF node %d is reached twice (cycle in the node hierarchy)", ni));
        seen[size_t(ni)] = 1;
        const tinygltf::Node& node = model.nodes[size_t(ni)];
        const Mat4 M = parent * node_matrix(node);
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model.meshes.size()) fail(path, fmt("glTF mesh %d does not exist", node.mesh));
            for (const auto& prim : model.meshes[size_t(node.mesh)].primitives)
                add_primitive(path, model, prim, M, s, node.mesh);
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.push_back({*c, M});
    }
    return finish(path, s, opt);
}

// ---------------------------------------------------------------- files

std::string read_file(const std::string& path) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::string data;
    char buf[1 << 16];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) data.append(buf, n);
    const bool bad = std::ferror(f);
    std::fclose(f);
    if (bad) fail(path, "read error");
    return data;
}

// The extension of `path` in lower case; fails unless it is one of the supported formats.
std::string format_of(const std::string& path) {
    const std::string ext = lower(fs::path(path).extension().string());
    if (ext != ".obj" && ext != ".ply" && ext != ".stl" && ext != ".off" && ext != ".gltf" && ext != ".glb")
        fail(path, "unknown file extension '" + ext + "' (supported: .obj .ply .stl .off .gltf .glb)");
    return ext;
}

// data must be a std::string: the text readers rely on its terminating '\0' (see Tokens).
TriangleMesh parse(const std::string& path, const std::string& ext, const std::string& data, bool external_files,
                   const LoadOptions& opt) {
    if (data.empty()) fail(path, "empty file");
    if (ext == ".obj") return read_obj(path, data, opt);
    if (ext == ".ply") return read_ply(path, data, opt);
    if (ext == ".stl") return read_stl(path, data, opt);
    if (ext == ".off") return read_off(path, data, opt);
    return read_gltf(path, data, ext == ".glb", external_files, opt);
}

}  // namespace

TriangleMesh load_mesh(const std::string& path, const LoadOptions& opt) {
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (!fs::exists(st)) fail(path, "file not found");
    if (fs::is_directory(st)) fail(path, "cannot open: is a directory");
    if (!fs::is_regular_file(st)) fail(path, "cannot open: not a regular file");
    const std::string ext = format_of(path);
    return parse(path, ext, read_file(path), true, opt);
}

TriangleMesh load_mesh_from_memory(const void* data, size_t size, const std::string& name, const LoadOptions& opt) {
    const std::string ext = format_of(name);
    return parse(name, ext, size ? std::string(static_cast<const char*>(data), size) : std::string(), false, opt);
}

TriangleMesh make_mesh(std::vector<Vec3> positions, std::vector<Tri> tris, const std::string& name) {
    const std::string who = name.empty() ? "<memory mesh>" : name;
    if (tris.empty()) fail(who, "no triangles");
    for (size_t t = 0; t < tris.size(); ++t)
        for (uint32_t i : tris[t]) {
            if (i >= positions.size())
                fail(who, fmt("triangle %zu: vertex index %u out of range (%zu vertices)", t, i, positions.size()));
            const Vec3& p = positions[i];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                fail(who, fmt("vertex %u has a NaN or infinite coordinate", i));
        }
    TriangleMesh m;
    m.path = name;
    m.positions = std::move(positions);
    m.triangles = std::move(tris);
    return m;
}

void save_obj(const TriangleMesh& m, const std::string& path) {
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) fail(path, std::string("cannot open for writing: ") + std::strerror(errno));
    std::fprintf(f, "# Hausdorff Lens: %zu vertices, %zu triangles\n", m.positions.size(), m.triangles.size());
    for (const Vec3& p : m.positions) std::fprintf(f, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    for (const Tri& t : m.triangles)
        std::fprintf(f, "f %llu %llu %llu\n", t[0] + 1ull, t[1] + 1ull, t[2] + 1ull);
    const bool bad = std::ferror(f) != 0;
    if (std::fclose(f) != 0 || bad) fail(path, "write error");
}

}  // namespace hlens
