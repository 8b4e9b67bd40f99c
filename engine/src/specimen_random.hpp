#pragma once
// The specimen generator's random numbers. std::mt19937_64's output sequence is fixed by the
// C++ standard, but std::uniform_real_distribution is not, so doubles come from our own
// conversion: the same seed gives the same specimen with any standard library.
#include <cstdint>
#include <random>

namespace grainlab::specimen {

class SpecimenRandom {
 public:
  explicit SpecimenRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform on [0, 1): the top 53 bits of one 64-bit draw, exactly representable.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform on [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace grainlab::specimen
