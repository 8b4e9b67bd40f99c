#include "cyclic_stage.hpp"

#include <algorithm>
#include <cmath>

namespace grainlab {

CyclicStage::CyclicStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane)
    : BiaxialStage(spec, output, world, membrane) {}

bool CyclicStage::atLimit() const {
  if (spec_.strainAmplitude) {
    const double a = *spec_.strainAmplitude;
    return axialRate_ > 0 ? axialStrain() >= a : axialStrain() <= -a;
  }
  // The stress is measured every few steps; between measurements the last one stands.
  const double sum = stress_.s22 + stress_.s11;
  if (!(sum > 0)) return false;
  const double ratio = (stress_.s22 - stress_.s11) / sum;
  return axialRate_ > 0 ? ratio >= spec_.qOverPLimits->second : ratio <= spec_.qOverPLimits->first;
}

void CyclicStage::afterStep() {
  const double before = axialStrain();
  BiaxialStage::afterStep();
  path_ += std::abs(axialStrain() - before);
  if (reversals_ < 2 * spec_.cycles && atLimit()) {
    ++reversals_;
    if (reversals_ < 2 * spec_.cycles) setAxialRate(-axialRate_);
  }
}

double CyclicStage::progress() const {
  if (finished()) return 1;
  // Within a half cycle, by strain toward the amplitude where there is one.
  double within = 0;
  if (spec_.strainAmplitude) {
    const double a = *spec_.strainAmplitude;
    const double target = axialRate_ > 0 ? a : -a;
    const double from = reversals_ == 0 ? 0.0 : -target;
    within = std::clamp((axialStrain() - from) / (target - from), 0.0, 1.0);
  }
  return (reversals_ + within) / (2.0 * spec_.cycles);
}

void CyclicStage::persist(StateArchive& a) {
  BiaxialStage::persist(a);
  a(path_);
  a(reversals_);
}

}  // namespace grainlab
