#pragma once
// `grainlab shapes`: the shape-fidelity trade measured on seed ensembles. Each representation
// (representation.hpp) runs `seeds` seeds of each assembly's preset, every run from its own
// generated specimen; the hexagons are the reference. Different shapes cannot share a
// specimen, so each comparison is between independent ensembles: the bias is the difference
// of the means and its 95% interval Welch's, with Student's t on the Welch–Satterthwaite
// degrees of freedom (tradeoff/paired_bias.hpp), on the quantities of the ensemble trade-off
// (tradeoff/ensemble_quantities.hpp) and the void ratio after consolidation. Discs, rolling or
// not, run once per seed and are compared with both assemblies' hexagons.
//
// Each finished run leaves DIR/runs/<key>.json (its status, CPU seconds and values); a run
// whose file is there is not run again (a failed one neither: delete its file to retry), so the
// study can be run in pieces and resumed. Writes
// DIR/shapes.csv (one row per assembly, representation and quantity, with the seeds per
// ensemble its tolerance would need: runs_for_tolerance), DIR/runs.csv,
// DIR/calibration.csv (the rolling discs' mean peak φ_mob per μ_r and the μ_r interpolated to
// the hexagons' on the random assembly) and DIR/scenes/.
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/studies/shape_fidelity/representation.hpp"
#include "grainlab/studies/shape_fidelity/rolling_calibration.hpp"
#include "grainlab/studies/tradeoff/pareto_panel.hpp"

namespace grainlab::shapes {

struct ShapeStudyOptions {
  std::string outDir;
  bool quick = true;                            ///< the -quick presets (250-odd particles)
  int seeds = 8;                                ///< per representation and assembly (≥ 2)
  unsigned jobs = 0;                            ///< runs at once; 0 = hardware threads
  std::vector<Representation> representations;  ///< compared with the hexagons (always run)
  std::vector<std::string> assemblies;          ///< of shapeAssemblies(); empty: both
};

struct ShapeStudy {
  std::size_t runs = 0;         ///< in the study
  std::size_t runsSkipped = 0;  ///< found done in DIR/runs and not run again
  std::size_t failedRuns = 0;
  RollingCalibration calibration;          ///< on the random assembly (NaN without it or rolling runs)
  std::vector<tradeoff::ParetoPanel> panels;  ///< per assembly: CPU s per run against |bias| of peak φ_mob
};

/// The quantities each run is judged on: ensembleQuantities() and void_ratio_consolidated.
std::vector<std::string> shapeQuantityNames();

/// Runs what is not done yet and writes the tables. Throws SceneError naming the option for
/// bad options, before running anything.
ShapeStudy runShapeStudy(const ShapeStudyOptions& options, std::ostream* progress);

}  // namespace grainlab::shapes
