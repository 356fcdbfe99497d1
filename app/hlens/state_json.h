// The state behind a headless picture (--screenshot), printed as one JSON line on stdout: what the
// tests check against hlens-cli and against the picture's pixels.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app_state.h"
#include "camera.h"
#include "scene.h"

namespace hlens::gui {

// Sample pixels of the measured mesh for the headless state: up to `per_kind` triangles not yet
// exact and as many exact ones, each with a pixel (image coordinates, from the top-left) and a
// radius `clear` >= 2 such that the square of that radius around it shows only that triangle: no
// edge of it (lines are kept 2 pixels away), no other mesh in front, no panel, witness marker or
// hint text over it. The triangles with the largest such squares first (radius up to `max_clear`).
// "value" is the value the colour map shows there (max, mean or RMS; null: not yet exact).
// `ids`: the triangle of each pixel of the view (Picker::triangle_ids).
std::string probes_json(const AppState& s, const std::vector<int>& ids, const int vp[4], int fb_h, const glm::mat4& mvp,
                        const Scene& scene, float fbs, int max_clear, int per_kind);

// The whole state, one JSON object; `vp`: the 3D view's viewport (GL convention), `probes`: from
// probes_json ("" for none).
std::string state_json(const AppState& s, const Camera& cam, const Vec3& origin, int fb_w, int fb_h, const int vp[4],
                       const std::string& probes);

}  // namespace hlens::gui
