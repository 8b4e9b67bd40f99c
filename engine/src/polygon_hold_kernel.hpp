#pragma once
// Which kept face-against-edge slots still hold their features this step, several slots per
// instruction (the wide path's persistent slots, polygon_face_slots.hpp). For each slot it
// answers what the pair loop's first pass asks of a face pair, in the scalar code's operations
// and order: are the bounding circles apart ((x_j − x_i)·(x_j − x_i) >= reach²), and has the
// pair moved its slack since its features were found (relativeMotion >= slack)? A slot that
// fails either goes back to the scalar code, which decides it as it always has; every slot's
// poses are written for the face kernel (the reference body's and the incident one's).
#include <cstdint>

namespace grainlab {

struct PolygonHoldInput {
  // Per slot: the pair's particles, and +1 where i's face is the reference (−1 where j's is).
  const std::int64_t *i, *j;
  const double* normalSign;
  // Per slot: the anchor its features were found at (CachedContact's offset, lever and
  // rotations), its slack, and the pair's reach r_i + r_j.
  const double *offsetX, *offsetY, *lever, *ca, *sa, *cb, *sb, *slack, *reach;
  // Particles: positions as x0 y0 x1 y1 …, cos and sin of their angles.
  const double* position;
  const double *cosAngle, *sinAngle;
  // Per slot, written: the reference body's pose and the incident body's.
  double *refX, *refY, *refC, *refS, *incX, *incY, *incC, *incS;
};

/// Tests slots [0, count) and writes their poses; the slots that fail go to `failed` in
/// ascending order. Returns how many failed.
int holdPolygonFaceSlots(const PolygonHoldInput& in, int count, std::int32_t* failed);

}  // namespace grainlab
