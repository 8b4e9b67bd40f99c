#pragma once
// Calibrating discs' rolling friction μ_r to a target peak strength: the ensemble mean peak
// φ_mob measured at a few μ_r, read between them by straight lines.
#include <limits>
#include <string>
#include <vector>

namespace grainlab::shapes {

struct CalibrationPoint {
  double rollingFriction = 0;  ///< μ_r
  double meanPeakDeg = 0;      ///< the ensemble's mean peak φ_mob there, °
};

struct RollingCalibration {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double rollingFriction = kNaN;          ///< μ_r whose interpolated mean peak is the target; NaN if none
  double below = kNaN, above = kNaN;      ///< the measured μ_r on either side of it
  std::string note;                       ///< why there is no value, when there is none
};

/// Sorts the points by μ_r and interpolates linearly in the first adjacent pair whose means
/// bracket `targetDeg` (inclusive). Points with a non-finite mean are skipped. With no bracket
/// (the target lies outside the measured means, or fewer than two points), the result is NaN
/// and the note says which μ_r to add.
RollingCalibration interpolateRollingFriction(std::vector<CalibrationPoint> points, double targetDeg);

}  // namespace grainlab::shapes
