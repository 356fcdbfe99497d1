// Integrals of the squared distance over the domains of a target's domain mesh.
//
// Straub 2007, §5 ("future work"): the mean squared distance is the integral of d^2 over the
// domains; issue 9 asks for the area, the integral of d^2, the integral of d and the area where
// d > t, per domain. Every domain is a region of the target's plane bounded by straight and conic
// arcs, and d^2 is one quadratic P on it, so by Green's theorem
//     integral over F of dQ/dx dA = integral along the boundary of F of Q dy
// (loops oriented with F on their left, as the domain mesh keeps them). With Q = x (area),
// Q = the x-antiderivative of P (integral of d^2), Q = an x-antiderivative of sqrt(P) in closed
// form (integral of d), each integral over a face is a sum of line integrals along its arcs.
//
//  - Straight arcs: Q along a segment is a polynomial of degree <= 3 (area, d^2): Gauss-Legendre
//    with 3 points is exact (to rounding).
//  - Conic arcs p(z) = N(z)/w(z): Q(p(z)) y'(z) is a rational function, N-degree 8 over w^5. It is
//    integrated by 16-point Gauss-Legendre with a certified remainder (Trefethen, "Is Gauss
//    quadrature better than Clenshaw-Curtis?", SIAM Review 2008, Thm 4.5): an integrand analytic
//    in the Bernstein ellipse E_rho with |f| <= M there has |error| <= 64 M / (15 (rho^2-1) rho^32).
//    M is bounded from the coefficients of N and the distance of the roots of w to E_rho; an arc
//    whose bound exceeds the tolerance is halved, so every conic-arc integral has a stated
//    error bound (returned), far below 1e-12 of the result on every mesh tried.
//  - The integral of d: the antiderivative of sqrt(P) along the principal axis of P is closed
//    form (sqrt and asinh), but it is not analytic where P = 0 touches the arc, so the line
//    integrals use adaptive Gauss-Kronrod (7/15 points) to 1e-11 relative per face; the error
//    returned is the sum of |K15 - G7| over the final pieces, an a-posteriori estimate, not a proof.
//  - The area where d > t: Green's theorem again, along the face's arcs where P > t^2 and the conic
//    P = t^2 inside the face (level_area.cpp), the face left as it is.
//
// All values here are in the target's frame units (TargetFrame::scale converts: areas by scale^2,
// the integral of d^2 by scale^4, the integral of d by scale^3).
#pragma once
#include <functional>
#include <vector>

#include "domain_mesh.h"

namespace hlens {

// A value and a bound on its quadrature error (rounding not included).
struct Integral {
    double value = 0, error = 0;
    Integral& operator+=(const Integral& o) { value += o.value; error += o.error; return *this; }
};

// Integral over face f of the polynomial P (area: P = 1), certified as described above.
Integral face_integral(const DomainMesh& m, int f, const Quadratic2& P);
inline Integral face_area_exact(const DomainMesh& m, int f) { Quadratic2 one; one.f = 1; return face_integral(m, f, one); }

// Integral over face f of sqrt(max(P, 0)) (P must be >= 0 on the plane, as every d^2 is).
Integral face_sqrt_integral(const DomainMesh& m, int f, const Quadratic2& P);

// Integrals of one domain mesh (a finished target), in frame units.
struct DomainIntegrals {
    double area = 0, int_d2 = 0, int_d = 0;
    double err_area = 0, err_d2 = 0, err_d = 0;
    double min_d2_lower = 0;   // a lower bound of d^2 over the target (the faces' box ranges)
    double max_d2 = 0;         // the largest face maximum (DomainMesh::Face::max_value)
};
// One domain's share (frame units): what surface_stats' estimate of the distribution reads.
struct FaceMoments { double area = 0, int_d = 0, int_d2 = 0, min_d2_lower = 0, max_d2 = 0; };
// `faces`, if given, receives each live finite face's moments (in face order).
DomainIntegrals domain_integrals(const DomainMesh& m, std::vector<FaceMoments>* faces = nullptr);

// One level t2 of d^2 on a domain mesh, in face order: a live finite face wholly above it is
// visited as visit(f, true, false); one that straddles it is split along d^2 - t2 (split_face, from
// freshly computed face boxes) and each piece visited as visit(piece, d^2 > t2 on it, true). Faces
// at or below t2 are not visited.
void split_at_level(DomainMesh& m, double t2, const std::function<void(int face, bool above, bool split)>& visit);

// Area (frame units) of the part of face f where d^2 > t2, without splitting it (level_area.cpp:
// Green's theorem along the face's arcs where d^2 > t2 and the conic d^2 = t2 inside the face).
double face_area_above(const DomainMesh& m, int f, double t2);

// The same summed over the target, for each t2 of `levels`: faces wholly above a level count their
// area, faces wholly below nothing, and only the faces a level cuts are integrated.
std::vector<double> area_above_levels(const DomainMesh& m, const std::vector<double>& levels);

// P(x + o.x, y + o.y) as a quadratic in (x, y), and c - o: coordinates shifted to near a face, for
// smaller rounding there.
Quadratic2 shifted(const Quadratic2& P, Vec2 o);
RationalCurve shifted(const RationalCurve& c, Vec2 o);

// Integral of x dy along c(z), z from z0 to z1 (z0 <= z1), certified as face_integral's arcs.
Integral curve_x_dy(const RationalCurve& c, double z0, double z1);

// Bounds of a convex quadratic (every d^2 is one) over a box: its exact range there, widened by
// rounding; much tighter than Quadratic2::range's interval arithmetic.
Interval convex_range(const Quadratic2& P, const Box2& box);

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on the Legendre polynomial), for tests.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w);

}  // namespace hlens
