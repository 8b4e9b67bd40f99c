#pragma once
// Loading in a periodic cell: the cell's velocity gradient L, written as in the membrane
// (engine/include/grainlab/membrane.hpp) through the strain rate D (compression positive) and
// the spin w, L = [[−D11, −D12 + w], [−D12 − w, −D22]]. Each of D11, D22 and D12 is either
// prescribed or set by a servo that holds a stress component (σ11, σ22, or the symmetric
// shear ½(σ12 + σ21)) at its target; the stress is Love's over the cell's area, with branch
// vectors to the images (docs/periodic-cell.md).
//
// The servo law, per held component: D = clamp(kp e + ki ∫e dt, ±cap) with the error
// e = target − σ (Pa), kp = 1 / (M τ), ki = kp / (4 τ): a strain rate that would remove
// the error in τ against the packing's modulus M = k_n / 2 (as the membrane's servos), with
// τ = `crossings` elastic-wave crossings of the cell (√A / √(M/ρ)); the integral only while
// not capped (anti-windup). The stress is measured four times per τ.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grainlab/scene.hpp"
#include "grainlab/stage.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {

/// One component of the cell's strain rate: prescribed, or held at a stress by a servo.
struct CellComponent {
  bool held = false;  ///< true: a servo sets the rate to hold `stress`
  double rate = 0;    ///< 1/s, compression positive, when prescribed
  double stress = 0;  ///< Pa, compression positive, the target when held

  static CellComponent prescribed(double rate) { return {false, rate, 0}; }
  static CellComponent holding(double stress) { return {true, 0, stress}; }
};

/// What a cell stage imposes.
struct CellLoading {
  CellComponent d11, d22, d12;
  double spin = 0;  ///< w, rad/s
  /// Stress-controlled rotation of the principal axes at constant p and q: when q > 0, every
  /// component is held, with targets σ11, σ22 = p ± q cos 2θ and ½(σ12 + σ21) = q sin 2θ, and
  /// θ = θ0 + θ̇ t turning (the strain rate is measured, not imposed).
  struct Rotation {
    double p = 0, q = 0;           ///< Pa
    double angle0 = 0, rate = 0;   ///< θ0 (rad) and θ̇ (rad/s)
  } rotation;
  /// The largest |D| a servo may command, 1/s (a quasi-static bound: the inertial number
  /// I = |D| d √(ρ/p) stays below 1e-3 for |D| ≤ 1e-3 √(p/ρ) / d).
  double rateCap = 1;
  /// Servo response time in elastic-wave crossings of the cell.
  double crossings = 0.5;
};

/// A servo on one stress component (see the file comment).
struct CellServo {
  double target = 0;             ///< Pa
  double kp = 0, ki = 0, cap = 0;  ///< 1/(Pa s), 1/(Pa s²), 1/s
  double integral = 0;           ///< ∫ e dt, Pa s
  double rate(double stress, double dt);
};

class CellStage : public Stage {
 public:
  /// A stage of `duration` seconds in the world's periodic cell (std::invalid_argument if the
  /// world has none).
  CellStage(std::string name, const CellLoading& loading, World& world, double duration, double sampleInterval);

  const std::string& name() const override { return name_; }
  void beforeStep() override;
  void afterStep() override;
  bool finished() const override { return world_.time() - startTime_ >= duration_; }
  double progress() const override;
  double sampleCoordinate() const override { return world_.time() - startTime_; }
  double sampleSpacing() const override { return sampleInterval_; }
  void persist(StateArchive& a) override;

  /// The stress at the last measurement (Love's, over the cell).
  const StressTensor& stress() const { return stress_; }
  /// Measures it now (also sets stress()).
  const StressTensor& measureStress();
  /// The strain rate D (compression positive) commanded at the last control step, 1/s.
  const Eigen::Matrix2d& strainRate() const { return D_; }
  /// Steps between stress measurements (and servo updates).
  int measureEvery() const { return measureEvery_; }
  /// A rotation's axes turn from this time on (θ = θ0 + θ̇ (t − time), θ0 before it); by
  /// default from the stage's start. Not saved by persist(): the caller that moves it says it
  /// again after loading.
  void turnAxesFrom(double time) { turnStart_ = time; }

 private:
  void control();

  std::string name_;
  CellLoading loading_;
  World& world_;
  double duration_, sampleInterval_;
  double startTime_;
  double turnStart_;
  int measureEvery_ = 1;
  double dtControl_ = 0;
  std::int64_t stepsDone_ = 0;
  CellServo servo11_, servo22_, servo12_;
  StressTensor stress_;
  Eigen::Matrix2d D_ = Eigen::Matrix2d::Zero();
  std::vector<unsigned char> inside_;
};

/// The scene's rotation stage in a cell (engine/src/cell_rotation_stage.cpp): the stress brought
/// to (p, q) at θ0, then turned at constant p and q.
std::unique_ptr<Stage> makeCellRotationStage(const StageSpec& spec, const OutputSpec& output, World& world,
                                             double rateCap);

}  // namespace grainlab
