#pragma once
// Which instruction path the contact step takes. The baseline is the scalar code every
// x86-64 runs; the wide path evaluates a discs-only scene's contacts several per instruction,
// on the widest instruction set this CPU has (chosen at run time, so one binary runs
// anywhere), and advances polygons' cos and sin by each step's turn instead of by sincos. The wide path is the default where it is built (it is faster on the disc pile:
// docs/benchmarks.md); GRAINLAB_SIMD=baseline, or a build with the CMake option
// GRAINLAB_SIMD=OFF, forces the baseline. The two differ at rounding level; each gives the
// same bits on every run and with any number of threads.
#include <optional>
#include <string>

namespace grainlab {

enum class SimdPath { Baseline, Wide };

/// The path this process takes: read once from GRAINLAB_SIMD ("baseline" or "wide"; unset
/// means wide; a build without the wide path is always the baseline). Throws
/// std::invalid_argument naming the variable for any other value.
SimdPath simdPath();
/// Tests only: simdPath() returns `path` from now on (std::nullopt: GRAINLAB_SIMD's again).
/// A build without the wide path stays on the baseline.
void overrideSimdPath(std::optional<SimdPath> path);
/// True if this build has the wide path (built with the CMake option GRAINLAB_SIMD on).
bool hasWidePath();
/// The instruction set the wide path runs on this CPU (e.g. "AVX2"), or "baseline".
std::string simdTargetName();

}  // namespace grainlab
