#include "simple_shear_stage.hpp"

namespace grainlab {

SimpleShearStage::SimpleShearStage(const StageSpec& spec, const OutputSpec& output, World& world,
                                   Membrane& membrane)
    : MembraneStage(spec, output, world, membrane), sampleStrain_(output.sampleStrain) {
  controlAsShearing();
  servo22_ = makeShearServo(spec.pressure, quasiStaticRateCap(spec.pressure));
}

void SimpleShearStage::control() {
  servo22_.maxRate = quasiStaticRateCap(spec_.pressure);
  const double gammaDot = spec_.shearRate;
  membrane_.setStrainRate(0.0, servo22_.rate(stress_.s22, dtControl_), -0.5 * gammaDot, 0.5 * gammaDot);
}

void SimpleShearStage::persist(StateArchive& a) {
  MembraneStage::persist(a);
  a(meanDiameter_);
  a(servo22_);
  a(sampleStrain_);
}

}  // namespace grainlab
