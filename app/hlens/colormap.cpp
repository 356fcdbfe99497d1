#include "colormap.h"

#include <algorithm>
#include <cmath>

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

}  // namespace hlens::gui
