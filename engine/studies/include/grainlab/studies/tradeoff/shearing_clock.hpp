#pragma once
// The thread's CPU time at the last sample before the shearing stage (the preparation's last,
// taken as its last stage ends): what preparing, or loading, the specimen cost. The trade-off
// splits a run's CPU time there (`grainlab tradeoff --seeds N`'s cpu_s and preparation_cpu_s),
// the CLI around runScene and the server around each run it runs.
#include <limits>
#include <string>

#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::tradeoff {

class ShearingClock : public RunObserver {
 public:
  /// `shearing`: the name of the stage whose start ends the preparation (shearingStageName).
  explicit ShearingClock(std::string shearing) : shearing_(std::move(shearing)) {}
  void onSample(const Sample& sample, const World&) override {
    if (sample.stage != shearing_ && !shearingSeen_) reached_ = threadCpuSeconds();
    shearingSeen_ = shearingSeen_ || sample.stage == shearing_;
  }
  /// threadCpuSeconds() then; NaN if no sample came before the shearing stage.
  double reached() const { return reached_; }

 private:
  std::string shearing_;
  double reached_ = std::numeric_limits<double>::quiet_NaN();
  bool shearingSeen_ = false;
};

/// The name of the scene's first shearing stage; empty if it has none.
inline std::string shearingStageName(const Scene& scene) {
  for (const StageSpec& s : scene.stages)
    if (isShearing(s.type)) return s.name;
  return {};
}

}  // namespace grainlab::tradeoff
