#pragma once
// Simple shear (docs/loading-paths.md): the ring follows v1 = γ̇ (x2 − c2), the shear plane
// horizontal, while a servo on the vertical rate holds the normal stress σ22 on it.
#include "membrane_stages.hpp"

namespace grainlab {

/// L = [[0, γ̇], [0, −ε̇22]]: D = [[0, −γ̇/2], [−γ̇/2, ε̇22]] (compression positive), spin γ̇/2.
class SimpleShearStage : public MembraneStage {
 public:
  SimpleShearStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  bool finished() const override { return shearStrain() >= spec_.targetShearStrain || timedOut(); }
  double progress() const override { return std::min(1.0, shearStrain() / spec_.targetShearStrain); }
  double sampleCoordinate() const override { return shearStrain(); }
  double sampleSpacing() const override { return sampleStrain_; }
  double work() const override { return stageWork(spec_.type); }
  void persist(StateArchive& a) override;

 private:
  /// γ since the stage began (engineering shear strain).
  double shearStrain() const { return spec_.shearRate * (world_.time() - startTime_); }
  void control() override;
  StressServo servo22_;
  double sampleStrain_;
};

}  // namespace grainlab
