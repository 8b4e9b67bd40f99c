// Prepare once, test many times: a run started from run A's end-of-consolidation checkpoint,
// running A's own shearing stage, writes A's rows from there on byte for byte (DEM discs and
// polygons, Box2D discs, discs in a periodic cell), and keeping the checkpoints changes nothing in a DEM run. A specimen
// that is missing, unreadable, of another format version, or that does not fit the scene is
// refused naming start_from's field, before anything is written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grainlab/checkpoint.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/prepared_specimen.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/run_output.hpp"

#include "../support/file_bytes.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

using grainlab::testing::fileBytes;

// The run's series.csv from its last row of stage `stage` on (with the header).
std::string seriesFrom(const fs::path& dir, const std::string& stage) {
  std::istringstream in(fileBytes(dir / "series.csv"));
  std::string header, line;
  std::getline(in, header);
  std::vector<std::string> rows;
  for (; std::getline(in, line);) rows.push_back(line);
  size_t last = rows.size();
  for (size_t k = 0; k < rows.size(); ++k)
    if (rows[k].find("," + stage + ",") != std::string::npos) last = k;
  std::string out = header + "\n";
  for (size_t k = last; k < rows.size(); ++k) out += rows[k] + "\n";
  return out;
}

RunSummary runInto(const nlohmann::json& json, const fs::path& dir, bool keepStages) {
  const Scene scene = parseScene(json);
  RunOutput output(dir.string(), scene, nullptr);
  return runScene(scene, output, {}, {}, keepStages ? dir.string() : std::string());
}

struct Variant {
  const char* name;
  nlohmann::json scene;
  friend void PrintTo(const Variant& v, std::ostream* os) { *os << v.name; }
};

Variant variant(const char* name, const char* preset, const char* engine, double axialStrain) {
  nlohmann::json scene = presetScene(preset);
  scene["solver"]["engine"] = engine;
  scene["output"]["stage_checkpoints"] = true;  // box2d keeps none unless asked
  scene["stages"].back()["target_axial_strain"] = axialStrain;  // shorter, same physics
  return {name, scene};
}

class Branch : public ::testing::TestWithParam<Variant> {
 protected:
  fs::path root_ = fs::temp_directory_path() / ("grainlab_branch_" + std::to_string(::getpid()) + "_" +
                                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { fs::create_directories(root_); }
  void TearDown() override { fs::remove_all(root_); }
};

TEST_P(Branch, ShearingFromTheConsolidatedSpecimenRepeatsTheRunByteForByte) {
  const nlohmann::json scene = GetParam().scene;
  const fs::path a = root_ / "a", b = root_ / "b";
  const RunSummary prepared = runInto(scene, a, true);
  ASSERT_EQ(prepared.status, RunStatus::Completed) << prepared.error;
  EXPECT_EQ(prepared.stageCheckpoints, 3) << "one per stage";
  EXPECT_GT(prepared.stageCheckpointBytes, 0u);
  ASSERT_TRUE(fs::exists(stageCheckpointPath(a.string(), "consolidation")));

  nlohmann::json branch = scene;
  branch["start_from"] = {{"run", a.string()}, {"stage", "consolidation"}};
  // With the same options as A: a box2d run that keeps its stages' ends rebuilds its world there.
  const RunSummary tested = runInto(branch, b, true);
  ASSERT_EQ(tested.status, RunStatus::Completed) << tested.error;
  EXPECT_EQ(tested.steps, prepared.steps) << "the clock comes from the specimen";

  const std::string expected = seriesFrom(a, "consolidation"), got = fileBytes(b / "series.csv");
  EXPECT_GE(std::count(expected.begin(), expected.end(), '\n'), 4);  // header, the specimen's row, shearing rows
  EXPECT_TRUE(expected == got) << "the branch's series.csv is not A's from the end of consolidation:\n"
                               << expected.substr(0, 600) << "\n---\n" << got.substr(0, 600);
  for (const char* file : {"particles_final.csv", "contacts_final.csv"}) {
    EXPECT_TRUE(fileBytes(a / file) == fileBytes(b / file)) << file;
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, Branch,
                         ::testing::Values(variant("DemDiscs", "circular-quick", "dem", 0.05),
                                           variant("DemPolygons", "elongated-bedding-30-quick", "dem", 0.01),
                                           variant("Box2dDiscs", "circular-quick", "box2d", 0.03),
                                           variant("PeriodicCellDiscs", "periodic-biaxial-circular-quick", "dem", 0.03)),
                         [](const auto& info) { return std::string(info.param.name); });

// A DEM run that keeps its stages' ends runs as one that does not: saving reads the state only.
TEST(StageCheckpoints, ChangeNothingInADemRun) {
  const fs::path root = fs::temp_directory_path() / ("grainlab_stagekeep_" + std::to_string(::getpid()));
  nlohmann::json scene = presetScene("elongated-bedding-30-quick");
  scene["stages"].back()["target_axial_strain"] = 0.01;
  ASSERT_EQ(runInto(scene, root / "kept", true).status, RunStatus::Completed);
  ASSERT_EQ(runInto(scene, root / "plain", false).status, RunStatus::Completed);
  EXPECT_TRUE(fs::exists(stageCheckpointPath((root / "kept").string(), "compaction")));
  EXPECT_FALSE(fs::exists(root / "plain" / kStageCheckpointFolder));
  EXPECT_TRUE(fileBytes(root / "kept" / "series.csv") == fileBytes(root / "plain" / "series.csv"));
  fs::remove_all(root);
}

// One prepared specimen (circular-quick, a short shearing) and scenes that misuse it.
class BadStart : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fs::create_directories(root());
    nlohmann::json scene = presetScene("circular-quick");
    scene["stages"].back()["target_axial_strain"] = 0.002;
    scene_ = new nlohmann::json(scene);
    ASSERT_EQ(runInto(scene, root() / "a", true).status, RunStatus::Completed);
  }
  static void TearDownTestSuite() {
    fs::remove_all(root());
    delete scene_;
  }
  static fs::path root() { return fs::temp_directory_path() / ("grainlab_badstart_" + std::to_string(::getpid())); }
  static std::string consolidation() { return stageCheckpointPath((root() / "a").string(), "consolidation"); }

  // The run is refused, naming `field`, with `reason` in the message, and writes nothing.
  void expectRefused(nlohmann::json scene, const std::string& field, const std::string& reason) {
    const fs::path out = root() / "refused";
    const Scene parsed = parseScene(scene);
    RunOutput output(out.string(), parsed, nullptr);
    const RunSummary s = runScene(parsed, output);
    EXPECT_EQ(s.status, RunStatus::Failed);
    EXPECT_TRUE(s.refused);
    EXPECT_EQ(s.error.rfind(field + ": ", 0), 0u) << s.error;
    EXPECT_NE(s.error.find(reason), std::string::npos) << s.error;
    EXPECT_EQ(s.error.find('\n'), std::string::npos) << "one line: " << s.error;
    EXPECT_FALSE(fs::exists(out)) << "nothing is written";
    fs::remove_all(out);  // a failure here is not the next test's
  }
  nlohmann::json from(const nlohmann::json& start) const {
    nlohmann::json s = *scene_;
    s["start_from"] = start;
    return s;
  }
  // A copy of the consolidation checkpoint with `edit` applied to its bytes.
  std::string edited(void (*edit)(std::string&)) const {
    std::string bytes = fileBytes(consolidation());
    edit(bytes);
    const std::string path = (root() / "edited.checkpoint").string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  static nlohmann::json* scene_;
};
nlohmann::json* BadStart::scene_ = nullptr;

TEST_F(BadStart, MissingRunDirectory) {
  expectRefused(from({{"run", (root() / "nowhere").string()}, {"stage", "consolidation"}}), "start_from.run",
                "no such run directory");
}

TEST_F(BadStart, StageTheRunDidNotKeep) {
  expectRefused(from({{"run", (root() / "a").string()}, {"stage", "settling"}}), "start_from.run",
                "kept no checkpoint of stage 'settling' (it kept: compaction, consolidation, shearing)");
}

TEST_F(BadStart, MissingCheckpointFile) {
  expectRefused(from({{"checkpoint", (root() / "none.checkpoint").string()}}), "start_from.checkpoint", "no such file");
}

TEST_F(BadStart, CorruptCheckpoint) {
  const std::string path = edited([](std::string& b) { b[b.size() / 2] ^= 0x20; });
  expectRefused(from({{"checkpoint", path}}), "start_from.checkpoint", "corrupt (checksum mismatch)");
}

TEST_F(BadStart, TruncatedCheckpoint) {
  const std::string path = edited([](std::string& b) { b.resize(b.size() - 100); });
  expectRefused(from({{"checkpoint", path}}), "start_from.checkpoint", "truncated");
}

TEST_F(BadStart, OtherFormatVersion) {
  const std::string path = edited([](std::string& b) {
    const std::uint32_t version = kCheckpointFormatVersion + 1;
    std::memcpy(b.data() + std::string_view("GRAINLAB-CHECKPOINT\n").size(), &version, sizeof version);
  });
  expectRefused(from({{"checkpoint", path}}), "start_from.checkpoint",
                "format version " + std::to_string(kCheckpointFormatVersion + 1));
}

TEST_F(BadStart, OtherParticleCount) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "consolidation"}});
  s["assembly"]["specimen_diameter"] = 0.05;
  expectRefused(s, "start_from.run", "particles, this scene's assembly makes");
}

TEST_F(BadStart, OtherSeed) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "consolidation"}});
  s["seed"] = 7;
  expectRefused(s, "start_from.run", "generated with seed 1, this scene's seed is 7");
}

TEST_F(BadStart, OtherGrading) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "consolidation"}});
  s["assembly"]["disc_radius"] = 0.002001;  // as many particles, each a little larger
  expectRefused(s, "start_from.run", "differ in size");
}

TEST_F(BadStart, OtherShapes) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "consolidation"}});
  s["assembly"] = presetScene("elongated-bedding-30-quick")["assembly"];
  expectRefused(s, "start_from.run", "is a disc, this scene's is a polygon");
}

TEST_F(BadStart, OtherEngine) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "consolidation"}});
  s["solver"]["engine"] = "box2d";
  expectRefused(s, "start_from.run", "prepared with solver.engine \"dem\", this scene's is \"box2d\"");
}

TEST_F(BadStart, StagesThatDoNotBeginWithThePreparedOnes) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "consolidation"}});
  s["stages"].erase(0);  // compaction dropped: consolidation is no longer stage 1
  expectRefused(s, "start_from.stage", "must begin with the same stages");
}

TEST_F(BadStart, NothingLeftToRun) {
  nlohmann::json s = from({{"run", (root() / "a").string()}, {"stage", "shearing"}});
  expectRefused(s, "start_from.stage", "no stage after 'shearing'");
}

TEST_F(BadStart, AResumeCheckpointIsNotASpecimen) {
  // A run stopped at once leaves a resume checkpoint, not a stage's end.
  const fs::path dir = root() / "stopped";
  const Scene scene = parseScene(*scene_);
  struct Stop : RunOutput {
    using RunOutput::RunOutput;
    bool stopRequested() override { return true; }
  } output(dir.string(), scene, nullptr);
  const std::string path = (dir / "checkpoint.bin").string();
  ASSERT_EQ(runScene(scene, output, {}, CheckpointPolicy{path, 1e9, scene_->dump()}).status, RunStatus::Interrupted);
  expectRefused(from({{"checkpoint", path}}), "start_from.checkpoint", "not a stage checkpoint");
}

TEST_F(BadStart, MalformedStartFromIsASceneError) {
  EXPECT_THROW(parseScene(from({{"stage", "consolidation"}})), SceneError);
  EXPECT_THROW(parseScene(from({{"run", "a"}, {"checkpoint", "b"}})), SceneError);
  EXPECT_THROW(parseScene(from({{"checkpoint", "b"}, {"stage", "consolidation"}})), SceneError);
  EXPECT_THROW(parseScene(from({{"run", "a"}, {"typo", 1}})), SceneError);
}

}  // namespace
}  // namespace grainlab
