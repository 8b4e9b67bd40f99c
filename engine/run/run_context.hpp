#pragma once
// Everything one run holds: the world built from the scene, its stages, and the sampler
// that turns the world's state into series rows.
#include <memory>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/stage.hpp"
#include "grainlab/world.hpp"
#include "sampled_boundary.hpp"
#include "sampler.hpp"
#include "validity_monitor.hpp"

namespace grainlab {

class Membrane;

class RunContext {
 public:
  /// Builds the world; throws SceneError or std::exception if the scene cannot be built.
  explicit RunContext(const Scene& scene);
  ~RunContext();

  World& world() { return *world_; }
  /// The stage begun last.
  Stage& stage() { return *stage_; }
  size_t stageIndex() const { return stageIndex_; }
  double totalWork() const;
  Stage& beginStage(size_t index);
  void endStage();
  bool sampleDue() const;
  void sample(RunObserver& observer);
  double peakPhiMobDeg() const { return sampler_->peakPhiMobDeg(); }
  double voidRatioAfterConsolidation() const { return voidRatioAfterConsolidation_; }
  /// The specimen's void ratio now, as the sampler measures it (NaN without a ring or cell).
  double voidRatioNow() const;
  double sampleSeconds() const { return sampleSeconds_; }
  /// The validity envelope's first crossings measured so far (ValidityMonitor).
  /// The validity envelope's warnings: those it started with (addWarnings), then the first
  /// crossings measured so far (ValidityMonitor).
  const std::vector<ValidityWarning>& runWarnings() const { return monitor_.warnings(); }
  void addWarnings(const std::vector<ValidityWarning>& warnings) { monitor_.add(warnings); }
  /// Checkpoints: the world, the ring, the sampler and the current stage, mid-stage. Loading
  /// (into a context just built from the same scene) rebuilds that stage on the loaded world
  /// and then loads its state: stage() is then the stage to go on with.
  void persist(StateArchive& a);
  /// Stage checkpoints (prepared_specimen.cpp): the world, the ring, the sampler and the last
  /// sample's step between two stages, with no stage under way.
  void persistSpecimen(StateArchive& a);
  /// A run started from a prepared specimen: the row the preparation's run sampled last (the
  /// state the specimen was kept in), sampled again from the loaded state.
  void sampleSpecimen(RunObserver& observer);

 private:
  // A periodic scene's cell and particles (the assembly's cell specimen, or explicit ones).
  void buildCell(const Scene& scene);
  std::unique_ptr<Stage> newStage(const StageSpec& spec);

  const Scene& scene_;
  std::unique_ptr<World> world_;
  std::unique_ptr<Membrane> membrane_;
  std::unique_ptr<SampledBoundary> sampled_;  // what the sampler reads: the ring or the cell
  std::unique_ptr<Sampler> sampler_;
  std::unique_ptr<Stage> stage_;
  ValidityMonitor monitor_;
  bool stageStartSample_ = false;  // the next sample is the state a stage starts from
  size_t stageIndex_ = 0;
  double nextSample_ = 0;
  std::int64_t lastSampleStep_ = -1;
  double lastSampleRate_ = 0;  // the ring's strain rate at the last sample (its inertial number)
  double voidRatioAfterConsolidation_ = -1;
  double sampleSeconds_ = 0;
};

}  // namespace grainlab
