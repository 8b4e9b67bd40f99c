#pragma once
// A run's files, stopped (as SIGTERM would stop it) once its progress passes `stopAt`: the
// first half of a kill-and-resume test.
#include <filesystem>
#include <string_view>

#include "grainlab/run_output.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/world.hpp"

namespace grainlab::testing {

class StoppingOutput : public RunOutput {
 public:
  StoppingOutput(const std::filesystem::path& dir, const Scene& scene, double stopAt)
      : RunOutput(dir.string(), scene, nullptr), stopAt_(stopAt) {}
  void onProgress(double fraction, std::string_view stage, const World& world) override {
    RunOutput::onProgress(fraction, stage, world);
    progress_ = fraction;
  }
  bool stopRequested() override { return progress_ >= stopAt_; }

 private:
  double stopAt_;
  double progress_ = 0;
};

}  // namespace grainlab::testing
