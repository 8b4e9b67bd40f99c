#pragma once
// `grainlab paper` end to end, in three steps: (1) list the runs, N seeds of each of the six
// assemblies (run_plan); (2) execute them, each writing only its own directory
// DIR/runs/<preset>/seed-<s>/ (parallel_runs); (3) read them back from disk and write
// DIR/report.html, the CSV behind every figure (DIR/fig06.csv ... fig15.csv, roses.csv),
// runs.csv, findings.csv and each chart as a standalone SVG in DIR/svg/.
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "grainlab/report/assembly_result.hpp"
#include "grainlab/report/findings.hpp"
#include "grainlab/report/html_report.hpp"

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
  /// alone. Only rank 0 writes the report.
  const studies::Cluster* cluster = nullptr;
};

struct PaperOutcome {
  std::vector<AssemblyResult> runs;  ///< every run, read back from disk, preset by preset
  std::vector<Finding> findings;
  double wallSeconds = 0;     ///< s
  bool allCompleted = false;
};

/// Writes every file of the report from finished runs; returns the findings. Creates outDir
/// (and svg/) if needed; throws std::runtime_error if a file cannot be written.
std::vector<Finding> writePaperReport(const std::string& outDir, std::span<const AssemblyResult> runs,
                                      const ReportContext& context);

/// Runs the six assemblies' ensembles (progress lines to `progress`, may be null), or with
/// reportOnly runs nothing, then reads every run back from disk and writes the report. A run
/// that cannot be read back counts as failed.
PaperOutcome runPaper(const PaperOptions& options, std::ostream* progress);

}  // namespace grainlab::report
