// Small fixed-size vector math for the core (double precision throughout).
#pragma once
#include <cmath>
#include <algorithm>

namespace hlens {

struct Vec2 {
    double x = 0, y = 0;
    Vec2() = default;
    Vec2(double x_, double y_) : x(x_), y(y_) {}
    Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    Vec2 operator-() const { return {-x, -y}; }
    Vec2 operator*(double s) const { return {x * s, y * s}; }
    Vec2 operator/(double s) const { return {x / s, y / s}; }
    Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
    Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
    bool operator==(const Vec2& o) const { return x == o.x && y == o.y; }
};
inline Vec2 operator*(double s, Vec2 v) { return v * s; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm2(Vec2 a) { return dot(a, a); }
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }
inline Vec2 perp(Vec2 a) { return {-a.y, a.x}; }  // rotate +90 degrees
// The point of the segment a-b nearest p (the clamped projection; a point segment is its end).
inline Vec2 segment_closest(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 d = b - a;
    const double t = norm2(d) > 0 ? std::clamp(dot(p - a, d) / norm2(d), 0.0, 1.0) : 0.0;
    return a + t * d;
}
// Distance from p to the segment a-b.
inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) { return norm(segment_closest(p, a, b) - p); }

struct Vec3 {
    double x = 0, y = 0, z = 0;
    Vec3() = default;
    Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3 operator-() const { return {-x, -y, -z}; }
    Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
    bool operator!=(const Vec3& o) const { return !(*this == o); }
};
inline Vec3 operator*(double s, const Vec3& v) { return v * s; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm2(const Vec3& a) { return dot(a, a); }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 vmin(const Vec3& a, const Vec3& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline Vec3 vmax(const Vec3& a, const Vec3& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }

struct Box3 {
    Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL};
    Vec3 hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    void add(const Vec3& p) { lo = vmin(lo, p); hi = vmax(hi, p); }
    void add(const Box3& b) { lo = vmin(lo, b.lo); hi = vmax(hi, b.hi); }
    bool empty() const { return lo.x > hi.x; }
    bool contains(const Box3& b) const {
        return b.lo.x >= lo.x && b.lo.y >= lo.y && b.lo.z >= lo.z && b.hi.x <= hi.x && b.hi.y <= hi.y && b.hi.z <= hi.z;
    }
    Vec3 extent() const { return hi - lo; }
    double diagonal() const { return empty() ? 0.0 : norm(hi - lo); }
};

// Squared distance from p to the box [lo, hi] (0 inside).
inline double point_box_distance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
        const double g = std::max({0.0, lo[i] - p[i], p[i] - hi[i]});
        d2 += g * g;
    }
    return d2;
}

// Squared distance between two axis-aligned boxes (0 when they overlap).
inline double box_distance2(const Box3& a, const Box3& b) {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
        double g = std::max({0.0, a.lo[i] - b.hi[i], b.lo[i] - a.hi[i]});
        d2 += g * g;
    }
    return d2;
}

}  // namespace hlens
