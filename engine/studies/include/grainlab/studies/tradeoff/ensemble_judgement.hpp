#pragma once
// From every run's measures to `grainlab tradeoff --seeds N`'s tables: tradeoff.csv (each
// setting's bias on each quantity, with its interval and verdict), runs.csv and the Pareto
// panels. Pure: the CLI feeds it the runs it ran, the server the runs it stored.
#include <limits>
#include <string>
#include <vector>

#include "grainlab/run_status.hpp"
#include "grainlab/studies/paper/csv_table.hpp"
#include "grainlab/studies/paper/shearing_series.hpp"
#include "grainlab/studies/tradeoff/ensemble_plan.hpp"
#include "grainlab/studies/tradeoff/ensemble_tradeoff.hpp"

namespace grainlab::tradeoff {

/// What one run gave: its end, its costs and its quantities (ensembleQuantities()'s order).
struct EnsembleRunResult {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  RunStatus status = RunStatus::Failed;
  std::string error;
  double cpuSeconds = kNaN;             ///< of the shearing
  double preparationCpuSeconds = kNaN;  ///< of preparing (or loading) the specimen
  double wallSeconds = 0;
  double lateralStressOff = kNaN;
  std::vector<double> values;
};

/// The measures of a run that ended `status` (NaN unless it completed) from its shearing stage,
/// its peak φ_mob (summary) and the shearing stage's confining pressure.
void measureEnsembleRun(EnsembleRunResult& result, const report::ShearingSeries& shearing, double peakPhiMobDeg,
                        double pressurePa);

struct EnsembleTables {
  EnsembleStudy study;
  report::CsvTable tradeoff{{}};  ///< tradeoff.csv
  report::CsvTable runs{{}};      ///< runs.csv
};

/// results[r][seed − 1] for every distinct run r of the plan.
EnsembleTables judgeEnsemble(const EnsemblePlan& plan, const std::vector<std::vector<EnsembleRunResult>>& results);

}  // namespace grainlab::tradeoff
