#pragma once
// What the trade-off's Pareto plot shows of one preset: each run's cost and error, its
// sweep axis, and whether it is on the front (drawn by grainlab/studies/draw/pareto_plot.hpp).
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
  /// The error's 95% interval, drawn as a bar through the marker (an ensemble's); NaN: none.
  double errorLow = std::numeric_limits<double>::quiet_NaN();
  double errorHigh = std::numeric_limits<double>::quiet_NaN();
};

struct ParetoPanel {
  std::string title;
  std::vector<ParetoPoint> points;
  /// The error a trivial perturbation alone produces (drawn as a dashed line); NaN for none.
  double noiseFloor = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace grainlab::tradeoff
