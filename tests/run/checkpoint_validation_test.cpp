// Loading a checkpoint checks what the engine will index with (array lengths, neighbour pairs,
// the polygon contact cache, flags) and refuses what cannot have come from the scene's world
// (tests/server/fuzz/fuzz_checkpoint found an out-of-range pair read). Here: real checkpoints
// of each kind of world still load and run on, so those checks refuse nothing they should
// accept; and a checkpoint with one pair's index out of range is refused by name.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "grainlab/checkpoint.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

// Cancels the run at its `after`-th progress report (every 200 steps).
class CancelAt : public RunObserver {
 public:
  explicit CancelAt(int after) : after_(after) {}
  bool cancelRequested() override { return ++polls_ >= after_; }

 private:
  int after_, polls_ = 0;
};

nlohmann::json smallScene(const std::string& preset, bool box2d = false) {
  nlohmann::json s = presetScene(preset);
  if (s.contains("assembly")) s["assembly"]["specimen_diameter"] = 0.024;
  if (box2d) s["solver"]["engine"] = "box2d";
  return s;
}

// Writes a checkpoint of `json` after 1,200 steps (box2d: one at every 1,000th step) to `path`.
void checkpointOf(const nlohmann::json& json, const std::string& path) {
  fs::remove(path);
  fs::remove(path + ".previous");
  CancelAt cancel(6);
  const RunSummary s = runScene(parseScene(json), cancel, {}, CheckpointPolicy{path, 0, json.dump()});
  ASSERT_EQ(s.status, RunStatus::Cancelled) << s.error;
  ASSERT_TRUE(fs::exists(path));
}

std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("grainlab-checkpoint-validation-" + name)).string();
}

TEST(CheckpointValidation, RealCheckpointsOfEveryKindOfWorldLoadAndRunOn) {
  struct Case { const char* name; nlohmann::json scene; };
  const Case cases[] = {{"discs-membrane", smallScene("circular-quick")},
                        {"polygons-membrane", smallScene("elongated-random-quick")},
                        {"discs-walls", smallScene("demo-pile")},
                        {"box2d-walls", smallScene("demo-pile", true)}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = tempPath(c.name);
    checkpointOf(c.scene, path);
    CancelAt cancel(3);  // 400 more steps from the loaded state
    const RunSummary resumed = resumeRun(path, cancel);
    EXPECT_EQ(resumed.status, RunStatus::Cancelled) << resumed.error;
    EXPECT_FALSE(resumed.refused);
    EXPECT_GT(resumed.steps, 1200);
    fs::remove(path);
    fs::remove(path + ".previous");
  }
}

TEST(CheckpointValidation, APairIndexOutOfRangeIsRefusedNotRead) {
  const std::string path = tempPath("bad-pair");
  checkpointOf(smallScene("circular-quick"), path);
  std::string payload = readCheckpointFile(path);
  // The contacts section: its name, then the list's valid_ flag, skin, reference positions
  // and pairs; the first pair's i is its first int. Set it past the particle count.
  const std::string mark = "contacts";
  const auto at = payload.find(mark);
  ASSERT_NE(at, std::string::npos);
  std::size_t p = at + mark.size();
  p += 1 + 8;  // valid_, skin_
  std::uint64_t n = 0;
  std::memcpy(&n, payload.data() + p, 8);
  p += 8 + n * 16;  // reference_: n Vec2
  std::uint64_t pairs = 0;
  std::memcpy(&pairs, payload.data() + p, 8);
  ASSERT_GT(pairs, 0u);
  p += 8;
  const int huge = 1 << 30;
  std::memcpy(payload.data() + p, &huge, sizeof huge);
  writeCheckpointFile(path, payload);
  fs::remove(path + ".previous");  // else resumeRun would fall back to the good one

  CancelAt cancel(1);
  const RunSummary resumed = resumeRun(path, cancel);
  EXPECT_EQ(resumed.status, RunStatus::Failed);
  EXPECT_TRUE(resumed.refused);
  EXPECT_NE(resumed.error.find("neighbour pair 0"), std::string::npos) << resumed.error;
  fs::remove(path);
}

}  // namespace
}  // namespace grainlab
