// Batches: each run's directory holds exactly what `grainlab run` writes, a finished
// directory is never half-written, and running a batch again reruns only what did not
// complete.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "grainlab/output_writer.hpp"
#include "grainlab/run_output.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/cluster.hpp"
#include "grainlab/studies/run_batch.hpp"
#include "grainlab/world.hpp"

#include "../support/file_bytes.hpp"

namespace grainlab::studies {
namespace {

namespace fs = std::filesystem;

// Two discs meeting head on, for a few hundred steps: each run a different approach speed.
nlohmann::json collision(double speed) {
  return {{"name", "pair"},
          {"particles",
           {{{"shape", "disc"}, {"radius", 0.002}, {"position", {0, 0}}, {"velocity", {speed, 0}}},
            {{"shape", "disc"}, {"radius", 0.002}, {"position", {0.0041, 0}}, {"velocity", {-speed, 0}}}}},
          {"stages", {{{"type", "free"}, {"duration", 0.0005}}}},
          {"output", {{"sample_interval", 0.0001}}}};
}

using grainlab::testing::fileBytes;

class RunBatchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("grainlab-batch-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    for (int k = 0; k < 4; ++k) runs_.push_back({"run" + std::to_string(k), dir_ / ("run" + std::to_string(k)), collision(0.05 * (k + 1))});
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::vector<BatchRunResult> run(BatchOptions options = {}) { return runBatch(runs_, options, cluster_); }

  fs::path dir_;
  std::vector<BatchRun> runs_;
  Cluster cluster_;  // no MPI launcher here: a world of one
};

TEST_F(RunBatchTest, EachRunWritesWhatGrainlabRunWrites) {
  BatchOptions options;
  options.jobs = 2;
  const std::vector<BatchRunResult> results = run(options);
  ASSERT_EQ(results.size(), runs_.size());
  for (size_t k = 0; k < runs_.size(); ++k) {
    EXPECT_EQ(results[k].status, RunStatus::Completed) << results[k].error;
    EXPECT_FALSE(results[k].reused);
    // The same scene run directly, as `grainlab run scene.json` does.
    const fs::path direct = dir_ / ("direct" + std::to_string(k));
    OutputWriter writer(direct.string(), nullptr);
    runScene(loadSceneFile((runs_[k].dir / kSceneFile).string()), writer);
    for (const char* file : {"series.csv", "particles_final.csv", "contacts_final.csv"}) {
      const std::string batch = fileBytes(runs_[k].dir / file);
      EXPECT_FALSE(batch.empty()) << file;
      EXPECT_EQ(batch, fileBytes(direct / file)) << runs_[k].id << " " << file;
    }
    EXPECT_EQ(nlohmann::json::parse(fileBytes(runs_[k].dir / kSceneFile)), runs_[k].scene);
  }
  // No partial directory is left behind.
  for (const auto& entry : fs::directory_iterator(dir_)) EXPECT_EQ(entry.path().extension(), "") << entry.path();
}

TEST_F(RunBatchTest, ParaViewFramesWhenTheSceneAsksAsGrainlabRunWrites) {
  runs_.resize(1);
  runs_[0].scene["output"]["vtk"] = true;
  ASSERT_EQ(run()[0].status, RunStatus::Completed);
  EXPECT_TRUE(fs::exists(runs_[0].dir / "vtk" / "run.pvd"));
  EXPECT_TRUE(fs::exists(runs_[0].dir / "vtk" / "particles_0000.vtp"));
}

TEST_F(RunBatchTest, RunningAgainRerunsExactlyWhatIsMissing) {
  run();
  const auto kept = fs::last_write_time(runs_[0].dir / "series.csv");
  fs::remove_all(runs_[2].dir);
  const std::vector<BatchRunResult> again = run();
  for (size_t k = 0; k < runs_.size(); ++k) {
    EXPECT_EQ(again[k].status, RunStatus::Completed);
    EXPECT_EQ(again[k].reused, k != 2) << k;
  }
  EXPECT_EQ(fs::last_write_time(runs_[0].dir / "series.csv"), kept);  // not rewritten
  EXPECT_TRUE(fs::exists(runs_[2].dir / "series.csv"));
}

TEST_F(RunBatchTest, ARunWhoseSceneChangedIsRunAgain) {
  run();
  runs_[1].scene["stages"][0]["duration"] = 0.0006;
  const std::vector<BatchRunResult> again = run();
  EXPECT_FALSE(again[1].reused);
  EXPECT_TRUE(again[0].reused);
  EXPECT_EQ(nlohmann::json::parse(fileBytes(runs_[1].dir / kSceneFile)), runs_[1].scene);
}

TEST_F(RunBatchTest, AFailedRunIsRecordedAndRerunLater) {
  BatchOptions options;
  options.observer = [](const BatchRun& r, const fs::path& work) -> std::unique_ptr<RunObserver> {
    if (r.id == "run1") throw std::runtime_error("disk full (simulated)");
    return std::make_unique<OutputWriter>(work.string(), nullptr);
  };
  const std::vector<BatchRunResult> results = run(options);
  EXPECT_EQ(results[1].status, RunStatus::Failed);
  EXPECT_NE(results[1].error.find("disk full"), std::string::npos);
  for (size_t k : {0u, 2u, 3u}) EXPECT_EQ(results[k].status, RunStatus::Completed) << k;
  const std::optional<BatchRunResult> recorded = finishedRun(runs_[1].dir);
  ASSERT_TRUE(recorded);
  EXPECT_EQ(recorded->status, RunStatus::Failed);
  EXPECT_EQ(recorded->error, results[1].error);

  const std::vector<BatchRunResult> again = run();  // the fault is gone
  EXPECT_EQ(again[1].status, RunStatus::Completed);
  EXPECT_FALSE(again[1].reused);
  EXPECT_TRUE(again[0].reused);
}

// A stand-in for `grainlab sweep` killed half-way through a run: the run's partial directory
// holds its outputs so far and a checkpoint (here from a clean stop at 40 %).
class StopAt : public RunOutput {
 public:
  StopAt(const fs::path& dir, const Scene& scene, double at) : RunOutput(dir.string(), scene, nullptr), at_(at) {}
  void onProgress(double fraction, std::string_view stage, const World& w) override {
    RunOutput::onProgress(fraction, stage, w);
    fraction_ = fraction;
  }
  bool stopRequested() override { return fraction_ >= at_; }

 private:
  double at_, fraction_ = 0;
};

TEST_F(RunBatchTest, ARunKilledHalfWayResumesFromItsCheckpointToTheSameOutputs) {
  runs_.resize(2);
  runs_[0].scene["stages"][0]["duration"] = 0.02;  // long enough to stop (polled every 200 steps)
  const fs::path partial = dir_ / ".run0.partial";
  fs::create_directories(partial);
  std::ofstream(partial / kSceneFile) << runs_[0].scene.dump(2) << "\n";
  const Scene scene = parseScene(runs_[0].scene);
  {
    StopAt attempt(partial, scene, 0.4);
    const CheckpointPolicy policy{(partial / "checkpoint.bin").string(), 1e9, runs_[0].scene.dump()};
    ASSERT_EQ(runScene(scene, attempt, {}, policy).status, RunStatus::Interrupted);
  }
  const std::vector<BatchRunResult> results = run();
  EXPECT_TRUE(results[0].resumed);
  EXPECT_FALSE(results[1].resumed) << "a run with no partial directory starts from the beginning";
  ASSERT_EQ(results[0].status, RunStatus::Completed) << results[0].error;
  const fs::path direct = dir_ / "direct";
  OutputWriter writer(direct.string(), nullptr);
  runScene(scene, writer);
  for (const char* file : {"series.csv", "particles_final.csv", "contacts_final.csv"})
    EXPECT_EQ(fileBytes(runs_[0].dir / file), fileBytes(direct / file)) << file;
  EXPECT_FALSE(fs::exists(runs_[0].dir / "checkpoint.bin")) << "a finished run keeps no checkpoint";
  EXPECT_FALSE(fs::exists(partial));
}

// Once no run is left to start, a finished run's core goes to the run still going, which
// takes it at its next progress report and ends with the outputs it would have had alone.
// Writes what `grainlab run` writes, and notes the most threads the run's world stepped on.
class ThreadWatcher : public OutputWriter {
 public:
  ThreadWatcher(const fs::path& dir, int& most) : OutputWriter(dir.string(), nullptr), most_(most) {}
  void onProgress(double fraction, std::string_view stage, const World& w) override {
    OutputWriter::onProgress(fraction, stage, w);
    most_ = std::max(most_, w.threads());
  }

 private:
  int& most_;
};

TEST_F(RunBatchTest, TheLastRunBorrowsTheCoreAFinishedRunLeftIdle) {
  runs_.resize(2);
  runs_[1].scene["stages"][0]["duration"] = 0.2;  // 400 times run0's: it reports long after run0 ends
  BatchOptions options;
  options.jobs = 2;
  int mostThreads[2] = {0, 0};
  options.observer = [&](const BatchRun& r, const fs::path& work) -> std::unique_ptr<RunObserver> {
    return std::make_unique<ThreadWatcher>(work, mostThreads[r.id == "run1"]);
  };
  const std::vector<BatchRunResult> results = run(options);
  for (const BatchRunResult& r : results) ASSERT_EQ(r.status, RunStatus::Completed) << r.error;
  EXPECT_EQ(results[0].threadsLent, 0) << "while both ran, no core was idle";
  EXPECT_EQ(results[1].threadsLent, 1);
  EXPECT_EQ(mostThreads[0], 1);
  EXPECT_EQ(mostThreads[1], 2) << "the run's world stepped on the core it was lent";
  const fs::path direct = dir_ / "direct";
  OutputWriter writer(direct.string(), nullptr);
  runScene(parseScene(runs_[1].scene), writer);
  for (const char* file : {"series.csv", "particles_final.csv", "contacts_final.csv"})
    EXPECT_EQ(fileBytes(runs_[1].dir / file), fileBytes(direct / file)) << file;
}

// More jobs than runs: the spare cores are lent from the start, up to the machine's own.
TEST_F(RunBatchTest, ASingleRunTakesTheSpareCoresItIsGiven) {
  runs_.resize(1);
  runs_[0].scene["stages"][0]["duration"] = 0.01;
  BatchOptions options;
  options.jobs = 2;
  const std::vector<BatchRunResult> results = run(options);
  ASSERT_EQ(results[0].status, RunStatus::Completed) << results[0].error;
  const int spare = std::min(2u, std::max(1u, std::thread::hardware_concurrency())) - 1;
  EXPECT_EQ(results[0].threadsLent, spare);
}

TEST_F(RunBatchTest, APartialOrUnreadableDirectoryIsNotAFinishedRun) {
  run();
  // An interrupted attempt: its partial directory may even hold a summary; it does not count.
  fs::rename(runs_[0].dir, dir_ / ".run0.partial");
  std::ofstream(runs_[3].dir / "summary.json", std::ios::trunc) << "{\"stat";  // torn by hand
  EXPECT_FALSE(finishedRun(runs_[0].dir));
  EXPECT_FALSE(finishedRun(runs_[3].dir));
  const std::vector<BatchRunResult> again = run();
  EXPECT_FALSE(again[0].reused);
  EXPECT_FALSE(again[3].reused);
  EXPECT_TRUE(again[1].reused);
  EXPECT_FALSE(fs::exists(dir_ / ".run0.partial"));
  EXPECT_EQ(finishedRun(runs_[3].dir)->status, RunStatus::Completed);
}

}  // namespace
}  // namespace grainlab::studies
