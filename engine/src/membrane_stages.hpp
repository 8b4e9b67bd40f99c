#pragma once
// The loading stages of the paper's biaxial test, all driven through the membrane ring:
// compaction (stage 0), isotropic consolidation (stage 1), biaxial shearing (stage 2), the
// last also at constant volume. The loading paths beyond it build on MembraneStage in their
// own files (rotation_stage, cyclic_stage, simple_shear_stage).
#include <vector>

#include "grainlab/membrane.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/stage.hpp"
#include "servo.hpp"

namespace grainlab {

/// Shared machinery: the stress is measured from the contacts every few steps (often
/// enough for the servo, rarely enough to cost little), and the ring is moved.
class MembraneStage : public Stage {
 public:
  MembraneStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  const std::string& name() const override { return spec_.name; }
  void beforeStep() override;
  void afterStep() override;
  double sampleCoordinate() const override { return world_.time() - startTime_; }
  double sampleSpacing() const override { return sampleInterval_; }
  const StressTensor& stress() const { return stress_; }
  void persist(StateArchive& a) override;

 protected:
  /// Called after each stress measurement: choose the strain rates.
  virtual void control() = 0;
  bool timedOut() const { return world_.time() - startTime_ >= spec_.maxTime; }
  std::string endNote() const override;
  /// A servo whose response time is `crossings` times the time a wave takes to cross the
  /// specimen.
  StressServo makeServo(double target, double maxRate, double crossings) const;
  /// The time a compression wave takes to cross the specimen (modulus ≈ k_n/2), s.
  double crossingTime() const;
  // The response time, in wave crossings, for a servo the DEM runs at `demCrossings`.
  double servoCrossings(double demCrossings) const;
  /// Shearing stages measure the stress several times per response time of a shearing
  /// servo (sets measureEvery_, dtControl_) and know the specimen's mean diameter.
  void controlAsShearing();
  /// A servo as fast as the biaxial stage's lateral one.
  StressServo makeShearServo(double target, double maxRate) const;
  /// The largest strain rate that keeps I = ε̇ d √(ρ/p) at the quasi-static bound, with p
  /// the measured mean stress but never below `floorStress`.
  double quasiStaticRateCap(double floorStress) const;

  StageSpec spec_;
  World& world_;
  Membrane& membrane_;
  StressTensor stress_;
  double startTime_;
  double sampleInterval_;
  int measureEvery_;      // steps between stress measurements
  double dtControl_ = 0;  // s between stress measurements
  int stepsSinceMeasure_ = 0;
  bool started_ = false;
  double meanDiameter_ = 0;  // m, of the specimen particles (equal-area discs); shearing only
};

/// Shrinks the ring equally on both axes, frictionless by default, until the void ratio
/// inside the ring reaches `voidRatio` (the particles are close, with almost no force between
/// them) or p reaches `pressure`, whichever comes first.
class CompactionStage : public MembraneStage {
 public:
  CompactionStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  bool finished() const override { return done_ || timedOut(); }
  /// By area, from the start toward the target void ratio, or without one toward a jammed
  /// packing (solid fraction ~0.8): the pressure says nothing until the particles touch.
  double progress() const override;
  void persist(StateArchive& a) override;

 private:
  void control() override;
  bool done_ = false;
  double startArea_ = 0, jammedArea_ = 0;
  mutable double progress_ = 0;
};

/// Servo-controls σ11 and σ22 to the target pressure, until p is there and the volume has
/// stopped changing.
class ConsolidationStage : public MembraneStage {
 public:
  ConsolidationStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  bool finished() const override { return done_ || timedOut(); }
  double progress() const override;
  void persist(StateArchive& a) override;

 private:
  void control() override;
  StressServo servo11_, servo22_;
  double windowStart_ = 0, windowArea_ = 0;
  bool done_ = false;
};

/// Compresses axis 2 at the prescribed rate while a servo holds σ11, up to the target
/// axial strain. The servo is faster than consolidation's (0.1 wave crossings, the stress
/// measured 4 times per response time) and the lateral rate is capped where the inertial
/// number reaches 0.8e-3, not at a multiple of the axial rate (docs/biaxial-test.md).
/// With "lateral": "constant_volume" the lateral rate keeps the enclosed area instead.
class BiaxialStage : public MembraneStage {
 public:
  BiaxialStage(const StageSpec& spec, const OutputSpec& output, World& world, Membrane& membrane);
  bool finished() const override { return axialStrain() >= spec_.targetAxialStrain || timedOut(); }
  double progress() const override { return std::min(1.0, axialStrain() / spec_.targetAxialStrain); }
  double sampleCoordinate() const override { return axialStrain(); }
  double sampleSpacing() const override { return sampleStrain_; }
  double work() const override { return stageWork(spec_.type); }
  void persist(StateArchive& a) override;

 protected:
  double axialStrain() const { return 1.0 - membrane_.stretch2() / stretch2Start_; }
  void control() override;
  /// Changes the axial rate at once (a cyclic reversal), the lateral rate kept or, at
  /// constant volume, matched to it.
  void setAxialRate(double rate);
  double axialRate_;       // 1/s, compression positive; the spec's rate until reversed
  double sampleStrain_;

 private:
  /// The largest lateral rate that keeps I = ε̇ d √(ρ/p) at kMaxInertial, with p the
  /// measured mean stress but never below the held σ11 (p ≥ σ11 while shearing; the floor
  /// keeps a collapse of p from freezing the ring just when it must close in).
  double lateralRateCap() const;
  /// Constant volume: the lateral rate that keeps the ring's area at its start.
  double constantVolumeRate() const;
  StressServo servo11_;
  double stretch2Start_;
  double areaStart_;
};

}  // namespace grainlab
