#pragma once
// `grainlab tradeoff --seeds N`: the trade measured on seed ensembles, paired where it can be.
// For each preset and seed the reference setting prepares a specimen once and shears it, keeping
// its end of consolidation (grainlab/prepared_specimen.hpp); every setting of the shearing alone
// (timestep safety, inertial number, sample strain, the noise probe) shears that same specimen.
// Settings that change the specimen or its engine (vertices, box2d) prepare their own and are
// compared unpaired. Per setting and quantity (ensemble_quantities): the bias with its 95%
// interval, the seed-to-seed sd, CPU seconds per run, a verdict, and the runs a tolerance needs
// (paired_bias). Writes DIR/tradeoff.csv, DIR/runs.csv, DIR/scenes/ and DIR/specimens/.
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/studies/tradeoff/paired_bias.hpp"
#include "grainlab/studies/tradeoff/pareto_panel.hpp"
#include "grainlab/studies/tradeoff/sweep_plan.hpp"
#include "grainlab/studies/tradeoff/tradeoff_study.hpp"

namespace grainlab::tradeoff {

/// One setting's judgement on one quantity.
struct EnsembleJudgement {
  Setting setting;
  bool paired = false;
  std::string quantity;
  double tolerance = 0;
  BiasEstimate estimate;
  double cpuSeconds = 0;            ///< mean per run (a paired run's: its shearing only)
  double lateralStressOff = 0;      ///< mean over seeds of the median |σ11/target − 1|
};

struct EnsembleStudy {
  std::vector<EnsembleJudgement> judgements;  ///< tradeoff.csv's rows (the reference's are left out)
  std::vector<ParetoPanel> panels;            ///< one per preset: CPU s against the mean angle difference
  std::size_t failedRuns = 0;
};

/// Runs options.seeds seeds of the plan into options.outDir; progress lines to `progress`.
EnsembleStudy runEnsembleTradeoff(const TradeoffOptions& options, std::ostream* progress);

}  // namespace grainlab::tradeoff
