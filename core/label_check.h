// The domain mesh of one target against an independent nearest-feature map (issue 8).
//
// Straub 2007 §3.1: after the sources S_1..S_k are inserted, each domain of T' must be a piece of
// the lower envelope of their region quadratics, labelled by the feature (source, region) whose
// quadratic it is. This checks that by brute force, without the domain mesh's geometry: a grid of
// samples over T', at each the nearest feature found directly in 3D (per source: the face if the
// foot lies inside it, else the nearest edge or corner; see nearest_feature), compared with the label of the
// domain the sample falls in. The debugger's overlay draws the same map; the tests run it after
// every insertion on degenerate pairs.
//
// The tie rule (one rule, also the domain mesh's): two features tie where their quadratics are the
// same polynomial up to rounding (same_quadratic with the mesh's delta(): coplanar sources, an edge shared by two sources, a corner
// shared by several). Over the union of their regions the domain mesh keeps one domain labelled by
// the feature inserted first, so a sample there whose nearest feature is another one of the tie is
// counted as a tie, not a disagreement. So is a sample where the labelled feature itself is as
// near as the nearest one to 1e-9 relative (a difference the quadratics may not resolve: a source
// standing 5e-7 rad off the vertical on an edge in T''s plane has its face 2.6e-13 relative nearer
// than that edge), or where the labelled feature's distance lies within the spread of the
// quadratics of either feature's tie class at the sample (the rule made each class one
// polynomial; the domain mesh holds it by one member's quadratic, which another feature may beat
// or lose to within that spread). Any other difference is a disagreement.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "domain_mesh.h"
#include "regions.h"

namespace hlens {

// Squared distance from p to the triangle abc (frame coordinates) and the region of abc its
// closest point lies in. Degenerate (collinear) triangles are their three edges, which names one
// of the coinciding features; the tie rule makes the name irrelevant where the quadratics agree.
struct NearestFeature {
    double d2 = HUGE_VAL;
    Region region = Region::abc;
};
NearestFeature nearest_feature(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// A source's corners in the target's frame: frame units, z along the target's normal.
std::array<Vec3, 3> source_in_frame(const TargetFrame& frame, const std::array<Vec3, 3>& corners);

struct LabelCheckOptions {
    int resolution = 256;   // samples along the longer side of T''s bounding box
    int border = 2;         // samples this close (in samples) to a change of either map are not compared
    // Inside an insertion (the debugger can stop between its events): the slot of the source being
    // inserted, whose domains are compared against all sources and the others against the sources
    // before it; -1 between insertions.
    int current = -1;
};

struct LabelCheck {
    int width = 0, height = 0;
    Vec2 lo, hi;                   // the sampled box in frame coordinates (row 0 at the top, at hi.y)
    // Per sample, as slot * 8 + region (slot: index into the sources given): the nearest feature
    // (-1: none), the domain's label (-1 outside T', -2 a domain without a source).
    std::vector<int> nearest, domain;
    long samples = 0;              // compared samples
    long ties = 0;                 // of those: another feature of the same quadratic is nearest
    long disagree = 0;             // of those: the label is wrong
    long ignored = 0;              // samples near a change, not compared
    std::string first;             // the first disagreement, described (empty if none)
    Vec2 sample_point(int x, int y) const;
};

// Compares the labels of `mesh` (T' in `frame`) with the nearest features of `sources` (world
// coordinates; `ids` their source indices, in insertion order).
LabelCheck check_labels(const DomainMesh& mesh, const TargetFrame& frame, const std::vector<std::array<Vec3, 3>>& sources,
                        const std::vector<uint32_t>& ids, const LabelCheckOptions& opt = {});

// The tie rule: the quadratic of region `r` of a projected source (null if it has no such region,
// as a degenerate source has fewer); two features' quadratics are one polynomial by
// same_quadratic, with `delta` the largest of the inserted sources' SourceProjection::delta.
const Quadratic2* region_quadratic(const SourceProjection& p, Region r);
// A feature's index in LabelCheck's maps and in tie_classes: slot (position among the sources
// given) * 8 + region.
inline int feature_index(size_t slot, Region r) { return 8 * (int)slot + (int)r; }
// The features that tie through a chain (a ~ b ~ c, though perhaps not a ~ c: the rule is not
// transitive, and merging joins neighbouring domains link by link, so a domain labelled c may
// cover a's region): a class per feature, indexed by feature_index (slot: position in proj), -1
// where a source has no such region. Two features of one class count as a tie.
std::vector<int> tie_classes(const std::vector<SourceProjection>& proj, double delta);

}  // namespace hlens
