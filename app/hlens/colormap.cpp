#include "colormap.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

namespace hlens::gui {

namespace {
// Polynomial fit of matplotlib's viridis (degree 6 per channel), accurate to about 1%.
double channel(const double c[7], double t) {
    double v = c[6];
    for (int i = 5; i >= 0; --i) v = v * t + c[i];
    return v;
}
std::array<Rgb8, kColormapSize> build() {
    static const double r[7] = {0.2777273272234177, 0.1050930431085774, -0.3308618287255563, -4.634230498983486,
                                6.228269936347081, 4.776384997670288, -5.435455855934631};
    static const double g[7] = {0.005407344544966578, 1.404613529898575, 0.214847559468213, -5.799100973351585,
                                14.17993336680509, -13.74514537774601, 4.645852612178535};
    static const double b[7] = {0.3340998053353061, 1.384590162594685, 0.09509516302823659, -19.33244095627987,
                                56.69055338051249, -65.35303263337234, 26.3124352495832};
    std::array<Rgb8, kColormapSize> table;
    for (int i = 0; i < kColormapSize; ++i) {
        double t = double(i) / (kColormapSize - 1);
        auto q = [](double v) { return (uint8_t)std::lround(std::clamp(v, 0.0, 1.0) * 255); };
        table[i] = {q(channel(r, t)), q(channel(g, t)), q(channel(b, t))};
    }
    return table;
}
}  // namespace

const std::array<Rgb8, kColormapSize>& colormap_table() {
    static const std::array<Rgb8, kColormapSize> table = build();
    return table;
}

Rgb8 colormap(double t) {
    if (!(t >= 0)) t = 0;   // NaN too
    if (t > 1) t = 1;
    return colormap_table()[(size_t)std::lround(t * (kColormapSize - 1))];
}

// A colour per label: the source's index hashed to a hue, the region varying lightness and
// saturation (face region light, edge regions middle, vertex regions dark).
unsigned domain_label_colour(const DomainLabel& l, bool infinite) {
    if (infinite || l.source < 0) return IM_COL32(70, 72, 80, 255);
    // Golden-ratio hues: consecutive indices (often neighbours in a mesh) get far-apart hues.
    float hue = (float)std::fmod(0.13 + 0.6180339887498949 * (double)l.source, 1.0);
    const int r = (int)l.region;
    static const float kSat[7] = {0.35f, 0.55f, 0.55f, 0.55f, 0.72f, 0.72f, 0.72f};
    static const float kVal[7] = {0.96f, 0.84f, 0.76f, 0.68f, 0.58f, 0.50f, 0.42f};
    static const float kHue[7] = {0.0f, -0.04f, 0.0f, 0.04f, -0.04f, 0.0f, 0.04f};
    const float s = kSat[r], v = kVal[r];
    hue += kHue[r] + 1.0f;
    hue -= std::floor(hue);
    float rr, gg, bb;
    ImGui::ColorConvertHSVtoRGB(hue, s, v, rr, gg, bb);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(rr, gg, bb, 1.0f));
}

}  // namespace hlens::gui
