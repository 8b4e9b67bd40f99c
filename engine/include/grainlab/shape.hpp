#pragma once
// Particle shapes: discs, convex polygons (3 to 8 vertices, Box2D's limit) and clumps of
// discs (grainlab/clump.hpp).
#include <array>
#include <span>
#include <vector>

#include "grainlab/math.hpp"

namespace grainlab {

enum class ShapeKind : unsigned char { Disc = 0, Polygon = 1, Clump = 2 };

inline constexpr int kMaxPolygonVertices = 8;

/// A convex polygon in its body frame: vertices counter-clockwise about the centroid (the
/// origin), with their outward unit face normals (normal k is of edge k -> k+1).
struct Polygon {
  int count = 0;
  std::array<Vec2, kMaxPolygonVertices> vertices{};
  std::array<Vec2, kMaxPolygonVertices> normals{};
  double area = 0;            ///< m² (per metre of thickness: m³/m)
  double polarMoment = 0;     ///< ∫ r² dA about the centroid, m⁴
  double circumradius = 0;    ///< largest vertex distance from the centroid, m
};

/// Builds a Polygon from vertices given relative to some reference point (any order, any
/// winding). Throws std::invalid_argument if there are not 3..8 vertices or they do not
/// form a strictly convex polygon of positive area. `centroidOffset` receives the
/// centroid's position relative to the reference point.
Polygon makePolygon(std::span<const Vec2> vertices, Vec2* centroidOffset = nullptr);

/// Area of a disc of radius r (per metre of thickness).
inline double discArea(double r) { return kPi * r * r; }

}  // namespace grainlab
