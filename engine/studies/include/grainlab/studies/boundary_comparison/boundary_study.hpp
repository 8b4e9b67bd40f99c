#pragma once
// `grainlab boundaries`: the ring and the periodic cell side by side on seed ensembles. For
// each assembly (circular, bedding-30) each boundary (boundary.hpp) runs its preset over seeds
// 1..N, each run from its own specimen, so ring and cell are independent ensembles: every
// quantity gets its mean and 95 % interval per boundary, and the difference boundary − ring its
// Welch interval (tradeoff/paired_bias.hpp, Student's t on the Welch–Satterthwaite degrees of
// freedom). The curves of φ_mob, a_c and ω against axial strain are averaged strain by strain
// on a common grid (run_profile.hpp).
//
// The runs go through the paper's executor (paper/parallel_runs.hpp): each into
// DIR/runs/<boundary>-<preset>/seed-<s>/ with everything `grainlab run` writes; a run completed
// for the same scene is kept, so the study resumes. Writes DIR/boundaries.csv (assembly,
// boundary, quantity: mean, interval, difference from the ring with its Welch interval),
// DIR/runs.csv (one row per run) and DIR/curves.csv (assembly, boundary, quantity, strain:
// mean and interval).
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/studies/boundary_comparison/boundary.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"

namespace grainlab::boundaries {

struct BoundaryStudyOptions {
  std::string outDir;
  bool quick = true;                      ///< the -quick presets
  int seeds = 8;                          ///< per boundary and assembly (≥ 2)
  unsigned jobs = 0;                      ///< runs at once; 0 = hardware threads
  std::vector<Boundary> boundaries;       ///< empty: ring, cell, cell-matched (the ring always runs)
  std::vector<std::string> assemblies;    ///< of boundaryAssemblies(); empty: both
  double axialStrain = 0;                 ///< > 0: shearing ends there (shortened runs)
  double curveStep = 0.005;               ///< the curves' grid of axial strain
};

/// One curve of one ensemble: mean and interval at each grid strain.
struct EnsembleCurve {
  std::string assembly, boundary, quantity;
  std::vector<double> strain;
  std::vector<report::MeanInterval> stats;
};

struct BoundaryStudy {
  size_t runs = 0, failedRuns = 0;
  std::vector<EnsembleCurve> curves;
};

/// The quantities of boundaries.csv, in order.
std::vector<std::string> boundaryQuantityNames();

/// Runs what is not done yet and writes the tables. Throws SceneError naming the option for
/// bad options, before anything is run or written.
BoundaryStudy runBoundaryStudy(const BoundaryStudyOptions& options, std::ostream* progress);

}  // namespace grainlab::boundaries
