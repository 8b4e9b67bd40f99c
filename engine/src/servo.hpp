#pragma once
// A proportional-integral servo from a stress error to a boundary strain rate.
#include <algorithm>

namespace grainlab {

struct StressServo {
  double target = 0;     ///< Pa
  double maxRate = 0;    ///< 1/s, the largest strain rate it may command
  double kp = 0;         ///< 1/s per unit relative error
  double ki = 0;         ///< 1/s² per unit relative error
  double integral = 0;   ///< ∫ relative error dt, s

  /// Compression rate (1/s, compression positive) that drives `stress` toward the target:
  /// positive (squeeze) when it is below, negative (release) when above.
  double rate(double stress, double dt) {
    const double error = (target - stress) / target;
    const double unclamped = kp * error + ki * (integral + error * dt);
    const double r = std::clamp(unclamped, -maxRate, maxRate);
    // Integrate only while not saturated (anti-windup).
    if (r == unclamped) integral += error * dt;
    return r;
  }
};

}  // namespace grainlab
