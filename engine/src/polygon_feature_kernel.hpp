#pragma once
// The feature search's arithmetic (polygon_features.cpp) several faces per instruction, for
// the wide path: every slot performs the scalar code's operations in its order, with no fused
// products (the build contracts none), so each slot has the scalar search's bits and both
// paths find the same features.
#include "polygon_features.hpp"

namespace grainlab {

/// `other`'s vertex slots placed in `ref`'s frame, u ↦ (dX + c u_x − s u_y, dY + s u_x + c u_y),
/// into wx, wy; and each of `ref`'s face slots' separation from the first `count` of them,
/// the least of n·w − offset, into `separation` (arrays of kMaxPolygonVertices).
void faceSeparationsWide(const PolygonFeatureTable& ref, const PolygonFeatureTable& other, int count, double dX,
                         double dY, double c, double s, double* wx, double* wy, double* separation);

/// For every normal slot m_q of `incident`: n·(c m_x − s m_y, s m_x + c m_y), into `facing`.
void incidentFacingWide(const PolygonFeatureTable& incident, double nx, double ny, double c, double s,
                        double* facing);

}  // namespace grainlab
