// The colour map of the per-target maxima (viridis: perceptually uniform, readable on a dark
// background, dark purple at the low end, yellow at the high end). One table, used both for the
// GPU texture and for the colour bar drawn by ImGui, so the two always agree.
#pragma once
#include <array>
#include <cstdint>

namespace hlens::gui {

constexpr int kColormapSize = 256;
using Rgb8 = std::array<uint8_t, 3>;
const std::array<Rgb8, kColormapSize>& colormap_table();
Rgb8 colormap(double t);   // t in [0, 1], clamped; nearest table entry

}  // namespace hlens::gui
