#include "rotation_stage.hpp"

#include <cmath>

namespace grainlab {

RotationStage::RotationStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane)
    : MembraneStage(spec, output, world, membrane),
      // Two degrees of a full turn per sample unless the scene says otherwise.
      sampleSpacing_(output.sampleInterval > 0 ? output.sampleInterval : spec.duration / 180) {
  controlAsShearing();
  servo_ = makeShearServo(spec.pressure, quasiStaticRateCap(spec.pressure));
}

void RotationStage::control() {
  servo_.maxRate = quasiStaticRateCap(spec_.pressure);
  volumetricRate_ = servo_.rate(stress_.p(), dtControl_);
}

void RotationStage::beforeStep() {
  if (!started_) {
    started_ = true;
    control();
  }
  // The direction is set every step (the servo acts only every few): at the time the step
  // starts, so the ring's measured motion follows θ0 + Ω t to within one step.
  const double twoTheta = 2 * radians(directionDeg());
  const double half = 0.5 * spec_.deviatoricStrainRate;
  membrane_.setStrainRate(volumetricRate_ + half * std::cos(twoTheta), volumetricRate_ - half * std::cos(twoTheta),
                          half * std::sin(twoTheta), 0.0);
  membrane_.applyVelocities();
}

void RotationStage::persist(StateArchive& a) {
  MembraneStage::persist(a);
  a(meanDiameter_);
  a(servo_);
  a(volumetricRate_);
  a(sampleSpacing_);
}

}  // namespace grainlab
