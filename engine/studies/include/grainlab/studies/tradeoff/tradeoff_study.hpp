#pragma once
// `grainlab tradeoff`'s runs and measures: speed against accuracy. Every setting of a sweep
// plan (sweep_plan) runs, each distinct scene once, most expensive first, side by side; each
// run's wall and CPU time and its errors against its preset's reference run are measured
// (metrics), and the Pareto front of cost against the mean angle error found per preset.
// Writes DIR/scenes/*.json and DIR/tradeoff.csv (docs/speed-accuracy.md); the plot is drawn
// from the panels (grainlab/studies/draw/pareto_plot.hpp).
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/run_status.hpp"
#include "grainlab/studies/tradeoff/pareto_panel.hpp"
#include "grainlab/studies/tradeoff/sweep_plan.hpp"

namespace grainlab::tradeoff {

struct TradeoffOptions {
  std::string outDir;
  bool quick = false;             ///< quickPlan() instead of fullPlan()
  unsigned jobs = 0;              ///< runs at once; 0 = hardware threads
  std::vector<std::string> presets;  ///< instead of the plan's, if not empty
  std::vector<std::string> axes;     ///< only these axes (keepAxes), if not empty
  /// The cost the Pareto front is taken on: "cpu" (the run's own CPU seconds: its wall time
  /// on an idle core, whatever else the machine runs) or "wall".
  std::string cost = "cpu";
  /// Seeds per setting: > 0 measures the trade on ensembles (ensemble_tradeoff.hpp) instead of
  /// one run per setting.
  int seeds = 0;
};

/// One setting's cost and errors (those of the run it shares with others, for the baseline).
struct SettingOutcome {
  Setting setting;
  double wallSeconds = 0, cpuSeconds = 0;    ///< s
  double meanAngleErrorDeg = 0, maxAngleErrorDeg = 0;
  double voidRatioError = 0;
  bool onFront = false;
};

struct TradeoffStudy {
  std::vector<SettingOutcome> settings;  ///< in tradeoff.csv's order
  std::vector<ParetoPanel> panels;       ///< one per preset, cost by options.cost
  std::size_t failedRuns = 0;
};

/// Runs the plan into options.outDir (progress lines to `progress`, may be null) and writes
/// scenes/ and tradeoff.csv there. Throws for an unknown preset before running anything.
TradeoffStudy runTradeoff(const TradeoffOptions& options, std::ostream* progress);

}  // namespace grainlab::tradeoff
