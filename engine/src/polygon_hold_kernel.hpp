#pragma once
// Which kept polygon pair slots still hold their features this step, several slots per
// instruction (the wide path's kept slots, polygon_pair_slots.hpp). For each slot it answers
// what the pair loop's first pass asks of a polygon pair with kept features, in the scalar
// code's operations and order: are the bounding circles apart ((x_j − x_i)·(x_j − x_i) >=
// reach²), and has the pair moved its slack since its features were found (relativeMotion >=
// slack)? A slot that fails either goes back to the scalar code, which decides it as it always
// has. Face slots have their poses written for the face kernel (the reference body's and the
// incident one's).
#include <cstdint>

namespace grainlab {

struct PolygonHoldInput {
  // Particles: positions as x0 y0 x1 y1 …, cos and sin of their angles.
  struct Particles {
    const double* position;
    const double *cosAngle, *sinAngle;
  };
  // Per slot: the pair's particles; the anchor its features were found at (CachedContact's
  // offset, lever and rotations), its slack, and the pair's reach r_i + r_j.
  const std::int64_t *i, *j;
  const double *offsetX, *offsetY, *lever, *ca, *sa, *cb, *sb, *slack, *reach;
  Particles particles;
  // Face slots only (null for others): +1 where i's face is the reference (−1 where j's is),
  // and where the reference body's pose and the incident body's are written.
  const double* normalSign = nullptr;
  double *refX = nullptr, *refY = nullptr, *refC = nullptr, *refS = nullptr;
  double *incX = nullptr, *incY = nullptr, *incC = nullptr, *incS = nullptr;
};

/// Tests slots [0, count) and writes their poses where asked; the slots that fail go to
/// `failed` in ascending order. Returns how many failed.
int holdPolygonSlots(const PolygonHoldInput& in, int count, std::int32_t* failed);

}  // namespace grainlab
