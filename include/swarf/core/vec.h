// 2D and 3D vectors and axis-aligned boxes, in mm. Plain value types.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarf {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }
  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double s) {
    x *= s;
    y *= s;
    return *this;
  }
  constexpr bool operator==(const Vec2&) const = default;
};
constexpr Vec2 operator*(double s, Vec2 v) {
  return v * s;
}
constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
/// z component of the 3D cross product: > 0 when b is counter-clockwise from a.
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
inline double norm(Vec2 v) {
  return std::hypot(v.x, v.y);
}
constexpr double norm_sq(Vec2 v) {
  return v.x * v.x + v.y * v.y;
}
inline double distance(Vec2 a, Vec2 b) {
  return norm(a - b);
}
/// Unit vector along v; v itself when it has zero length.
inline Vec2 normalized(Vec2 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : v;
}
/// v turned 90 degrees counter-clockwise.
constexpr Vec2 perp(Vec2 v) {
  return {-v.y, v.x};
}
/// v rotated counter-clockwise by angle_rad.
inline Vec2 rotated(Vec2 v, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  constexpr Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3& operator+=(Vec3 o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr Vec3& operator-=(Vec3 o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  constexpr Vec3& operator*=(double s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr bool operator==(const Vec3&) const = default;
  constexpr Vec2 xy() const { return {x, y}; }
  /// Component by axis index 0, 1, 2 = x, y, z.
  constexpr double operator[](int axis) const { return axis == 0 ? x : (axis == 1 ? y : z); }
  constexpr double& operator[](int axis) { return axis == 0 ? x : (axis == 1 ? y : z); }
};
constexpr Vec3 operator*(double s, Vec3 v) {
  return v * s;
}
constexpr double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 v) {
  return std::sqrt(dot(v, v));
}
constexpr double norm_sq(Vec3 v) {
  return dot(v, v);
}
inline double distance(Vec3 a, Vec3 b) {
  return norm(a - b);
}
inline Vec3 normalized(Vec3 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : v;
}
constexpr Vec3 to_vec3(Vec2 v, double z = 0.0) {
  return {v.x, v.y, z};
}

/// Axis-aligned 2D box; empty (min > max) when default-constructed.
struct Box2 {
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  constexpr bool empty() const { return min.x > max.x || min.y > max.y; }
  constexpr void add(Vec2 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y)};
  }
  constexpr void merge(const Box2& b) {
    if (!b.empty()) {
      add(b.min);
      add(b.max);
    }
  }
  constexpr Vec2 size() const { return empty() ? Vec2{} : max - min; }
  constexpr Vec2 center() const { return (min + max) * 0.5; }
  constexpr bool contains(Vec2 p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y;
  }
  constexpr Box2 inflated(double d) const {
    return empty() ? *this : Box2{{min.x - d, min.y - d}, {max.x + d, max.y + d}};
  }
};

/// Axis-aligned 3D box; empty (min > max) when default-constructed.
struct Box3 {
  Vec3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  constexpr bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  constexpr void add(Vec3 p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
  }
  constexpr void merge(const Box3& b) {
    if (!b.empty()) {
      add(b.min);
      add(b.max);
    }
  }
  constexpr Vec3 size() const { return empty() ? Vec3{} : max - min; }
  constexpr Vec3 center() const { return (min + max) * 0.5; }
  constexpr bool contains(Vec3 p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
           p.z <= max.z;
  }
  constexpr Box3 inflated(double d) const {
    return empty() ? *this
                   : Box3{{min.x - d, min.y - d, min.z - d}, {max.x + d, max.y + d, max.z + d}};
  }
  constexpr Box2 xy() const { return empty() ? Box2{} : Box2{min.xy(), max.xy()}; }
};

inline constexpr double kPi = 3.14159265358979323846;
constexpr double deg_to_rad(double deg) {
  return deg * kPi / 180.0;
}
constexpr double rad_to_deg(double rad) {
  return rad * 180.0 / kPi;
}

}  // namespace swarf
