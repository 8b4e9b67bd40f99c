#pragma once
// Rotation of the principal strain-rate axes (docs/loading-paths.md): the deviatoric strain
// rate keeps its magnitude while its major (compressive) direction turns at a constant
// angular speed, and a servo on the volumetric part holds the mean stress.
#include "membrane_stages.hpp"

namespace grainlab {

/// D = ε̇v/2 · I + (d/2)[[cos 2θ, sin 2θ], [sin 2θ, −cos 2θ]], θ = θ0 + Ω t, d = ε̇1 − ε̇3.
class RotationStage : public MembraneStage {
 public:
  RotationStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  void beforeStep() override;
  bool finished() const override { return elapsed() >= spec_.duration * (1 - 1e-12) || timedOut(); }
  double progress() const override { return std::min(1.0, elapsed() / spec_.duration); }
  double sampleSpacing() const override { return sampleSpacing_; }
  double work() const override { return stageWork(spec_.type); }
  void persist(StateArchive& a) override;
  /// The prescribed direction of the major principal strain rate now, degrees (unwrapped).
  double directionDeg() const { return spec_.initialDirectionDeg + spec_.rotationRateDeg * elapsed(); }

 private:
  double elapsed() const { return world_.time() - startTime_; }
  void control() override;
  StressServo servo_;
  double volumetricRate_ = 0;  // 1/s per axis, compression positive, from the servo
  double sampleSpacing_;
};

}  // namespace grainlab
