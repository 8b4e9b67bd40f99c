#pragma once
#include <string>
#include <vector>

namespace grainlab {

/// `grainlab boundaries --out DIR [--full] [--seeds N] [--jobs N] [--boundaries A,B]
/// [--assemblies A,B] [--axial-strain E]`: the ring and the periodic cell side by side
/// (boundaries.csv, runs.csv, curves.csv, curves.svg). Returns the exit code.
int boundariesCommand(const std::vector<std::string>& args);

}  // namespace grainlab
