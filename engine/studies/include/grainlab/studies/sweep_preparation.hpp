#pragma once
// A sweep that prepares each seed's specimen once (docs/sweeps.md, "Prepare once per seed"):
// the spec's "prepare": {"stage": NAME} makes one preparation run per distinct seed, which
// runs the base scene's stages up to NAME and stops, into DIR/specimens/seed-<N>/; every run
// of the sweep then starts from its seed's specimen ("start_from") and runs only the stages
// after NAME. Varied paths may touch only what comes after the specimen.
#include <filesystem>
#include <string>
#include <vector>

#include "grainlab/studies/run_batch.hpp"
#include "grainlab/studies/sweep_spec.hpp"

namespace grainlab::studies {

struct SweepPreparation {
  std::string stage;               ///< the stage whose end each specimen is
  std::vector<BatchRun> specimens; ///< one preparation run per distinct seed, in order of first use
};

/// Checks the spec's "prepare" against its runs and plans the preparations: a stage the base
/// does not have, one with no stage after it, or a varied path that changes the preparation
/// (anything but seed, name, output, solver apart from solver.engine, and stages after the
/// prepared one) throws SceneError naming "prepare.stage" or "vary.<path>". Then gives every
/// run a start_from its seed's specimen and a "specimen" parameter (sweep.csv's column, the
/// specimen's folder relative to outDir).
SweepPreparation prepareSweep(const SweepSpec& spec, std::vector<SweepRun>& runs, const std::filesystem::path& outDir);

}  // namespace grainlab::studies
