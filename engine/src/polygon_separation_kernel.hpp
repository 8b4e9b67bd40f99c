#pragma once
// The feature search's two scans (polygon_features.cpp) several faces per instruction: the face
// of one polygon that best separates the other (b2FindMaxSeparation), and the other's edge most
// anti-parallel to a reference face (b2FindIncidentEdge). Every lane performs the scalar loops'
// operations in their order (no fused products: the build contracts none); the least or
// greatest of a set does not depend on the order it is taken in, and the first of equals is found
// by index, as the scalar loops find it. (Where a +0 ties a −0, either may be returned: no
// decision or slack of the search tells them apart.) So the search takes the same decisions,
// with the same slack, on either path (tests/engine/polygon_feature_search_test.cpp, on every
// instruction set).
#include "polygon_features.hpp"

namespace grainlab {

/// `other`'s vertex slots placed at d + R(c, s) u in `ref`'s frame (wx, wy: kMaxPolygonVertices
/// each, for the clipping), each of ref's faces' least n·w − n·v_e over other's placed corners,
/// and the greatest of those: returned, with its face (the first of equals) and the greatest of
/// the other faces' (`runnerUp`).
double bestSeparatingFaceWide(const PolygonFeatureTable& ref, const PolygonFeatureTable& other, double dx, double dy,
                              double c, double s, double* wx, double* wy, int& face, double& runnerUp);

/// The edge of `incident` whose outward normal, turned by R(c, s), has the least dot product
/// with n: returned (the first of equals), with that least and the least of the other edges'
/// (`nextLeast`).
int mostAntiParallelEdgeWide(double nx, double ny, double c, double s, const PolygonFeatureTable& incident,
                             double& least, double& nextLeast);

}  // namespace grainlab
