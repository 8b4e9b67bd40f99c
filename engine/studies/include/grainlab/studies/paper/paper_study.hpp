#pragma once
// `grainlab paper`'s runs, in three steps: (1) list them, N seeds of each of the six
// assemblies (run_plan); (2) execute them, each writing only its own directory
// DIR/runs/<preset>/seed-<s>/ (parallel_runs); (3) read them back from disk. The report is
// drawn from what step 3 read (grainlab/studies/draw/paper_report.hpp).
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/studies/paper/assembly_result.hpp"

namespace grainlab::studies { class Cluster; }

namespace grainlab::report {

/// circular, elongated-random, elongated-bedding-{0,30,60,90}; with `quick` their -quick variants.
std::vector<std::string> paperPresets(bool quick);

struct PaperOptions {
  std::string outDir;
  bool quick = false;
  unsigned jobs = 0;          ///< runs at once; 0 = hardware threads (never more than those)
  int seeds = 1;              ///< seeds 1..seeds of each assembly (independent random packings)
  std::string command;        ///< shown in the report
  /// Run nothing: rebuild the report from the runs already in outDir/runs/ (as an earlier
  /// `grainlab paper` left them: every seed-<s> folder found, or the older single-run layout
  /// runs/<preset>/), e.g. after the report's code changed. `seeds` is then ignored.
  bool reportOnly = false;
  /// The MPI world to spread the runs over (as `grainlab sweep` does); null: this process
  /// alone. Only rank 0 reads the runs back (and writes the report).
  const studies::Cluster* cluster = nullptr;
};

struct PaperStudy {
  std::vector<AssemblyResult> runs;  ///< every run, read back from disk, preset by preset
  unsigned concurrentRuns = 0;       ///< runs at once; 0: nothing ran (reportOnly)
  int seeds = 0;                     ///< runs per assembly as found on disk
  double wallSeconds = 0;            ///< s, from the start to the runs read back
};

/// Runs the six assemblies' ensembles (progress lines to `progress`, may be null), or with
/// reportOnly runs nothing, then reads every run back from disk. A run that cannot be read
/// back counts as failed. Ranks other than 0 only run, and get an empty study.
PaperStudy runPaperStudy(const PaperOptions& options, std::ostream* progress);

}  // namespace grainlab::report
