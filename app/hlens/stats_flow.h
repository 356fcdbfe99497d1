// The exact surface statistics in the debugger: when they are computed (StatsJob, on request),
// and what the colour map shows per triangle (the exact maximum, or the mean or RMS distance
// over the triangle once the statistics are known).
#pragma once
#include <vector>

#include "app_state.h"

namespace hlens::gui {

// Acts on the statistics' requests (req.stats_start / stats_cancel), takes the job's outcome
// (for the current meshes only) and starts the job when the statistics are wanted and missing.
// Returns true when new statistics arrived.
bool update_stats(AppState& s, const Requests& req, StatsJob& job);

// Per triangle of mesh d, the value the colour map shows (s.colour_by): the exact maximum (-1:
// not yet exact), or the mean / RMS distance over the triangle; while the statistics are not
// known, the exact maxima.
std::vector<double> colour_values(const AppState& s, int d);

// "Export map" (and --export-errors): the error maps of both directions as hlens-cli
// --export-errors writes them (report.h, write_error_maps), into s.errors_path; waits for the
// statistics (starting them) when they are not known yet. False: the export failed.
bool export_error_maps(AppState& s);

// Mesh d against the tolerance T (s.tolerance >= 0): the triangles whose exact maximum exceeds T
// (outlined in the 3D view) and their area, a bound of the area above T; and that area itself
// once the statistics were computed at T (else -1).
struct MeshAbove {
    size_t triangles = 0;
    double bound = 0, area = 0;       // the triangles' area, the mesh's area
    double exact = -1, fraction = -1; // from the statistics at T
};
MeshAbove mesh_above(const AppState& s, int d);

}  // namespace hlens::gui
