#pragma once
// Exact overlap tests between the generator's shapes, in double precision and without
// bounding approximations: discs and convex polygons whose vertices are given
// counter-clockwise in world coordinates. Touching is not overlapping.
#include <span>

#include "grainlab/math.hpp"

namespace grainlab::specimen {

/// Whether two discs (centres m, radii m) overlap.
bool discsOverlap(const Vec2& centreA, double radiusA, const Vec2& centreB, double radiusB);

/// Whether a disc overlaps a convex polygon: its centre inside, or nearer an edge than r.
bool discPolygonOverlap(const Vec2& centre, double radius, std::span<const Vec2> polygon);

/// Whether two convex polygons overlap: no edge normal of either separates them
/// (separating axis theorem).
bool polygonsOverlap(std::span<const Vec2> a, std::span<const Vec2> b);

}  // namespace grainlab::specimen
