// The built-in cases. Every B is one triangle (or one triangle twice), so d(p, B) is a convex
// function of p and its maximum over a triangle of A lies at a vertex of A:
//     h(A,B) = max over the vertices v of A of d(v, B).
// Each case lists those vertex distances. T0 is the unit right triangle (0,0,0),(1,0,0),(0,1,0).
#include "cases.h"

#include <cmath>

#include <hlens/mesh_io.h>

namespace hlens::gui {

const std::vector<BuiltinCase>& builtin_cases() {
    static const std::vector<BuiltinCase> c = {
        {"parallel", "A = T0, B a large triangle in the plane z = 1 + eps"},
        {"coplanar_overlap", "A = T0 moved by 0.5 in x (and eps in z), B = T0: overlapping"},
        {"shared_edge", "A = T0, B = (1,0,0),(0,1,0),(0,0,1) moved by eps along its normal"},
        {"shared_vertex", "A = T0, B = (0,0,0),(-1,0,1),(0,-1,1) moved by (-eps,-eps,0)"},
        {"perpendicular", "A = T0, B a large triangle in the plane y = 0.25 + eps, crossing A"},
        {"sliver", "A = (0,0,0),(1,0,0),(0.5,eps,0) (collinear at eps = 0), B large at z = 1"},
        {"duplicated", "A = T0 moved by eps in z, B = T0 twice"},
        {"target_in_source_plane", "A = (2,0,0),(3,0,0),(2,1,0) moved by eps in z, B = T0"},
    };
    return c;
}

bool make_case(const std::string& name, double eps, TriangleMesh& a, TriangleMesh& b, double& hand) {
    std::vector<Vec3> pa, pb;
    std::vector<Tri> ta = {{0, 1, 2}}, tb = {{0, 1, 2}};
    const Vec3 t0[3] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    if (name == "parallel") {
        // Every vertex of A projects into B (B covers x, y >= -1, x + y <= 2): all at 1 + eps.
        pa = {t0[0], t0[1], t0[2]};
        pb = {Vec3(-1, -1, 1 + eps), Vec3(3, -1, 1 + eps), Vec3(-1, 3, 1 + eps)};
        hand = 1 + eps;
    } else if (name == "coplanar_overlap") {
        // In the plane: (0.5,0) lies in T0: 0. (1.5,0): the foot on the hypotenuse x + y = 1 is
        // (1.25,-0.25), off the segment, so the nearest point is the corner (1,0): 0.5. (0.5,1): the
        // foot (0.25,0.75) is on the hypotenuse: 0.5/sqrt2. Lifting by eps adds eps^2 under the root:
        // h = sqrt(0.25 + eps^2).
        pa = {Vec3(0.5, 0, eps), Vec3(1.5, 0, eps), Vec3(0.5, 1, eps)};
        pb = {t0[0], t0[1], t0[2]};
        hand = std::sqrt(0.25 + eps * eps);
    } else if (name == "shared_edge") {
        // B lies in x + y + z = 1 (unit normal n = (1,1,1)/sqrt3), moved by eps n. The origin projects
        // to B's centroid (+ eps n): 1/sqrt3 + eps; (1,0,0) and (0,1,0) project to B's corners: eps.
        // h = 1/sqrt3 + eps.
        const double k = eps / std::sqrt(3.0);
        pa = {t0[0], t0[1], t0[2]};
        pb = {Vec3(1 + k, k, k), Vec3(k, 1 + k, k), Vec3(k, k, 1 + k)};
        hand = 1 / std::sqrt(3.0) + eps;
    } else if (name == "shared_vertex") {
        // B = {(-eps - s, -eps - t, s + t) : s, t >= 0, s + t <= 1}. For (1,0,0):
        // |.|^2 = (1 + eps + s)^2 + (eps + t)^2 + (s + t)^2, least at s = t = 0: (1+eps)^2 + eps^2;
        // (0,1,0) the same by symmetry; the origin: 2 eps^2. h = sqrt((1 + eps)^2 + eps^2).
        pa = {t0[0], t0[1], t0[2]};
        pb = {Vec3(-eps, -eps, 0), Vec3(-1 - eps, -eps, 1), Vec3(-eps, -1 - eps, 1)};
        hand = std::sqrt((1 + eps) * (1 + eps) + eps * eps);
    } else if (name == "perpendicular") {
        // B in the plane y = 0.25 + eps covers x, z >= -1, x + z <= 2: every vertex of A projects
        // into it. Distances |y - 0.25 - eps|: 0.25 + eps, 0.25 + eps, 0.75 - eps. h = 0.75 - eps
        // (eps < 0.25).
        pa = {t0[0], t0[1], t0[2]};
        pb = {Vec3(-1, 0.25 + eps, -1), Vec3(3, 0.25 + eps, -1), Vec3(-1, 0.25 + eps, 3)};
        hand = 0.75 - eps;
    } else if (name == "sliver") {
        // The three vertices of A project into B (large, z = 1): all at 1. h = 1.
        pa = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, eps, 0)};
        pb = {Vec3(-1, -1, 1), Vec3(3, -1, 1), Vec3(-1, 3, 1)};
        hand = 1;
    } else if (name == "duplicated") {
        // B is T0 twice (the union is T0); A is T0 lifted by eps: every vertex at eps. h = eps.
        pa = {Vec3(0, 0, eps), Vec3(1, 0, eps), Vec3(0, 1, eps)};
        pb = {t0[0], t0[1], t0[2]};
        tb = {{0, 1, 2}, {0, 1, 2}};
        hand = eps;
    } else if (name == "target_in_source_plane") {
        // In the plane: (2,0) -> corner (1,0): 1. (3,0) -> (1,0): 2. (2,1): the foot on x + y = 1 is
        // (1,0), a corner: sqrt2. The lift eps adds eps^2: h = sqrt(4 + eps^2).
        pa = {Vec3(2, 0, eps), Vec3(3, 0, eps), Vec3(2, 1, eps)};
        pb = {t0[0], t0[1], t0[2]};
        hand = std::sqrt(4 + eps * eps);
    } else {
        return false;
    }
    a = make_mesh(pa, ta, "case:" + name + " A");
    b = make_mesh(pb, tb, "case:" + name + " B");
    return true;
}

}  // namespace hlens::gui
