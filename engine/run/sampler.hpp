#pragma once
// Turns the world's state into one series row: strains and stresses from the boundary (the
// membrane ring or the periodic cell, through SampledBoundary),
// packing measures, and (if the scene asks) the fabric and the principal stress directions.
// It reads the world and never changes it.
#include <memory>
#include <string>
#include <vector>

#include "grainlab/analysis/histogram.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/contact.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {

class World;
class SampledBoundary;

class Sampler {
 public:
  /// `boundary` null: no stresses or strains (a scene without a boundary).
  Sampler(const OutputSpec& output, const World& world, const SampledBoundary* boundary);

  /// Strains are measured from the boundary's state at the last call (the start of shearing).
  void resetStrainReference();
  /// The row for the world's current state; `stageIndex` and `stage` label it. The peak of
  /// φ_mob is taken over shearing samples only (during compaction σ3 ≈ 0 makes it ~90°).
  Sample measure(int stageIndex, const StageSpec& stage, double strainRate);
  double peakPhiMobDeg() const { return peakPhiMob_; }
  double lastVoidRatio() const { return lastVoidRatio_; }
  /// Checkpoints: the strain references and the running peak.
  void persist(StateArchive& a) {
    a.section("sampler");
    a(stretch1Ref_);
    a(stretch2Ref_);
    a(areaRef_);
    a(meanDiameter_);
    a(peakPhiMob_);
    a(lastVoidRatio_);
  }

 private:
  OutputSpec output_;
  const World& world_;
  const SampledBoundary* boundary_;
  std::vector<unsigned char> inside_;
  std::vector<ContactRecord> contacts_;
  analysis::PolarHistograms histograms_;
  double stretch1Ref_ = 1, stretch2Ref_ = 1, areaRef_ = 0;
  double meanDiameter_ = 0;  // m, of the specimen particles (equal-area discs)
  double peakPhiMob_ = 0;
  double lastVoidRatio_ = -1;
};

}  // namespace grainlab
