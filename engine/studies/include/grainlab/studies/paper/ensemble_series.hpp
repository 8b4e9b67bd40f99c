#pragma once
// The runs of one assembly over several seeds, and any per-sample quantity of theirs put on a
// common strain axis: each run's values, their mean and its 95 % interval at each strain.
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"

namespace grainlab::report {

struct Ensemble {
  std::string preset;
  AssemblyKind kind = AssemblyKind::Circular;
  double beddingDeg = 0;
  int attempted = 0;                         ///< runs of this preset, completed or not
  std::vector<const AssemblyResult*> runs;   ///< the completed ones with a shearing series, by seed
  std::string label() const;                 ///< as AssemblyResult::label()
};

/// The runs grouped by preset, in the order the presets first appear; every preset comes,
/// even one with no completed run.
std::vector<Ensemble> groupEnsembles(std::span<const AssemblyResult> runs);

/// A column's values at the given axial strains, linear between the samples around each (for
/// an axial direction along the shorter arc); NaN outside the series or beside a missing value
/// (unless the strain is a sample's own).
std::vector<double> atStrains(const AssemblyResult& a, const std::vector<double>& values,
                              const std::vector<double>& strains, bool axial);

/// One quantity of an ensemble on a common strain axis.
struct EnsembleBand {
  std::vector<double> strain;                ///< ε22: the first run's samples up to the shortest run's end
  std::vector<std::vector<double>> perRun;   ///< one row per run, at those strains
  std::vector<MeanInterval> stats;           ///< per strain, over the runs' finite values
  std::vector<double> mean() const;
  std::vector<double> low() const;
  std::vector<double> high() const;
};

/// `quantity(run)` gives one value per sample of the run (its own strains); `axial` averages
/// directions on 2θ. With `quorum`, a mean made of fewer than half the runs' values (at least
/// one) is dropped to NaN: e.g. a direction that is meaningful in too few seeds.
EnsembleBand ensembleBand(const Ensemble& e, const std::function<std::vector<double>(const AssemblyResult&)>& quantity,
                          bool axial, bool quorum = false);

/// The same for a stored column.
EnsembleBand ensembleColumn(const Ensemble& e, const std::string& column, bool axial = false);

}  // namespace grainlab::report
