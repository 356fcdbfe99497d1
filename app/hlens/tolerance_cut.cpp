#include "tolerance_cut.h"

#include <algorithm>
#include <cmath>

#include <hlens/integrals.h>
#include "stepper.h"

namespace hlens::gui {

namespace {

// Splits every face of `m` that straddles P = t2 (core's split_at_level); marks the faces above
// it (per face id) and collects the new arcs on the level: the edges a split made whose equation is
// the face's P - t2 (normalised, as split_face keeps it).
void split_at_level(DomainMesh& m, double t2, std::vector<char>& above, std::vector<int>& curve_edges) {
    above.assign(m.faces().size(), 0);
    size_t scanned = m.edges().size();
    hlens::split_at_level(m, t2, [&](int f, bool up, bool split) {
        if ((size_t)f >= above.size()) above.resize(f + 1, 0);
        above[f] = up;
        if (!split) return;
        Quadratic2 g = m.faces()[f].poly;  // a piece keeps the polynomial of the face it came from
        g.f -= t2;
        const Quadratic2 normalised = g * (1.0 / g.scale());
        for (; scanned < m.edges().size(); ++scanned) {
            const Quadratic2& q = m.edges()[scanned].equation;
            if (m.edges()[scanned].alive && (q - normalised).scale() == 0) curve_edges.push_back((int)scanned);
        }
    });
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
