#include "event_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hlens::gui {

std::string label_text(const DomainLabel& l, bool infinite) {
    if (infinite || l.source < 0) return "no source (d^2 = inf)";
    return "T " + std::to_string(l.source) + ", " + region_name(l.region);
}

std::string vec_text(Vec2 p) {
    char b[64];
    std::snprintf(b, sizeof b, "(%.4g, %.4g)", p.x, p.y);
    return b;
}

std::string event_summary(const Event& e) {
    char b[256];
    std::string t;
    switch (e.kind) {
    case EventKind::TargetBegun: return "the target's frame is set up";
    case EventKind::VoxelVisited:
    case EventKind::VoxelCulled:
        std::snprintf(b, sizeof b, "voxel %lld, distance %.6g", e.voxel, e.distance);
        return b;
    case EventKind::SourceChosen:
        std::snprintf(b, sizeof b, "source T %d from voxel %lld, distance %.6g", e.source, e.voxel, e.distance);
        return b;
    case EventKind::SourceCulled:
        std::snprintf(b, sizeof b, "source T %d, distance %.6g", e.source, e.distance);
        return b;
    case EventKind::RegionsProjected:
        std::snprintf(b, sizeof b, "source T %d: %zu regions clipped to T'", e.source, e.regions.size());
        return b;
    case EventKind::DomainSplit:
        t = "face " + std::to_string(e.face) + " -> {";
        for (size_t i = 0; i < e.faces.size(); ++i) t += (i ? ", " : "") + std::to_string(e.faces[i]);
        return t + "} by " + conic_type_name(decompose_conic(e.curve).type);
    case EventKind::DomainCreated:
        return "face " + std::to_string(e.face) + ": " + label_text(e.old_label, e.old_label.source < 0) + " -> " +
               label_text(e.label, false);
    case EventKind::DomainMerged:
        return "face " + std::to_string(e.face) + " absorbed face " + std::to_string(e.other);
    case EventKind::ArcMaximum:
    case EventKind::MaximumRaised:
    case EventKind::TargetFinished:
        std::snprintf(b, sizeof b, "at %s, d^2 %.6g (d %.6g)", vec_text(e.point).c_str(), e.value, std::sqrt(std::max(0.0, e.value)));
        return b;
    case EventKind::SearchRadiusShrunk:
        std::snprintf(b, sizeof b, "radius %.6g", e.radius);
        return b;
    }
    return "";
}

}  // namespace hlens::gui
