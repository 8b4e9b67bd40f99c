// Checkpoints inside each loading path: a run stopped mid-stage and resumed writes the same
// series.csv and final particles, byte for byte, as one never stopped. Every member a path
// stage or the generalised membrane changes after construction has to be saved for that.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "grainlab/checkpoint.hpp"
#include "grainlab/observer_tee.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Asks for a clean stop once the named stage has given `samples` samples.
class StopInStage : public RunObserver {
 public:
  StopInStage(std::string stage, int samples) : stage_(std::move(stage)), samples_(samples) {}
  void onSample(const Sample& s, const World&) override { seen_ += s.stage == stage_; }
  bool stopRequested() override { return seen_ >= samples_; }

 private:
  std::string stage_;
  int samples_;
  int seen_ = 0;
};

void checkResume(const std::string& preset, const std::string& stage) {
  const nlohmann::json json = presetScene(preset);
  const Scene scene = parseScene(json);
  const fs::path root = fs::temp_directory_path() / ("grainlab-resume-" + preset);
  fs::remove_all(root);
  {
    OutputWriter whole((root / "whole").string(), nullptr);
    ASSERT_EQ(runScene(scene, whole).status, RunStatus::Completed);
  }
  const std::string checkpoint = (root / "parts" / "checkpoint.bin").string();
  const CheckpointPolicy policy{checkpoint, 1e9, json.dump()};  // only the stop's checkpoint
  {
    OutputWriter writer((root / "parts").string(), nullptr);
    StopInStage stop(stage, 20);
    ObserverTee tee{&writer, &stop};
    ASSERT_EQ(runScene(scene, tee, {}, policy).status, RunStatus::Interrupted);
  }
  {
    OutputWriter writer((root / "parts").string(), nullptr);
    const RunSummary resumed = resumeRun(checkpoint, writer, policy);
    ASSERT_EQ(resumed.status, RunStatus::Completed) << resumed.error;
  }
  EXPECT_EQ(slurp(root / "parts" / "series.csv"), slurp(root / "whole" / "series.csv")) << preset;
  EXPECT_EQ(slurp(root / "parts" / "particles_final.csv"), slurp(root / "whole" / "particles_final.csv")) << preset;
  fs::remove_all(root);
}

TEST(LoadingPathResume, Rotation) { checkResume("rotation-circular-quick", "rotation"); }
TEST(LoadingPathResume, Cyclic) { checkResume("cyclic-circular-quick", "cyclic"); }
TEST(LoadingPathResume, SimpleShear) { checkResume("simple-shear-circular-quick", "simple shear"); }
TEST(LoadingPathResume, ConstantVolume) { checkResume("constant-volume-circular-quick", "constant volume"); }

}  // namespace
}  // namespace grainlab
