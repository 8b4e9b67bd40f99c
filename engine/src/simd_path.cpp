#include "grainlab/simd_path.hpp"

#include <cstdlib>
#include <stdexcept>

#include "disc_pair_kernel.hpp"

namespace grainlab {
namespace {

SimdPath readPath() {
  const char* value = std::getenv("GRAINLAB_SIMD");
  const std::string v = value ? value : "";
  if (!v.empty() && v != "baseline" && v != "wide") {
    throw std::invalid_argument("GRAINLAB_SIMD: \"" + v + "\" is not a path (baseline or wide)");
  }
#ifdef GRAINLAB_HAS_WIDE_SIMD
  // The wide path unless told otherwise: it is the faster on the disc pile (docs/benchmarks.md).
  return v == "baseline" ? SimdPath::Baseline : SimdPath::Wide;
#else
  return SimdPath::Baseline;  // this build has no wide path
#endif
}

std::optional<SimdPath> overridden;

}  // namespace

SimdPath simdPath() {
  static const SimdPath path = readPath();
#ifdef GRAINLAB_HAS_WIDE_SIMD
  if (overridden) return *overridden;
#endif
  return path;
}

void overrideSimdPath(std::optional<SimdPath> path) { overridden = path; }

bool hasWidePath() {
#ifdef GRAINLAB_HAS_WIDE_SIMD
  return true;
#else
  return false;
#endif
}

std::string simdTargetName() {
#ifdef GRAINLAB_HAS_WIDE_SIMD
  if (simdPath() == SimdPath::Wide) return discPairKernelTarget();
#endif
  return "baseline";
}

}  // namespace grainlab
