// One target's domain mesh cut at a tolerance T: inside each domain d^2 is one quadratic P, so
// d = T is the conic P = T^2 (frame units), and the construction's own clipping (split_face on a
// copy of the mesh, as core/integrals.cpp's area above a level does) gives the pieces above and
// below it, their exact areas (face_area_exact) and the arcs of the curve d = T itself.
#pragma once
#include <vector>

#include <hlens/domain_mesh.h>
#include <hlens/regions.h>

namespace hlens::gui {

struct ToleranceCut {
    double t = -1;                    // the tolerance (world units)
    double area = 0, area_above = 0;  // world units: the target's area and where d > T
    struct Piece {
        std::vector<Vec2> outer;      // outer loop, frame coordinates
        std::vector<int> tris;        // its triangulation (index triples)
        DomainLabel label;
        bool infinite = false;        // no source covers it yet (inside a construction)
        bool above = false;           // d > T on it
    };
    std::vector<Piece> pieces;        // every live face of the cut mesh, largest outer loop first
    std::vector<std::vector<Vec2>> curve;   // the arcs of d = T, sampled (frame coordinates)
    std::vector<Vec3> samples;        // points on those arcs (world coordinates), a few per arc
};

// The cut of `m` (the domain mesh of the target with frame `fr`, possibly mid-construction:
// domains no source covers yet are left out) at distance T >= 0.
ToleranceCut cut_at_tolerance(const DomainMesh& m, const TargetFrame& fr, double T);

}  // namespace hlens::gui
