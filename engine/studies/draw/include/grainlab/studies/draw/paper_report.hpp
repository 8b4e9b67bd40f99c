#pragma once
// `grainlab paper`'s report, drawn from the runs its study read back: DIR/report.html, the
// CSV behind every figure (DIR/fig06.csv ... fig15.csv, roses.csv), runs.csv, findings.csv
// and each chart as a standalone SVG in DIR/svg/.
#include <ostream>
#include <string>
#include <vector>

#include "grainlab/studies/paper/findings.hpp"
#include "grainlab/studies/paper/paper_study.hpp"

namespace grainlab::report {

/// Writes every file of the report of `study` into options.outDir (creating it and svg/ if
/// needed); returns the findings. A line saying where it went and the time since the study
/// began goes to `progress` (may be null). Throws std::runtime_error if a file cannot be written.
std::vector<Finding> writePaperReport(const PaperOptions& options, const PaperStudy& study, std::ostream* progress);

}  // namespace grainlab::report
