#include "grainlab/studies/shape_fidelity/rolling_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace grainlab::shapes {

RollingCalibration interpolateRollingFriction(std::vector<CalibrationPoint> points, double targetDeg) {
  RollingCalibration c;
  std::erase_if(points, [](const CalibrationPoint& p) { return !std::isfinite(p.meanPeakDeg) || !std::isfinite(p.rollingFriction); });
  std::sort(points.begin(), points.end(),
            [](const CalibrationPoint& a, const CalibrationPoint& b) { return a.rollingFriction < b.rollingFriction; });
  if (points.size() < 2 || !std::isfinite(targetDeg)) {
    c.note = "needs the mean peak at two rolling frictions or more";
    return c;
  }
  for (size_t k = 0; k + 1 < points.size(); ++k) {
    const CalibrationPoint &a = points[k], &b = points[k + 1];
    if ((targetDeg - a.meanPeakDeg) * (targetDeg - b.meanPeakDeg) > 0) continue;
    c.below = a.rollingFriction;
    c.above = b.rollingFriction;
    c.rollingFriction = a.meanPeakDeg == b.meanPeakDeg
                            ? a.rollingFriction
                            : a.rollingFriction + (targetDeg - a.meanPeakDeg) / (b.meanPeakDeg - a.meanPeakDeg) *
                                                      (b.rollingFriction - a.rollingFriction);
    return c;
  }
  const bool above = std::all_of(points.begin(), points.end(), [&](const CalibrationPoint& p) { return targetDeg > p.meanPeakDeg; });
  const bool below = std::all_of(points.begin(), points.end(), [&](const CalibrationPoint& p) { return targetDeg < p.meanPeakDeg; });
  char b[160];
  if (above) std::snprintf(b, sizeof b, "the target lies above every measured mean: add a rolling friction above %g", points.back().rollingFriction);
  else if (below) std::snprintf(b, sizeof b, "the target lies below every measured mean: add a rolling friction below %g", points.front().rollingFriction);
  else std::snprintf(b, sizeof b, "no two neighbouring rolling frictions bracket the target");
  c.note = b;
  return c;
}

}  // namespace grainlab::shapes
