#pragma once
// Cyclic biaxial loading (docs/loading-paths.md): the biaxial stage's boundary control
// (σ11 held, or the area), with the axial strain rate reversed at the limits: axial strain
// ±strain_amplitude, or the stress ratio (σ22 − σ11)/(σ22 + σ11) at q_over_p_limits.
#include "membrane_stages.hpp"

namespace grainlab {

/// A cycle: compression up to the upper limit, extension down to the lower one. The stage
/// ends at its 2·cycles-th reversal, on the lower limit.
class CyclicStage : public BiaxialStage {
 public:
  CyclicStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  void afterStep() override;
  bool finished() const override { return reversals_ >= 2 * spec_.cycles || timedOut(); }
  double progress() const override;
  /// Samples along the axial strain path travelled (monotonic through reversals).
  double sampleCoordinate() const override { return path_; }
  void persist(StateArchive& a) override;
  int reversals() const { return reversals_; }

 private:
  /// Whether the loading in its current direction has reached its limit.
  bool atLimit() const;
  double path_ = 0;  // Σ |Δ axial strain| since the start
  int reversals_ = 0;
};

}  // namespace grainlab
