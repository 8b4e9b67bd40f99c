#pragma once
// A polygon's or a clump's cosine and sine advanced by its step's rotation δ = ω dt, instead
// of sincos of its angle (the wide path; the baseline keeps sincos). sincos was a tenth of a
// settled polygon pile's step, and a sixth of a clump pile's; this is a dozen multiplications.
//
//  - cos δ and sin δ come from their Taylor series to δ⁶ and δ⁷. For |δ| ≤ kMaxIncrementalTurn
//    = 1/64 the first term left out, δ⁸/8! ≤ 9e-20, is under a thousandth of a double's rounding
//    at 1, so the series is exact to rounding. A larger turn (a fast spin in a loose stage)
//    takes sincos of the angle.
//  - The rotated pair is renormalised every step by one Newton step for 1/√(c² + s²) from 1:
//    a norm 1 + e becomes 1 − (3/4)e² + O(e³), so the norm stays within rounding of 1 rather
//    than drifting. (The interval of renormalisation is one step: it costs four operations.)
//  - The phase is not resynchronised with the angle: each step adds a few units of rounding, so
//    after N steps cos and sin differ from those of the stored angle by at most about
//    N × 8 × 2⁻⁵³ rad (5e-10 rad after the 0.59 M steps of the longest preset), while the angle
//    itself carries rounding of the same order. Both stay far below anything the contacts
//    resolve (features are decided with margins of 1e-4 of a particle's size).
// A function of the state alone: the same bits on any thread count and after a resume (cos and
// sin are part of the checkpoint).
#include <cmath>

namespace grainlab {

/// The largest |δ| (rad) advanced by the series; beyond it sincos of the angle is taken.
constexpr double kMaxIncrementalTurn = 1.0 / 64;

/// Rotates (c, s) by δ, |δ| ≤ kMaxIncrementalTurn, and renormalises the result.
inline void rotateIncrementally(double& c, double& s, double delta) {
  const double d2 = delta * delta;
  // Horner forms of 1 − δ²/2! + δ⁴/4! − δ⁶/6! and δ − δ³/3! + δ⁵/5! − δ⁷/7!, by reciprocals
  // (multiplications, not divisions).
  const double cosD = 1 - d2 * 0.5 * (1 - d2 * (1.0 / 12) * (1 - d2 * (1.0 / 30)));
  const double sinD = delta * (1 - d2 * (1.0 / 6) * (1 - d2 * (1.0 / 20) * (1 - d2 * (1.0 / 42))));
  const double c1 = c * cosD - s * sinD, s1 = s * cosD + c * sinD;
  const double g = 1.5 - 0.5 * (c1 * c1 + s1 * s1);
  c = c1 * g;
  s = s1 * g;
}

/// A particle's (cos, sin) after its angle advanced by δ to `angle`: incrementally where the
/// turn is small, by sincos of the new angle otherwise.
inline void advanceRotation(double& c, double& s, double delta, double angle) {
  if (std::abs(delta) <= kMaxIncrementalTurn) rotateIncrementally(c, s, delta);
  else ::sincos(angle, &s, &c);
}

}  // namespace grainlab
