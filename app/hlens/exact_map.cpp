#include "exact_map.h"

#include <algorithm>
#include <cmath>

#include "stats_flow.h"

namespace hlens::gui {

namespace {

// The colour map's range: the values shown (exact maxima known so far, never a bound; or the
// means or RMS). It follows them while the user has not moved it (or always, with `reset`).
void refresh_range(AppState& s, int d, const std::vector<double>& values, bool reset) {
    ColourRange& r = s.range[d];
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (double v : values)
        if (v >= 0) lo = std::min(lo, v), hi = std::max(hi, v);
    const bool follow = reset || !r.valid || (r.lo == r.data_lo && r.hi == r.data_hi);
    r.valid = lo <= hi;
    if (!r.valid) return;
    r.data_lo = (float)lo;
    r.data_hi = (float)hi;
    if (follow) {
        r.lo = r.data_lo;
        r.hi = r.data_hi;
    }
}

}  // namespace

void show_values(AppState& s, Scene& scene, int d, bool reset) {
    const std::vector<double> v = colour_values(s, d);
    scene.set_values(d, v);
    scene.set_maxima(d, s.exact[d].value);
    refresh_range(s, d, v, reset);
}

void init_exact(AppState& s, int d) {
    const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
    ExactMap& m = s.exact[d];
    m = ExactMap{};
    m.value.assign(r.target_max.size(), -1.0);
    for (size_t t = 0; t < m.value.size(); ++t)
        if (t < r.target_exact.size() && r.target_exact[t] && r.target_max[t] >= 0) {
            m.value[t] = r.target_max[t];
            ++m.exact;
        }
}

bool set_exact(AppState& s, int d, uint32_t t, double v) {
    ExactMap& m = s.exact[d];
    if (t >= m.value.size() || m.value[t] >= 0 || !(v >= 0)) return false;
    m.value[t] = v;
    ++m.exact;
    return true;
}

double target_value(const AppState& s, int d, long t, bool& exact) {
    const OneSidedResult& r = d == 0 ? s.result.a_to_b : s.result.b_to_a;
    exact = s.exact[d].known(t);
    if (exact) return s.exact[d].value[t];
    return t >= 0 && (size_t)t < r.target_max.size() ? r.target_max[t] : NAN;
}

}  // namespace hlens::gui
