#pragma once
#include <string>
#include <vector>

namespace grainlab {

/// `grainlab paper --out DIR [--quick] [--jobs N] [--report-only]`: runs the paper's six
/// assemblies (N at a time, at most the hardware threads; default all of them), progress on
/// stderr, and writes DIR/report.html with the CSV behind every figure. --report-only runs
/// nothing and rebuilds the report from DIR/runs/. Exit 0 when every run completed, 1 when one
/// failed (the report is written all the same), 2 for bad arguments.
int paperCommand(const std::vector<std::string>& args);

}  // namespace grainlab
