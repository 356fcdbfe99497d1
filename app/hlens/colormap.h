// The colour map of the per-target maxima (viridis: perceptually uniform, readable on a dark
// background, dark purple at the low end, yellow at the high end). One table, used both for the
// GPU texture and for the colour bar drawn by ImGui, so the two always agree.
#pragma once
#include <array>
#include <cstdint>

#include <hlens/domain_mesh.h>

namespace hlens::gui {

constexpr int kColormapSize = 256;
using Rgb8 = std::array<uint8_t, 3>;
const std::array<Rgb8, kColormapSize>& colormap_table();
Rgb8 colormap(double t);   // t in [0, 1], clamped; nearest table entry

// A triangle whose exact maximum is not yet known is drawn "not yet exact": neutral grey in
// diagonal stripes of these two greys (no colour of the map is grey), never on the colour scale.
constexpr float kNotExactGrey[2] = {0.62f, 0.46f};
// The stripes' period in pixels for a font size (so they follow DPI scaling).
inline float hatch_period(float font_px) { return font_px * 0.6f < 6.0f ? 6.0f : font_px * 0.6f; }

// The colour of a domain label (ImU32) in the domain view, the graph and the overlay.
unsigned domain_label_colour(const DomainLabel& l, bool infinite);

}  // namespace hlens::gui
