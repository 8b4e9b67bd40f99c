#pragma once
// Which instruction path the contact step takes. The baseline is the scalar code every
// x86-64 runs; the wide path evaluates batches of contacts several per instruction, on the
// widest instruction set this CPU has (chosen at run time, so one binary runs anywhere).
// GRAINLAB_SIMD=wide opts in; unset or "baseline" (or a build with GRAINLAB_SIMD=OFF) is the
// baseline, which is faster today. Both give the same bits.
#include <optional>
#include <string>

namespace grainlab {

enum class SimdPath { Baseline, Wide };

/// The path this process takes: read once from GRAINLAB_SIMD ("baseline" or "wide"; unset
/// means baseline; "wide" in a build without it means baseline). Throws std::invalid_argument naming the variable for
/// any other value.
SimdPath simdPath();
/// Tests only: simdPath() returns `path` from now on (std::nullopt: GRAINLAB_SIMD's again).
/// A build without the wide path stays on the baseline.
void overrideSimdPath(std::optional<SimdPath> path);
/// True if this build has the wide path (built with the CMake option GRAINLAB_SIMD on).
bool hasWidePath();
/// The instruction set the wide path runs on this CPU (e.g. "AVX2"), or "baseline".
std::string simdTargetName();

}  // namespace grainlab
