#include "tolerance_cut.h"

#include <algorithm>
#include <cmath>

#include "integrals.h"
#include "stepper.h"

namespace hlens::gui {

namespace {

// Splits every face of `m` that straddles P = t2; marks the faces above it (per face id) and
// collects the new arcs on the level (their equation: P - t2 normalised, as split_face keeps it).
void split_at_level(DomainMesh& m, double t2, std::vector<char>& above, std::vector<int>& curve_edges) {
    const size_t nf = m.faces().size();
    above.assign(nf, 0);
    for (size_t f = 1; f < nf; ++f) {
        const DomainMesh::Face& F = m.faces()[f];
        if (!F.alive || F.infinite) continue;
        const Interval r = convex_range(F.poly, m.face_box((int)f));
        if (r.hi <= t2) continue;
        if (r.lo > t2) {
            above[f] = 1;
            continue;
        }
        Quadratic2 g = F.poly;
        g.f -= t2;
        const Quadratic2 normalised = g * (1.0 / g.scale());
        const size_t e0 = m.edges().size();
        m.forget_face_boxes();   // (integrals.cpp: split_face trusts the box cache)
        for (const DomainMesh::SplitPiece& piece : m.split_face((int)f, g)) {
            if ((size_t)piece.face >= above.size()) above.resize(piece.face + 1, 0);
            above[piece.face] = piece.sign > 0;
        }
        for (size_t e = e0; e < m.edges().size(); ++e) {
            const Quadratic2& q = m.edges()[e].equation;
            if (m.edges()[e].alive && (q - normalised).scale() == 0) curve_edges.push_back((int)e);
        }
    }
    above.resize(m.faces().size(), 0);
}

}  // namespace

ToleranceCut cut_at_tolerance(const DomainMesh& m, const TargetFrame& fr, double T) {
    ToleranceCut c;
    c.t = T;
    DomainMesh copy(m);
    copy.forget_face_boxes();
    const double t = T / fr.scale, s2 = fr.scale * fr.scale;
    std::vector<char> above;
    std::vector<int> curve_edges;
    split_at_level(copy, t * t, above, curve_edges);
    std::vector<std::pair<double, int>> order;   // (-|outer loop area|, face)
    for (size_t f = 1; f < copy.faces().size(); ++f) {
        const DomainMesh::Face& F = copy.faces()[f];
        if (!F.alive || F.loops.empty()) continue;
        order.push_back({-std::fabs(copy.loop_area(F.loops[0])), (int)f});
        if (F.infinite) continue;
        const double a = face_area_exact(copy, (int)f).value * s2;
        c.area += a;
        if (above[f]) c.area_above += a;
    }
    std::sort(order.begin(), order.end());
    for (const auto& [key, f] : order) {
        ToleranceCut::Piece p;
        face_polygon(copy, f, p.outer, p.tris);
        p.label = copy.faces()[f].label;
        p.infinite = copy.faces()[f].infinite;
        p.above = above[f] && !p.infinite;
        c.pieces.push_back(std::move(p));
    }
    for (int e : curve_edges) {
        std::vector<Vec2> pts;
        for (int i = 0; i <= 24; ++i) pts.push_back(copy.edge_point(e, i / 24.0));
        c.curve.push_back(std::move(pts));
        if (c.samples.size() < 60)
            for (double u : {0.25, 0.5, 0.75}) c.samples.push_back(fr.to_world(copy.edge_point(e, u)));
    }
    return c;
}

}  // namespace hlens::gui
