#pragma once
// The kept face-against-edge features of polygon pairs measured several pairs per instruction
// (the wide path): PolygonCollider::measurePolygons lane by lane. Every lane performs that
// function's operations in its order, with no fused products (the build contracts none) and
// IEEE division, so each lane's contact has the scalar function's bits; lanes do not
// interact, so how the pairs are split between threads changes nothing.
#include <cstdint>

#include "contact_geometry.hpp"
#include "neighbor_list.hpp"

namespace grainlab {

/// One range's face-against-edge pairs in structure-of-arrays slots, the polygons' shape
/// tables they read, and where the contacts go.
struct PolygonFaceKernelInput {
  // Per slot: the reference body's pose (centre, cos, sin) and the incident body's.
  const double *refX, *refY, *refC, *refS;
  const double *incX, *incY, *incC, *incS;
  // Per slot: where the reference face's record and the incident edge's record start in the
  // tables below (in doubles); the sign of the normal (+1 when the reference body is the
  // pair's i, −1 when it is j: the contact's normal runs from i to j); the pair the contact
  // is for.
  const std::int64_t* face;
  const std::int64_t* edge;
  const double* normalSign;
  const std::int32_t* pair;
  // Shape tables (PolygonCollider::faceTable, edgeTable), a record per polygon corner:
  // face e's n_x n_y lo hi front; edge e's ends (vertex e, vertex e + 1) x0 y0 x1 y1.
  const double* faces;
  const double* edges;
  // Pair k's contact goes to contacts[k] (overlap −1 where the features no longer touch).
  ContactGeometry* contacts;
};

/// The force law at the slots' contacts (polygon_face_kernel.cpp, measurePolygonFaceForces):
/// ContactSolver's linear spring-dashpot and Cundall-Strack friction (or none) for a pair of
/// polygons, lane by lane in the scalar code's operations and order, so each lane has its bits.
struct PolygonFaceLaw {
  double normalStiffness = 0, tangentialStiffness = 0, friction = 0, dt = 0;
  bool frictional = false;
};
struct PolygonFaceForceInput {
  // Per slot: the pair's particles i and j (the contact's normal runs from i to j).
  const std::int64_t* i;
  const std::int64_t* j;
  // Particles: velocity as x0 y0 x1 y1 …, spin.
  const double* velocity;
  const double* spin;
  // The pairs, by the slots' pair index: dampN, dampT and the tangential spring are read; a
  // touching pair's spring, fn, ft and overlap are written in place. An apart pair is left as
  // it is (the caller clears it).
  PairState* pairs;
  PolygonFaceLaw law;
  // Per slot: the force on j from i (−F on i), the torques about i's and j's centroids, and
  // 1 where the pair touches (0 where the outputs mean nothing).
  double *fx, *fy, *torqueI, *torqueJ;
  std::uint8_t* touching;
};

/// Doubles in a record of the face table and of the edge table.
inline constexpr int kFaceRecord = 5;
inline constexpr int kEdgeRecord = 4;

/// Measures slots [0, count).
void measurePolygonFaces(const PolygonFaceKernelInput& in, int count);
/// Measures slots [0, count) and applies the law at each: the slots' forces are the answer, and
/// each touching pair's contact is written too (an apart pair's is not), for the servos'
/// stress, which would otherwise measure them again (contact_solver_stress.cpp).
void measurePolygonFaceForces(const PolygonFaceKernelInput& in, const PolygonFaceForceInput& forces, int count);

}  // namespace grainlab
