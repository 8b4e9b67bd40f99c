#pragma once
// `grainlab sweep SPEC.json --out DIR [--jobs N]`, alone or under mpirun (docs/sweeps.md).
#include <string>
#include <vector>

namespace grainlab {

int sweepCommand(const std::vector<std::string>& args);

}  // namespace grainlab
