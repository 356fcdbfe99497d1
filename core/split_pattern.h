// How a piece of a target (a sub-triangle) is split where the bounds over it do not yet drop or
// close it: by the cascade (cascade.cpp) and by the confirmation of the top (confirm_top.cpp).
// Design notes, "Beyond the paper: exact and fast".
#pragma once

#include <array>

#include "vec.h"

namespace hlens {

// The children of a triangle with corners S, as corners taken from {S0, S1, S2, m0, m1, m2}, where
// index 3 + a is the midpoint of edge (a, a + 1): four, by the edges' midpoints; or, where the
// triangle is thin (its height over its longest edge below a quarter of that edge: a needle, or a
// segment where two corners of a degenerate target coincide), two, by its longest edge's midpoint,
// which shrinks it as the four do at half the cost. A needle's four children are needles, three of
// them over the same half of it: halving it k times took up to 4^k pieces (generate_pairs6.py
// "sliver_strip" 58161, generate_pairs10.py "cad_plate" 498 in the confirmation; generate_pairs11.py
// "slivers_strip" 1023 in the cascade: 2,047 pieces of one needle target solved, 452 distinct).
// Two corners the same point: the segment's halves, each with a corner twice (longest-edge
// bisection would keep a child as long as its parent, the third corner lying on the edge it halves).
struct SplitPattern {
    int count;                                 // 2 or 4
    std::array<std::array<int, 3>, 4> child;  // indices into {S0, S1, S2, m0, m1, m2}
};

inline SplitPattern split_pattern(const std::array<Vec3, 3>& S) {
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        if (S[a] == S[b]) return {2, {{{a, a, 3 + c}, {3 + c, 3 + c, c}}}};  // 3 + c: edge (c, a)'s midpoint
    }
    int i = 0;
    double longest = 0;
    for (int k = 0; k < 3; ++k)
        if (const double l = norm(S[(k + 1) % 3] - S[k]); l > longest) longest = l, i = k;
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    if (norm(cross(S[j] - S[i], S[k] - S[i])) < 0.25 * longest * longest) return {2, {{{k, i, 3 + i}, {k, 3 + i, j}}}};
    return {4, {{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}}};
}

}  // namespace hlens
