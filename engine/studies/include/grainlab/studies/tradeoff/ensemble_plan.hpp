#pragma once
// The runs of `grainlab tradeoff --seeds N`, planned before any of them runs: every setting of
// the sweep plan, the distinct runs they share (the baseline sits on every axis but runs once
// per seed), which of them shear the reference's specimen (paired) and each run's scene. The
// CLI runs them itself (ensemble_tradeoff); the server queues the same scenes as a study.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/studies/tradeoff/sweep_plan.hpp"
#include "grainlab/studies/tradeoff/tradeoff_study.hpp"

namespace grainlab::tradeoff {

struct EnsemblePlan {
  std::vector<std::string> presets;
  int seeds = 0;
  std::vector<Setting> settings;   ///< tradeoff.csv's rows, in order
  std::vector<size_t> runOf;       ///< settings[k] is the distinct run runOf[k]
  std::vector<size_t> runSetting;  ///< distinct run r is settings[runSetting[r]]
  /// By distinct run: only the shearing differs from its preset's reference, so it shears the
  /// reference's specimen of the same seed.
  std::vector<bool> paired;
  /// The distinct run that is run r's preset's reference.
  size_t referenceRun(size_t r) const;
};

/// The plan options ask for (quick or full, presets, axes, seeds). Throws SceneError naming
/// "--axes" for an unknown axis and "preset" for an unknown preset, before anything runs.
EnsemblePlan planEnsemble(const TradeoffOptions& options);

/// One run of the plan: distinct run `run` on seed `seed`.
struct EnsembleRun {
  size_t run = 0;
  int seed = 1;
  /// A reference run: it prepares the seed's specimen, shears it, and keeps its stages' ends
  /// (output.stage_checkpoints) for the paired runs.
  bool preparing = false;
  /// Shears the reference's specimen of its seed: its scene still needs a start_from naming
  /// that specimen (the CLI's file, the server's stored run).
  bool paired = false;
  nlohmann::json scene;
  std::string name;  ///< "PRESET AXIS VALUE seed N", as the progress lines say
  std::string file;  ///< "run-RR-seed-N.json", its name in DIR/scenes/
};

/// The preparing runs (the references, every seed) or the others, in the CLI's order.
std::vector<EnsembleRun> ensembleRuns(const EnsemblePlan& plan, bool preparing);

/// The stage a paired run starts after: the one before the preset's first shearing stage.
std::string preparedStage(const std::string& preset);

}  // namespace grainlab::tradeoff
