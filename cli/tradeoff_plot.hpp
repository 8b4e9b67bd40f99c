#pragma once
// The Pareto plot of `grainlab tradeoff`: error against cost, one panel per preset, as a
// standalone SVG written by hand (log-scaled time, linear error, the front as a staircase).
#include <limits>
#include <string>
#include <vector>

namespace grainlab::tradeoff {

struct ParetoPoint {
  double seconds = 0;      ///< cost, s (> 0 to be drawn)
  double error = 0;        ///< error, in the panel's unit (finite to be drawn)
  std::string label;       ///< short text beside the marker
  std::string axis;        ///< the sweep axis (or "baseline"): sets the colour and the legend entry
  bool onFront = false;    ///< part of the Pareto front
};

struct ParetoPanel {
  std::string title;
  std::vector<ParetoPoint> points;
  /// The error a trivial perturbation alone produces (drawn as a dashed line); NaN for none.
  double noiseFloor = std::numeric_limits<double>::quiet_NaN();
};

/// The panels side by side in one <svg> document.
std::string renderParetoSvg(const std::vector<ParetoPanel>& panels, const std::string& xLabel,
                            const std::string& yLabel);

}  // namespace grainlab::tradeoff
