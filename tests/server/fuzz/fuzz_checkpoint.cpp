// libFuzzer: checkpoint files (grainlab/checkpoint.hpp). Every input is used twice:
//  (a) as the raw bytes of a checkpoint file: checkpointPayload must return its payload or
//      refuse it with a CheckpointError (magic, version, size, checksum);
//  (b) as the state of a run, past the checksum: the input's first byte picks one of a few
//      small fixed scenes, the rest follows that scene's JSON in the payload, and the whole
//      is written as a valid file (checkpointChecksum) and resumed with resumeRun. A state
//      that cannot be loaded must be refused (the summary says failed, with the reason,
//      before anything runs); one that loads runs 200 steps and is cancelled. Nothing may
//      crash, read out of bounds or allocate without bound (libFuzzer's -malloc_limit_mb).
//
// Seeds: GRAINLAB_FUZZ_MAKE_SEEDS=DIR ./fuzz_checkpoint writes real checkpoints of the fixed
// scenes into DIR (after 1,200 and 8,000 steps of each run, in this format) and exits;
// tests/server/fuzz/corpus/checkpoint holds them.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/checkpoint.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/state_archive.hpp"

namespace {

namespace fs = std::filesystem;

// Small scenes with each kind of state a checkpoint holds: a membrane with discs, one with
// polygons, walls and gravity, and Box2D's solver.
std::vector<std::string> makeScenes() {
  std::vector<std::string> out;
  for (const char* name : {"circular-quick", "elongated-random-quick"}) {
    nlohmann::json s = grainlab::presetScene(name);
    s["assembly"]["specimen_diameter"] = 0.024;
    out.push_back(s.dump());
  }
  nlohmann::json pile = grainlab::presetScene("demo-pile");
  out.push_back(pile.dump());
  pile["solver"]["engine"] = "box2d";
  out.push_back(pile.dump());
  return out;
}

const std::vector<std::string>& sceneJsons() {
  static const std::vector<std::string> scenes = makeScenes();
  return scenes;
}

// The payload's start that the scene fixes: what RunLoop::checkpoint writes before the loop.
std::string payloadPrefix(const std::string& sceneJson) {
  grainlab::StateArchive a;
  a.section("grainlab run");
  std::string json = sceneJson;
  a(json);
  return a.bytes();
}

// Stops the run at its `after`-th progress report (every 200 steps).
class Cancel : public grainlab::RunObserver {
 public:
  explicit Cancel(int after) : after_(after) {}
  bool cancelRequested() override { return ++polls_ >= after_; }

 private:
  int after_;
  int polls_ = 0;
};

std::string fileBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// A checkpoint file as writeCheckpointFile lays it out, without its fsyncs.
std::string wrap(const std::string& payload) {
  std::string file = "GRAINLAB-CHECKPOINT\n";
  const std::uint32_t version = grainlab::kCheckpointFormatVersion;
  const std::uint64_t size = payload.size(), checksum = grainlab::checkpointChecksum(payload);
  file.append(reinterpret_cast<const char*>(&version), sizeof version);
  file.append(reinterpret_cast<const char*>(&size), sizeof size);
  file.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
  return file + payload;
}

void makeSeeds(const fs::path& dir) {
  fs::create_directories(dir);
  const auto& scenes = sceneJsons();
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const grainlab::Scene scene = grainlab::parseScene(nlohmann::json::parse(scenes[k]));
    for (int after : {6, 40}) {  // (box2d: a checkpoint every 1,000 steps, 5 reports)
      const fs::path file = dir / "make-seed.ckpt";
      grainlab::CheckpointPolicy policy{file.string(), 0, scenes[k]};
      Cancel cancel(after);
      const auto summary = grainlab::runScene(scene, cancel, {}, policy);
      const std::string payload = grainlab::readCheckpointFile(file.string());
      const std::string prefix = payloadPrefix(scenes[k]);
      if (payload.compare(0, prefix.size(), prefix) != 0) {
        std::cerr << "scene " << k << ": the checkpoint does not start with the scene's prefix\n";
        std::exit(1);
      }
      const std::string seed = std::string(1, static_cast<char>(k)) + payload.substr(prefix.size());
      const fs::path out = dir / ("scene" + std::to_string(k) + "-progress" + std::to_string(after) + ".bin");
      std::ofstream(out, std::ios::binary) << seed;
      std::cerr << out.string() << ": " << seed.size() << " bytes, step " << summary.steps << " (" << summary.status << ")\n";
      fs::remove(file);
      fs::remove(file.string() + ".previous");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("GRAINLAB_FUZZ_MAKE_SEEDS")) {
    makeSeeds(dir);
    std::exit(0);
  }
  sceneJsons();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // (a) The file's header and checksum.
  try {
    (void)grainlab::checkpointPayload(bytes, "fuzz");
  } catch (const grainlab::CheckpointError& e) {
    if (std::string(e.what()).size() <= std::string("fuzz: ").size()) std::abort();
  } catch (const std::exception& e) {
    std::cerr << "checkpointPayload threw something other than CheckpointError: " << e.what() << "\n";
    std::abort();
  }

  // (b) The state, past the checksum.
  if (size == 0) return 0;
  const auto& scenes = sceneJsons();
  const std::string& scene = scenes[data[0] % scenes.size()];
  const std::string file = wrap(payloadPrefix(scene) + std::string(bytes.substr(1)));
  static const std::string path = "/dev/shm/grainlab-fuzz-checkpoint-" + std::to_string(::getpid());
  std::ofstream(path, std::ios::binary | std::ios::trunc) << file;
  Cancel cancel(1);
  grainlab::RunSummary summary;
  try {
    summary = grainlab::resumeRun(path, cancel);
  } catch (const std::exception& e) {
    std::cerr << "resumeRun threw instead of failing the run: " << e.what() << "\n";
    std::abort();
  }
  using grainlab::RunStatus;
  const bool known = summary.status == RunStatus::Failed || summary.status == RunStatus::Cancelled ||
                     summary.status == RunStatus::Completed;
  if (!known || (summary.status == RunStatus::Failed && summary.error.empty())) {
    std::cerr << "resumeRun ended '" << summary.status << "' with error '" << summary.error << "'\n";
    std::abort();
  }
  return 0;
}
