// The recorder keeps the shearing stage from its ε22 = 0 state on, and the histograms of the
// samples nearest to the rose diagrams' strains, while the run's own files are still written.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "grainlab/studies/paper/assembly_recorder.hpp"
#include "grainlab/world.hpp"

namespace grainlab::report {
namespace {

size_t col(const char* name) { return seriesColumnIndex(name); }

Sample sample(std::int64_t step, int stage, double strain) {
  Sample s;
  s.step = step;
  s.stage = stage == 2 ? "shearing" : "consolidation";
  s.values.assign(seriesColumns().size(), 0.0);
  s.values[col("step")] = static_cast<double>(step);
  s.values[col("stage")] = stage;
  s.values[col("axial_strain")] = strain;
  s.values[col("a_c")] = 0.1 * step;  // tells the samples apart
  return s;
}

analysis::PolarHistograms histogramsTagged(std::int64_t ends) {
  analysis::PolarHistograms h;
  h.ends = ends;
  return h;
}

class Recorder : public ::testing::Test {
 protected:
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("grainlab-recorder-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                               "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(Recorder, ShearingStartsFromTheConsolidatedStateAtZeroStrain) {
  Scene scene;
  scene.stages.resize(3);
  scene.stages[0].type = StageSpec::Type::Compaction;
  scene.stages[1].type = StageSpec::Type::Isotropic;
  scene.stages[2].type = StageSpec::Type::Biaxial;
  World world{Material{}};
  AssemblyResult initial;
  for (double s : roseStrains()) initial.roses.push_back({s, NAN, std::nullopt});
  AssemblyRecorder recorder(std::move(initial), dir.string());
  const AssemblyResult& result = recorder.result();
  recorder.onStart(scene, world);

  const auto h0 = histogramsTagged(100), h1 = histogramsTagged(101), h5 = histogramsTagged(105),
             h19 = histogramsTagged(119), h20 = histogramsTagged(120);
  auto feed = [&](Sample s, const analysis::PolarHistograms& h) {
    s.histograms = &h;
    recorder.onSample(s, world);
  };
  feed(sample(1, 0, 0.3), h0);     // compaction: not part of the shearing
  feed(sample(2, 1, 0.004), h1);   // consolidation's last sample = shearing's start
  feed(sample(3, 2, 0.048), h5);
  feed(sample(4, 2, 0.19), h19);
  feed(sample(5, 2, 0.2001), h20);
  recorder.onFinish(RunSummary{}, world);

  ASSERT_EQ(result.shearing.size(), 4u);
  EXPECT_DOUBLE_EQ(result.shearing.at("axial_strain", 0), 0.0);  // measured from this very state
  EXPECT_DOUBLE_EQ(result.shearing.at("a_c", 0), 0.2);
  EXPECT_DOUBLE_EQ(result.shearing.at("stage", 0), 2.0);
  EXPECT_DOUBLE_EQ(result.shearing.at("a_c", 3), 0.5);
  ASSERT_EQ(result.roses.size(), 3u);
  EXPECT_EQ(result.roses[0].histograms->ends, 101);
  EXPECT_EQ(result.roses[1].histograms->ends, 105);
  EXPECT_EQ(result.roses[2].histograms->ends, 120);
  EXPECT_DOUBLE_EQ(result.roses[2].axialStrain, 0.2001);
  // The run's own output goes on as `grainlab run` writes it.
  std::ifstream series(dir / "series.csv");
  std::string line;
  int lines = 0;
  while (std::getline(series, line)) ++lines;
  EXPECT_EQ(lines, 6);  // header and all five samples
  EXPECT_TRUE(std::filesystem::exists(dir / "summary.json"));
}

TEST_F(Recorder, AStartSampleOfItsOwnReplacesTheConsolidationsLast) {
  Scene scene;
  scene.stages.resize(2);
  scene.stages[0].type = StageSpec::Type::Isotropic;
  scene.stages[1].type = StageSpec::Type::Biaxial;
  World world{Material{}};
  AssemblyRecorder recorder(AssemblyResult{}, dir.string());
  const AssemblyResult& result = recorder.result();
  recorder.onStart(scene, world);
  Sample last = sample(7, 0, 0.01), start = sample(7, 1, 0.0), next = sample(9, 1, 0.01);
  recorder.onSample(last, world);
  recorder.onSample(start, world);
  recorder.onSample(next, world);
  ASSERT_EQ(result.shearing.size(), 2u);
  EXPECT_DOUBLE_EQ(result.shearing.at("step", 0), 7.0);
  EXPECT_DOUBLE_EQ(result.shearing.at("step", 1), 9.0);
}

}  // namespace
}  // namespace grainlab::report
