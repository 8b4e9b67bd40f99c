#pragma once
// Which instruction path the contact step takes. The baseline is the scalar code every
// x86-64 runs; the wide path evaluates batches of contacts several per instruction, on the
// widest instruction set this CPU has (chosen at run time, so one binary runs anywhere).
// GRAINLAB_SIMD=baseline (or a build with GRAINLAB_SIMD=OFF) forces the baseline.
#include <string>

namespace grainlab {

enum class SimdPath { Baseline, Wide };

/// The path this process takes: read once from GRAINLAB_SIMD ("baseline" or "wide"; unset
/// means wide where the build has it). Throws std::invalid_argument naming the variable for
/// any other value.
SimdPath simdPath();
/// The instruction set the wide path runs on this CPU (e.g. "AVX2"), or "baseline".
std::string simdTargetName();

}  // namespace grainlab
