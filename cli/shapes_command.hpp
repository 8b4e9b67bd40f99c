#pragma once
// `grainlab shapes --out DIR [--full] [--seeds N] [--jobs N] [--representations A,B]
// [--assemblies A,B]`: the shape-fidelity trade on seed ensembles (hexagons the reference;
// clumps, rolling discs and discs against them). Resumes: runs already done in DIR are kept.
// Writes DIR/shapes.csv, runs.csv, calibration.csv and shapes.svg (docs/shape-fidelity.md).
#include <string>
#include <vector>

namespace grainlab {

int shapesCommand(const std::vector<std::string>& args);

}  // namespace grainlab
