#pragma once
// report.html: one self-contained page (inline CSS and SVG, no scripts, no external
// resources) with the runs, the findings table and every figure.
#include <span>
#include <string>
#include <vector>

#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/draw/figures.hpp"
#include "grainlab/studies/paper/findings.hpp"

namespace grainlab::report {

struct ReportContext {
  std::string command;        ///< the command line that made the report
  bool quick = false;         ///< the -quick presets
  unsigned concurrentRuns = 1;  ///< 0: the report was rebuilt from runs already on disk
  int seeds = 1;              ///< runs (seeds) per assembly
  double wallSeconds = 0;     ///< s, all runs and the report
};

/// The runs' table as CSV (runs.csv), one row per run (assembly and seed): status, particles,
/// wall time, void ratios, peak φ_mob during shearing, its output directory.
CsvTable runsTable(std::span<const AssemblyResult> runs);
/// The findings as CSV (findings.csv): number, claim, criterion, verdict, measured, note.
CsvTable findingsTable(const std::vector<Finding>& findings);

/// The whole page. Links to the CSVs are relative (they sit beside report.html).
std::string renderReportHtml(std::span<const AssemblyResult> runs, const std::vector<Finding>& findings,
                             const std::vector<Figure>& figures, const ReportContext& context);

}  // namespace grainlab::report
