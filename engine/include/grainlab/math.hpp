#pragma once
// Small 2D vector helpers over Eigen. All state is double precision.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace grainlab {

using Vec2 = Eigen::Vector2d;

/// z-component of the cross product a × b.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
/// ω ẑ × r for a scalar spin ω (rad/s): the velocity of a point at r from the centre.
inline Vec2 cross(double w, const Vec2& r) { return {-w * r.y(), w * r.x()}; }
/// a turned +90° (counter-clockwise).
inline Vec2 perp(const Vec2& a) { return {-a.y(), a.x()}; }
/// a rotated by angle (rad) counter-clockwise.
inline Vec2 rotate(const Vec2& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * a.x() - s * a.y(), s * a.x() + c * a.y()};
}

inline constexpr double kPi = std::numbers::pi;
inline double degrees(double rad) { return rad * 180.0 / kPi; }
inline double radians(double deg) { return deg * kPi / 180.0; }

}  // namespace grainlab
