#pragma once
// `grainlab tradeoff --out DIR [--quick] [--jobs N] [--presets A,B] [--axes A,B] [--cost cpu|wall]`:
// speed against accuracy.
// Sweeps timestep safety, shearing inertial number, polygon vertex count, sampling interval
// (and the engine, where the parser takes "box2d") on quick presets; measures each run's
// wall and CPU time and its errors against the most accurate reference run; writes
// DIR/tradeoff.csv, DIR/pareto.svg and DIR/scenes/*.json (docs/speed-accuracy.md).
#include <string>
#include <vector>

namespace grainlab {

int tradeoffCommand(const std::vector<std::string>& args);

}  // namespace grainlab
