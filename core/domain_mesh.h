// The domain mesh of one target triangle T': an attributed half-edge structure over T'.
//
// Straub 2007 §3.1: faces are the domains of d^2 (each carries the quadratic of d^2 there and a
// label naming the source triangle and which of its seven regions), edges are conic or straight
// arcs carrying their equation and a parameterisation, vertices are 2D points. A source triangle
// is inserted by clipping each domain it reaches by its regions and by the conic
// q_domain - q_region = 0, and neighbouring domains whose quadratics are equal are merged.
//
// Faces may have holes (a closed ellipse inside a domain). The plane is the target's own frame
// (see regions.h): T' has unit size, so every tolerance here is relative.
//
// The structure and its queries are in domain_mesh.cpp, the insertion of a source (with the
// merging) in domain_insert.cpp, the clipping primitive (split_face) in domain_split.cpp, and the
// test of where a source can be nearer, which spares the insertion most cuts, in domain_reach.cpp.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "conic.h"
#include "regions.h"

namespace hlens {

struct DomainLabel {
    int32_t source = -1;        // index of the source triangle in B; -1: no source inserted yet
    Region region = Region::abc;
    bool operator==(const DomainLabel& o) const { return source == o.source && region == o.region; }
};

struct Box2 {
    Vec2 lo{HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL};
    void add(Vec2 p) { lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}; hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)}; }
};

enum class ArcKind : uint8_t { TargetBoundary, RegionBoundary, Conic };
const char* arc_kind_name(ArcKind k);

struct Candidate {              // a point where the maximum of d^2 over T' may lie
    Vec2 p;
    double value;               // d^2 there by the adjacent face's quadratic (frame units)
    int vertex = -1;            // a domain vertex, or
    int edge = -1;              // the interior maximum of a curved arc
};

// `cull(face)` for DomainMesh::insert: a non-owning reference to any callable bool(int), or
// nothing. It is called once per face and insertion, so a plain function pointer, not a
// std::function (which would allocate for a lambda with several captures).
class FaceCull {
public:
    FaceCull() = default;
    template <class F, class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, FaceCull>>>
    FaceCull(const F& f) : ctx_(&f), fn_([](const void* c, int face) { return (bool)(*static_cast<const F*>(c))(face); }) {}
    explicit operator bool() const { return fn_ != nullptr; }
    bool operator()(int face) const { return fn_(ctx_, face); }
private:
    const void* ctx_ = nullptr;
    bool (*fn_)(const void*, int) = nullptr;
};

class DomainMesh {
public:
    struct Vertex { Vec2 p; bool alive = true; };
    struct Edge {
        RationalCurve curve;    // the arc is curve(z) for z in [z0, z1]; half-edge 2e runs z0 -> z1
        double z0 = 0, z1 = 1;
        Quadratic2 equation;    // the arc lies on equation = 0
        ArcKind kind = ArcKind::Conic;
        CurveKind curve_kind = CurveKind::Line;
        bool alive = true;
        bool connector = false; // a flat tip's straight link from a vertex to its chord's curve
    };
    struct HalfEdge { int origin = -1, next = -1, prev = -1, face = -1; };
    struct Face {
        Quadratic2 poly;        // d^2 over the domain (frame units); meaningless while `infinite`
        DomainLabel label;
        bool infinite = true;   // d^2 = +inf: no source covers it yet
        std::vector<int> loops; // one half-edge per boundary loop: the outer loop first, then holes
        bool alive = true;
        double max_value = HUGE_VAL;  // max of poly over the face, from the last update_maxima()
        // How far d^2 may step at this domain's edges because the tie rule kept its quadratic
        // where another one, within the allowance, met it (a merge, or a region that tied): a
        // bound of their difference over T'. validate() allows it, at its edges and against d^2;
        // a region winning the face keeps it (give_to_region).
        double tie_slack = 0;
    };
    struct Stats { long splits = 0, merges = 0, snaps = 0, warnings = 0, rehooks = 0, tiny_chords = 0, line_pairs = 0, hole_chords = 0,
                   departures = 0, unfolds = 0, side_change_cuts = 0, dropped_pieces = 0; };

    // Events a caller may watch while a source is inserted (all optional).
    struct Listener {
        std::function<void(int parent, const std::vector<int>& children, const Quadratic2& curve)> on_split;
        std::function<void(int face, DomainLabel old_label, DomainLabel new_label)> on_relabel;
        std::function<void(int kept, int removed)> on_merge;
    };

    explicit DomainMesh(const std::array<Vec2, 3>& ccw_corners);

    // Insert one source (its regions with their quadratics): d^2 := min(d^2, d_T^2).
    // `cull(face)` may return true for faces the source provably cannot reach. With a listener,
    // the paper's insertion, every cut reported; without, only the regions that may be nearer are
    // cut in (domain_reach.cpp). Returns false if the mesh is unchanged (never with a listener).
    bool insert(const SourceProjection& src, FaceCull cull = {}, const Listener* listener = nullptr);

    // Maxima of each face's quadratic on its boundary; returns every candidate point.
    std::vector<Candidate> update_maxima();
    void update_maxima(std::vector<Candidate>& out);  // the same into `out` (its storage reused)

    // The tie rule's allowance: quadratics within same_quadratic(.., .., delta()) are one domain.
    double delta() const { return delta_; }
    // Invariants; returns an empty string when they hold, else a description of the first failure.
    std::string validate(double area_tol = 1e-9) const;

    // Queries used by the solver, the tests and the debugger.
    const std::vector<Vertex>& vertices() const { return vertices_; }
    const std::vector<Edge>& edges() const { return edges_; }
    const std::vector<HalfEdge>& half_edges() const { return half_; }
    const std::vector<Face>& faces() const { return faces_; }
    int outside_face() const { return 0; }
    int num_live_faces() const;
    int num_live_edges() const;
    int num_live_vertices() const;
    double face_area(int f) const;
    double loop_area(int h) const;
    void add_half_edge_area(int h, double& area) const;
    bool point_in_face(int f, Vec2 p) const;
    bool interior_point(int f, Vec2& out) const;     // some point strictly inside face f
    // p within tol of face f's boundary (but for edge `except`, if given)
    bool near_boundary(int f, Vec2 p, double tol, int except = -1) const;
    Box2 face_box(int f) const;                      // bounding box, bulging arcs included
    Box2 cached_face_box(int f);                     // the same, kept until the mesh is edited
    int face_at(Vec2 p) const;                       // the live inner face containing p, or -1
    std::vector<int> face_half_edges(int f) const;   // all half-edges of all loops of f
    std::vector<Vec2> sample_loop(int h, int per_arc) const;  // a polyline along a loop
    Vec2 edge_point(int e, double s) const;          // s in [0,1] along the arc's parameter
    const Stats& stats() const { return stats_; }
    // Drop every kept face box (cached_face_box recomputes them): for a copy that will be split on
    // its own (core/integrals.cpp), whatever the state of the original's cache.
    void forget_face_boxes() { std::fill(box_stamp_.begin(), box_stamp_.end(), 0); }

    // How far (frame units, T' of unit size) a vertex may sit from where its curves meet: crossings
    // this close along a curve are one point (kCluster below), and a vertex polished onto two
    // curves may sit this far off a third. A domain's boundary, and so the domain, may reach this
    // far past its label's region.
    static constexpr double kVertexTolerance = 1e-7;
    // A chord between vertices this close is not inserted (domain_split.cpp, find_chords): what
    // lies across it, a sliver that thin, stays whole on the side of the rest of its face.
    static constexpr double kTinyChord = 1e-11;

    // Drop the dead vertices, edges and faces (the construction's history: on a coarse target among
    // fine sources, 6 of 7 edges) and renumber the live ones in their order; the outside face
    // stays 0. The same domains, arcs and queries; a kept mesh (the statistics' cache) is then
    // about a sixth of the size. False (and the mesh unchanged) if a live element refers to a
    // dead one, which validate() would report.
    bool compact();

    // Building blocks, public for tests.
    struct SplitPiece { int face; int sign; };
    std::vector<SplitPiece> split_face(int f, const Quadratic2& g);
    int split_edge(int e, double z);
    // `since`: only edges beside a face touched after that clock value (0: every edge). Returns
    // true if an edge was removed.
    bool merge_equal_neighbours(const Listener* listener = nullptr, uint64_t since = 0);

private:
    std::vector<Vertex> vertices_;
    std::vector<Edge> edges_;
    std::vector<HalfEdge> half_;
    std::vector<Face> faces_;
    Stats stats_;
    double delta_ = 0;  // the largest rounding of the inserted sources' coordinates (the tie rule's)

    // face_box() is asked for many times per insertion (culling, region tests, split_face), mostly
    // of faces nothing has touched since. Every edit of a face's loops, of the half-edges, arcs or
    // vertices on them, and every relabelling, stamps the face (touch_face: face_stamp_ = ++clock_); a box is kept with
    // the clock it was computed at and used while no later stamp says the face changed.
    uint64_t clock_ = 0;
    std::vector<uint64_t> face_stamp_, box_stamp_;
    std::vector<Box2> box_cache_;
    void touch_face(int f);
    void touch_edge_faces(int e);  // the faces on both sides of edge e

    // edges_[e].alive, packed, and the live edges in increasing order (dead ones dropped lazily):
    // the scans in id order (merging, dissolving, maxima) skip the many dead edges cheaply.
    std::vector<uint8_t> edge_alive_;
    std::vector<int> live_edges_;
    const std::vector<int>& live_edge_ids();
    // The same for the inner faces (ids >= 1) and the vertices: ids only grow, and what dies stays
    // dead, so appending at birth and dropping the dead before a scan keeps them in order.
    std::vector<int> live_faces_, live_vertices_;
    const std::vector<int>& live_face_ids();
    const std::vector<int>& live_vertex_ids();

    // What the geometry queries need of an arc that depends on its curve and [z0, z1] alone,
    // computed when these are set (set_arc_geometry), so the queries only read it. A straight arc
    // has none.
    struct ArcGeometry {
        double segment = 0;            // signed area between the arc and its chord, z0 -> z1
        Box2 bulge;                    // the arc's extreme points in x and in y
        int nturns = 0;                // interior parameters where y turns (for ray crossings)
        double turns[8];
    };
    // The cache of a curved arc's interior maximum for one quadratic (faces rarely change).
    struct EdgeMax { bool cached = false; Quadratic2 poly; double z0 = 0, z1 = 0, value = 0; Vec2 point; };
    // Kept for curved arcs only (most arcs are straight): curved_of_[e] indexes curved_, or is -1.
    struct CurvedArc { ArcGeometry geo; EdgeMax max; };
    std::vector<int> curved_of_;
    std::vector<CurvedArc> curved_;
    const ArcGeometry& arc_geometry(int e) const { return curved_[curved_of_[e]].geo; }
    void set_arc_geometry(int e);

    // A piece of the curve g = 0 to insert into a face (split_face): curve parameters t0..t1,
    // from vertex va to vb (-1, -1 for a closed curve wholly inside).
    struct Chord { CurveComponent comp; double t0, t1; int va, vb; };

    // A face's arcs as the tests of domain_reach.cpp read them (tmp_.face_arcs): ends, edge, and a
    // curved arc's box (bulge included).
    struct FaceArc { Vec2 a, b; int e; bool straight; Box2 box; };

    // Buffers reused across calls so the insertion does not allocate in its inner loops. Their
    // contents never outlive one call; a copy of the mesh starts with empty ones.
    struct Scratch {
        std::vector<int> snapshot, pending, inside, rest, cur, nxt, ids, dropped;
        std::vector<SplitPiece> pieces, hp_pieces;
        std::vector<int> hes, edge_list, zero_list, zverts, fh, fids;
        std::vector<uint64_t> edge_mark, he_mark, seen_mark;  // an entry is marked if it equals its stamp
        uint64_t stamp = 0;
        std::vector<double> side_val, side_n2;     // per half-edge, valid where he_mark is set
        std::vector<int> cycles, outers, holes, merge_hes, live;
        std::vector<double> areas, vval;
        std::vector<int> degree, any_out;
        ConicDecomposition dec;
        std::vector<Vec2> clipped, clip_tmp;
        std::vector<Chord> chords, cand, hole_cands;
        std::vector<SplitPiece> line_first, line_second;  // split_by_line_pair
        std::vector<int> loop_ends;
        std::vector<std::pair<double, int>> pts;
        std::vector<int> verts, es, wedge_cands, thin_cands;
        // insert_chords: each chord's path (flat, with offsets), the face's links before them, and
        // each path end's hook: its wedges and the one taken (rehook_chords retries the others).
        std::vector<int> path_es, path_verts, path_es_off, path_verts_off, links_before;
        std::vector<bool> path_closed;
        std::vector<int> hook_wedges, hook_taken;
        std::vector<uint64_t> cycle_mark;
        int hook_count = 0, force_hook = -1, force_wedge = -1;
        bool recording_hooks = false;
        std::vector<CurveComponent::Piece> arc_pieces;
        std::vector<FaceArc> face_arcs;
        Scratch() = default;
        Scratch(const Scratch&) {}
        Scratch& operator=(const Scratch&) { return *this; }
        uint64_t next_stamp(std::vector<uint64_t>& marks, size_t n);  // a fresh stamp, marks sized >= n
    };
    Scratch tmp_;

    // The farthest a vertex sits from its arcs' curves (validate): where several curves cross
    // within 1e-7 of each other, a vertex on one of them ends a chord of another this far away
    // (domain_split.cpp, on_component; measured on the bunny pair: up to 8.4e-7).
    static constexpr double kOffCurve = 1e-6;
    // A vertex this close to a curve is on it: the precision to which a split (domain_split.cpp)
    // places a vertex on a curve.
    static constexpr double kOnCurve = 1e-8;
    // Crossing points this close along a curve are one point: where several curves meet (the
    // shadow of a vertex shared by many sources), nearly double roots are only accurate to about
    // sqrt(epsilon). (The split's other tolerances are in domain_split.cpp.)
    static constexpr double kCluster = kVertexTolerance;

    template <class Fn> void for_each_half_edge(int f, Fn&& fn) const;  // in face_half_edges() order
    template <class Fn> void for_each_in_loop(int start, Fn&& fn) const;  // one loop, from `start`
    void collect_half_edges(int f, std::vector<int>& out) const;
    bool near_arc(int h, Vec2 p, double tol) const;  // p within tol of half-edge h's arc
    double jump_allowance(int F, int G, Vec2 p, double pos, double pos_sq) const;
    bool sliver_beside_arc(int F, int G, int e, Vec2 m) const;

    // The clipping primitive (domain_split.cpp): split_face_into runs these steps on one SplitCall.
    struct SplitCall;
    // `quad`: where g is a difference of two quadratics, the larger of their quadratic parts'
    // quad_scale(): g's part is exact only to an ulp of it.
    void split_face_into(int f, const Quadratic2& g, std::vector<SplitPiece>& out, double quad = 0, double operands = 0);
    // Face f split where q lies below its polynomial (g = poly - q > 0 there, with both operands'
    // scales for the rounding); returns g.
    Quadratic2 split_where_below(int f, const Quadratic2& q, std::vector<SplitPiece>& out);
    bool split_by_line_pair(int f, const Quadratic2& g, double l2_rounding, std::vector<SplitPiece>& out);
    void split_boundary_where_g_changes_sign(SplitCall& s);
    void split_arc_at_sign_changes(SplitCall& s, int e);
    bool split_at_touching_point(SplitCall& s, int e, const Poly& along);
    static bool at_centre(const Quadratic2& g, Vec2 p);
    bool line_pair(SplitCall& s);
    bool roots_on_the_lines(int e, double z0, double z1) const;
    bool reverse_loops(int a, int b) const;
    bool split_arc_on_the_curve(SplitCall& s, int e);
    bool snap_to_end(SplitCall& s, int e, Vec2 p, double tol);
    bool snap_to_end_on_curve(SplitCall& s, int e, Vec2 p);
    bool pinches_face(const SplitCall& s, int e, Vec2 p, double along_a) const;
    bool past_end(int e, Vec2 p) const;
    bool duplicate_chord(const Chord& c) const;
    void classify_by_side(SplitCall& s);
    void find_chords(SplitCall& s);
    static void hyperbola_as_line_pair(const Quadratic2& g, ConicDecomposition& dec);
    void add_line_pair_centre(SplitCall& s);
    void add_chords_of_component(SplitCall& s, const CurveComponent& comp);
    bool leaves_into_face(int f, int v, Vec2 dir) const;
    void order_coincident_crossings(int f, const CurveComponent& comp, std::vector<std::pair<double, int>>& pts) const;
    bool on_component(const SplitCall& s, const CurveComponent& comp, int v, double t) const;
    bool flat_boundary_edge(const SplitCall& s, int u, int v) const;
    bool foot_in_face(int f, Vec2 q) const;
    bool short_chord_inside(int f, const Chord& c, Vec2 mid) const;
    template <class Near> bool path_stays_near(int from, int to, const Near& near) const;
    bool boundary_hugs_chord(int f, const Chord& c, double tol) const;
    bool thin_beyond_chord(int f, const Chord& c) const;
    bool real_sliver_beside_chord(const SplitCall& s, const Chord& c) const;
    bool chord_past_departure(const SplitCall& s, const Chord& c, double tol, Chord& out) const;
    int loop_of(int f, int v) const;
    void close_hole_crossings(SplitCall& s);
    void add_hole_candidate(const SplitCall& s, const Chord& c, bool short_chord);
    bool chord_inside(const SplitCall& s, const Chord& c) const;
    double path_area(int from, int to, Box2& box) const;
    bool pinched_lobes(const SplitCall& s, int va, int vb, int& ha, int& hb) const;
    void side_range(const SplitCall& s, int from, int to, double& lo, double& hi) const;
    bool once_on_one_loop(int f, int va, int vb, int& ha, int& hb) const;
    void pinch_face(int va, int vb, int ha, int hb);
    bool insert_chords(SplitCall& s);
    bool flat_tip(int v, Vec2 curve_end) const;
    void rebuild_split_faces(SplitCall& s, std::vector<SplitPiece>& out);
    int side_of_piece(SplitCall& s, int face, const std::vector<int>& loop_hes) const;

    // The insertion of a source (domain_insert.cpp): its regions clipped to T' once, then each face.
    struct RegionBoxes { Box2 box[7]; bool empty[7]; bool thin[7] = {}; };  // thin: clip_regions_to_target
    long relabels_ = 0;  // pieces given to a source, ever (insert: did anything change?)
    std::array<Vec2, 3> grown_;  // T' grown by kCluster, for the regions' boxes (grown_target)
    std::array<Vec2, 3> tripled_;  // grown_ three times as large about its centre (clip_regions_to_target)
    static std::array<Vec2, 3> grown_target(const std::array<Vec2, 3>& P);
    void clip_regions_to_target(const SourceProjection& src, RegionBoxes& out);
    static bool region_box_misses(const Box2& b, const RegionBoxes& boxes, size_t k);
    static bool region_box_inside(const Box2& b, const SourceRegion& reg);
    void insert_into_face(int F, const SourceProjection& src, const RegionBoxes& boxes, const Listener* L);
    bool thin_region_reaches(int F, const SourceProjection& src, const RegionBoxes& boxes);
    // Without a listener (domain_reach.cpp): the regions that may be nearer on F, and the tests.
    void insert_where_nearer(int F, const SourceProjection& src, const RegionBoxes& boxes);
    bool region_nowhere_nearer(int F, const SourceRegion& reg, const Box2& rbox);
    // Face F keeps its quadratic where a region's `q` ties with it: its edges with that region's
    // other pieces may step by their difference.
    void note_tie(int F, const Quadratic2& q) {
        faces_[F].tie_slack = std::max(faces_[F].tie_slack, unit_box_bound(faces_[F].poly - q));
    }
    void claim_cracks(const SourceProjection& src, unsigned may_win);
    void set_aside_dropped_pieces(const SourceProjection& src, unsigned may_win);
    void claim_crack(int P, const SourceProjection& src, unsigned may_win);
    void claim_sliver(int P, const SourceProjection& src, unsigned may_win);
    size_t leftover_region(int P, const SourceProjection& src, unsigned may_win, size_t last);
    bool long_arc_point(int f, Vec2& out) const;
    // A point of face f stepped `step` times min(1, len) to the inside from the middle of
    // half-edge h (interior_point, long_arc_point); false if that is not in f.
    bool point_beside(int f, int h, double len, double step, Vec2& out) const;
    unsigned regions_holding_corners(int P, const SourceProjection& src, unsigned mask) const;
    unsigned regions_holding_piece(int P, const SourceProjection& src, unsigned mask) const;
    bool arcs_nowhere_nearer(const SourceRegion& reg, const Quadratic2& g, const Box2& b) const;
    bool lines_nowhere_nearer(const SourceRegion& reg, const Quadratic2& g) const;

    void cut_by_region(const SourceRegion& reg, const Listener* L);
    void apply_region(int P, const SourceProjection& src, const SourceRegion& reg, const Listener* L);
    void give_to_region(int P, const SourceProjection& src, const SourceRegion& reg, const Listener* L);
    bool unfold_needles(uint64_t since);
    bool unfold_at(int f, int h);
    bool tiny_arc(int h) const;
    void cut_needle_base(int f, std::array<int, 4>& cycle, int n, int first, int last, int loser, ArcKind kind);
    bool nearly_straight(int e) const;
    bool straight_face_range(int f, const Quadratic2& g, const Box2& b, double& lo, double& hi) const;
    void report_split(const Listener* L, int parent, const std::vector<SplitPiece>& pieces, const Quadratic2& curve);

    int add_vertex(Vec2 p);
    int add_edge(const RationalCurve& c, double z0, double z1, const Quadratic2& eq, ArcKind kind, CurveKind ck);
    int straight_edge(Vec2 a, Vec2 b, ArcKind kind) {  // the segment a -> b as an edge
        return add_edge(segment_curve(a, b), 0, 1, line_through(a, b), kind, CurveKind::Line);
    }
    int target(int h) const { return half_[h ^ 1].origin; }
    Vec2 he_point(int h, double s) const;            // s in [0,1] along the half-edge's direction
    Vec2 out_tangent(int h) const;                   // direction leaving origin(h)
    int loop_crossings(int start, Vec2 p) const;      // ray crossings of one loop (parity: inside)
    int outer_across(int hole, const std::vector<int>& cycles, const std::vector<int>& outers) const;  // a lens's piece
    void add_piece(int reuse, bool first, int loop, std::vector<int>& fids);  // rebuild_faces
    void add_lost_crossing(const CurveComponent& line, std::vector<std::pair<double, int>>& pts) const;
    bool noise_chord_hugged(int f, const CurveComponent& comp, const Chord& c) const;
    int find_wedge(const std::vector<int>& hes, int face, int v, Vec2 dir, Vec2 dir2, bool dir_loose);
    bool loose_tangent(int h) const;
    bool thin_loop(int h, size_t guard) const;
    int past_connector(int h) const;
    bool sides_part_at(const SplitCall& s, int va, int vb) const;
    double certain_side(const SplitCall& s) const;
    bool straight_chord(int va, int vb, Chord& out) const;
    int hook_wedge(int hin);
    bool mixed_cycle(const SplitCall& s);
    void hook_paths(int face, const std::vector<int>& hes, int force_hook, int force_wedge);
    bool rehook_chords(SplitCall& s);
    void undo_chords(int f, size_t nv, size_t ne);
    bool side_change_chords(const SplitCall& s, std::vector<Chord>& out) const;
    void cut_at_side_changes(SplitCall& s, size_t nv, size_t ne);
    void insert_path(int face, const std::vector<int>& hes, const std::vector<int>& verts, const std::vector<int>& path_edges, bool closed_new);
    void rebuild_faces(const std::vector<int>& hes, int reuse, std::vector<int>& fids, bool split = false);
    void remove_edge(int e);
    void drop_edge(int e);  // marks edge e removed, its half-edges in no face (no splicing)
    double straight_foot(int e, Vec2 p) const;  // the parameter z of p's foot on straight arc e
    bool detach_orphan_loops(uint64_t since, const Listener* listener);
    bool split_orphan_at_waist(int f, int h0, int& first, int& second);
    int finite_face_across(int f, int he) const;
    int face_across_longest(int f, const std::vector<int>& hs, int i, int cnt) const;
    void dissolve_collinear_vertices();
    double edge_max(int e, const Quadratic2& q, Vec2* where);
    void replace_loop_start(int face, int from, int to);
    double edge_max_uncached(int e, const Quadratic2& q, Vec2* where) const;
    bool polish_on_two(const Quadratic2& f, const Quadratic2& g, Vec2& p) const;
    bool polish_along_arc(const Quadratic2& g, const Quadratic2& eq, const RationalCurve& curve, double lo, double hi, double& z,
                          Vec2& p) const;
    bool polish_arc_max(const Quadratic2& q, const Quadratic2& g, Vec2& p) const;
};

template <class Fn>
void DomainMesh::for_each_in_loop(int start, Fn&& fn) const {
    int h = start, guard = 0;
    do {
        fn(h);
        h = half_[h].next;
        if (++guard > 1000000) break;
    } while (h != start);
}

template <class Fn>
void DomainMesh::for_each_half_edge(int f, Fn&& fn) const {
    for (int start : faces_[f].loops) for_each_in_loop(start, fn);
}

// Largest value of q along the arc curve(z), z in [z0, z1], over interior critical points only.
// Returns -inf if there are none.
double arc_interior_max(const RationalCurve& c, double z0, double z1, const Quadratic2& q, double* zmax);

}  // namespace hlens
