// Exact restart: a run stopped (cleanly, at a checkpoint) and resumed, once or twice, writes
// the same bytes as the same run done without stopping — series.csv, the final particles and
// contacts, summary.json apart from its wall-clock figures, and ParaView frames — for discs
// and polygons, in the DEM (one and two threads) and Box2D modes. And a checkpoint that
// cannot be trusted is refused, with the previous good one used instead. Each resume continues
// from the step where the run stopped (identical bytes alone would not show a fresh start).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "grainlab/checkpoint.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/run_output.hpp"

#include "../support/file_bytes.hpp"
#include "../support/stopping_output.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using grainlab::testing::fileBytes;
using grainlab::testing::StoppingOutput;

// The files of a run, and the cost it announced before its first step.
class EstimatingOutput : public RunOutput {
 public:
  using RunOutput::RunOutput;
  void onEstimate(const RunCost& cost) override {
    RunOutput::onEstimate(cost);
    estimate = cost;
  }
  RunCost estimate;
};

// summary.json without what the wall clock decides.
nlohmann::json deterministicSummary(const fs::path& dir) {
  nlohmann::json s = nlohmann::json::parse(fileBytes(dir / "summary.json"));
  for (const char* key : {"wall_seconds", "sample_seconds", "particle_steps_per_second", "checkpoints"}) s.erase(key);
  for (const char* key : {"forces", "integrate", "neighbors"}) s["profile_seconds"].erase(key);
  return s;
}

// A scene and the name its test goes by (printed instead of the whole scene).
struct Variant {
  const char* name;
  nlohmann::json scene;
  friend void PrintTo(const Variant& v, std::ostream* os) { *os << v.name; }
};

class Resume : public ::testing::TestWithParam<Variant> {
 protected:
  fs::path root_ = fs::temp_directory_path() / ("grainlab_resume_" + std::to_string(::getpid()) + "_" +
                                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { fs::create_directories(root_); }
  void TearDown() override { fs::remove_all(root_); }
};

std::string variantName(const ::testing::TestParamInfo<Resume::ParamType>& info) {
  return info.param.name;
}

Variant variant(const char* name, const char* preset, const char* engine, int threads, double axialStrain,
                bool vtk = false) {
  nlohmann::json scene = presetScene(preset);
  scene["solver"]["engine"] = engine;
  scene["solver"]["threads"] = threads;
  scene["stages"].back()["target_axial_strain"] = axialStrain;  // shorter, same physics
  if (vtk) scene["output"]["vtk"] = true;
  return {name, scene};
}

// Stopped in compaction, resumed and stopped in shearing, resumed to the end.
TEST_P(Resume, StoppedTwiceEndsByteIdenticalToTheUninterruptedRun) {
  const Scene scene = parseScene(GetParam().scene);
  const fs::path whole = root_ / "whole", stopped = root_ / "stopped";
  {
    RunOutput output(whole.string(), scene, nullptr);
    ASSERT_EQ(runScene(scene, output).status, RunStatus::Completed);
  }
  const std::string checkpoint = (stopped / "checkpoint.bin").string();
  const CheckpointPolicy policy{checkpoint, 1e9, GetParam().scene.dump()};  // only at the stops
  std::vector<std::int64_t> stops, resumedFrom;  // the step of each stop, and each resume's start
  {
    StoppingOutput output(stopped, scene, 0.05);
    const RunSummary first = runScene(scene, output, {}, policy);
    ASSERT_EQ(first.status, RunStatus::Interrupted) << first.error;
    ASSERT_EQ(first.checkpoints, 1);
    ASSERT_TRUE(fs::exists(checkpoint));
    stops.push_back(first.steps);
  }
  {
    StoppingOutput output(stopped, scene, 0.7);
    const RunSummary second = resumeRun(checkpoint, output, policy);
    ASSERT_EQ(second.status, RunStatus::Interrupted) << second.error;
    ASSERT_TRUE(second.resumeNote.empty()) << second.resumeNote;
    resumedFrom.push_back(second.resumedFromStep);
    stops.push_back(second.steps);
  }
  {
    EstimatingOutput output(stopped.string(), scene, nullptr);
    const RunSummary last = resumeRun(checkpoint, output, policy);
    ASSERT_EQ(last.status, RunStatus::Completed) << last.error;
    resumedFrom.push_back(last.resumedFromStep);
    // Resumed in shearing: the estimate counts the stages still to run, not compaction and
    // consolidation again (those end on a criterion: they would add bounded time).
    EXPECT_EQ(output.estimate.firstStage, scene.stages.size() - 1);
    EXPECT_EQ(output.estimate.boundedTime, 0.0);
  }
  // Identical outputs alone cannot tell a resume from a run started afresh (the simulation is
  // deterministic): each resume must have continued from the step where the run before it stopped.
  ASSERT_GT(stops[0], 0);
  EXPECT_EQ(resumedFrom, stops) << "a resume that ignored its checkpoint starts at step 0 (or says -1)";
  for (const char* file : {"series.csv", "particles_final.csv", "contacts_final.csv", "histograms.csv",
                           "clump_members_final.csv"}) {
    if (std::string(file) == "histograms.csv" && !scene.output.histograms) continue;
    if (std::string(file) == "clump_members_final.csv" && !fs::exists(whole / file)) continue;
    const std::string a = fileBytes(whole / file), b = fileBytes(stopped / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_TRUE(a == b) << file << " differs after resuming (" << a.size() << " vs " << b.size() << " bytes)";
  }
  EXPECT_EQ(deterministicSummary(whole), deterministicSummary(stopped));
  if (fs::exists(whole / "vtk")) {  // ParaView frames (output.vtk): the same files, the same bytes
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(whole / "vtk")) {
      ++files;
      const fs::path name = entry.path().filename();
      EXPECT_TRUE(fileBytes(entry.path()) == fileBytes(stopped / "vtk" / name)) << "vtk/" << name.string();
    }
    EXPECT_EQ(files, static_cast<std::size_t>(std::distance(fs::directory_iterator(stopped / "vtk"), {})));
    EXPECT_GT(files, 10u);
  }
  EXPECT_FALSE(fs::exists(checkpoint)) << "a completed run leaves no checkpoint behind";
  EXPECT_FALSE(fs::exists(checkpoint + ".previous"));
}

// The threaded variants are shorter: a pool of two threads on two busy cores (ctest -j2) is slow,
// and what they add (per-thread force assembly resumed) shows within the first stages.
INSTANTIATE_TEST_SUITE_P(
    Modes, Resume,
    ::testing::Values(variant("DemDiscs", "circular-quick", "dem", 1, 0.2),
                      variant("DemDiscsTwoThreads", "circular-quick", "dem", 2, 0.05),
                      variant("DemPolygons", "elongated-random-quick", "dem", 1, 0.03),
                      variant("DemPolygonsTwoThreads", "elongated-random-quick", "dem", 2, 0.01),
                      variant("DemDiscsWithParaViewFrames", "circular-quick", "dem", 1, 0.1, true),
                      // The rolling springs' relative rotations are history the checkpoint keeps.
                      variant("DemDiscsRolling", "circular-rolling-quick", "dem", 1, 0.1),
                      variant("DemDiscsRollingTwoThreads", "circular-rolling-quick", "dem", 2, 0.05),
                      variant("Box2dDiscs", "circular-quick", "box2d", 1, 0.1),
                      variant("Box2dPolygons", "elongated-random-quick", "box2d", 1, 0.03),
                      variant("DemClumpsWithParaViewFrames", "clump-random-quick", "dem", 1, 0.03, true)),
    variantName);

// Two checkpoints of one run: the newest and the one before it.
class BadCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_);
    scene_ = presetScene("circular-quick");
    const Scene scene = parseScene(scene_);
    StoppingOutput first(dir_, scene, 0.2);
    ASSERT_EQ(runScene(scene, first, {}, policy()).status, RunStatus::Interrupted);
    previousPayload_ = readCheckpointFile(path());
    StoppingOutput second(dir_, scene, 0.4);
    ASSERT_EQ(resumeRun(path(), second, policy()).status, RunStatus::Interrupted);
    ASSERT_NE(readCheckpointFile(path()), previousPayload_);
    ASSERT_EQ(readCheckpointFile(path() + ".previous"), previousPayload_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path() const { return (dir_ / "checkpoint.bin").string(); }
  CheckpointPolicy policy() const { return {path(), 1e9, scene_.dump()}; }
  void overwrite(const std::string& bytes) { std::ofstream(path(), std::ios::binary) << bytes; }
  // Resuming now falls back to the previous checkpoint, says so, and keeps it.
  void expectFallback(const std::string& reason) {
    RunOutput output(dir_.string(), parseScene(scene_), nullptr);
    const RunSummary summary = resumeRun(path(), output, {});
    EXPECT_EQ(summary.status, RunStatus::Completed) << summary.error;
    EXPECT_NE(summary.resumeNote.find(reason), std::string::npos) << summary.resumeNote;
    EXPECT_NE(summary.resumeNote.find("checkpoint before it"), std::string::npos) << summary.resumeNote;
    EXPECT_EQ(readCheckpointFile(path() + ".previous"), previousPayload_) << "the good checkpoint is kept";
    EXPECT_TRUE(fs::exists(path() + ".refused")) << "the bad one is kept aside for whoever asks why";
  }

  fs::path dir_ = fs::temp_directory_path() / ("grainlab_badcheckpoint_" + std::to_string(::getpid()));
  nlohmann::json scene_;
  std::string previousPayload_;
};

TEST_F(BadCheckpoint, FlippedByteIsRefusedAsCorrupt) {
  std::string bytes = fileBytes(path());
  bytes[bytes.size() / 2] ^= 0x20;
  overwrite(bytes);
  EXPECT_THROW(readCheckpointFile(path()), CheckpointError);
  expectFallback("corrupt (checksum mismatch)");
}

TEST_F(BadCheckpoint, TruncatedFileIsRefused) {
  const std::string bytes = fileBytes(path());
  overwrite(bytes.substr(0, bytes.size() - 100));
  expectFallback("truncated");
}

TEST_F(BadCheckpoint, OtherFormatVersionIsRefused) {
  std::string bytes = fileBytes(path());
  const std::uint32_t version = kCheckpointFormatVersion + 1;
  std::memcpy(bytes.data() + std::string_view("GRAINLAB-CHECKPOINT\n").size(), &version, sizeof version);
  overwrite(bytes);
  expectFallback("format version " + std::to_string(version));
}

TEST_F(BadCheckpoint, BothUnreadableFailsTheRunNamingBothAndWritesNothing) {
  overwrite("not a checkpoint");
  std::ofstream(path() + ".previous", std::ios::binary) << "GRAINLAB-CHECKPOINT\n";
  const std::string seriesBefore = fileBytes(dir_ / "series.csv");
  RunOutput output(dir_.string(), parseScene(scene_), nullptr);
  const RunSummary summary = resumeRun(path(), output, {});
  EXPECT_EQ(summary.status, RunStatus::Failed);
  EXPECT_NE(summary.error.find("not a grainlab checkpoint"), std::string::npos) << summary.error;
  EXPECT_NE(summary.error.find("header incomplete"), std::string::npos) << summary.error;
  EXPECT_EQ(fileBytes(dir_ / "series.csv"), seriesBefore) << "a refused resume leaves the outputs as they were";
}

TEST(CheckpointFile, WriteIsAtomicAndKeepsTheOldFileAsPrevious) {
  const fs::path dir = fs::temp_directory_path() / ("grainlab_ckfile_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "c.bin").string();
  writeCheckpointFile(path, "first");
  writeCheckpointFile(path, "second");
  EXPECT_EQ(readCheckpointFile(path), "second");
  EXPECT_EQ(readCheckpointFile(path + ".previous"), "first");
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace grainlab
