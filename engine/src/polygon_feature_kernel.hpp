#pragma once
// The feature search's arithmetic (polygon_features.cpp) several faces per instruction, for
// the wide path: every slot performs the scalar code's operations in its order, with no fused
// products (the build contracts none), so each slot has the scalar search's bits and both
// paths find the same features.
#include "polygon_features.hpp"

namespace grainlab {

/// One side of the separating-axis test: `other`'s vertex slots placed in `ref`'s frame,
/// u ↦ (dX + c u_x − s u_y, dY + s u_x + c u_y), into wx, wy; and each of `ref`'s face slots'
/// separation from the first `count` of them, the least of n·w − offset, into `separation`.
struct FeatureSide {
  const PolygonFeatureTable* ref;
  const PolygonFeatureTable* other;
  int count;
  double dX, dY, c, s;
  double *wx, *wy, *separation;  // kMaxPolygonVertices each
};

/// Side `first`, then side `second` unless one of the first's `firstFaces` faces separates by
/// more than `reach` (the search then stops there); false in that case. One dispatch for both.
bool featureSidesWide(const FeatureSide& first, int firstFaces, double reach, const FeatureSide& second);

}  // namespace grainlab
