#include "prepared_specimen.hpp"

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <vector>

#include "grainlab/checkpoint.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/membrane.hpp"
#include "grainlab/prepared_specimen.hpp"
#include "grainlab/world.hpp"
#include "run_context.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

// What the specimen was made with, saved ahead of its state: a scene that does not fit it is
// refused by field before any of the state is loaded into its world.
struct SpecimenIdentity {
  std::uint32_t engine = 0;
  std::uint64_t seed = 0;
  std::uint64_t particles = 0;
  std::vector<std::uint8_t> shapes;
  double massFingerprint = 0;
  Material material;
  std::uint64_t stageIndex = 0;
  std::string stageName;
  std::uint32_t stageType = 0;

  static SpecimenIdentity of(const Scene& scene, const World& world, std::size_t stageIndex) {
    SpecimenIdentity id;
    id.engine = static_cast<std::uint32_t>(scene.solver.engine);
    id.seed = scene.seed;
    id.particles = static_cast<std::uint64_t>(world.size());
    for (ShapeKind k : world.shapes()) id.shapes.push_back(static_cast<std::uint8_t>(k));
    for (double m : world.masses()) id.massFingerprint = id.massFingerprint * 1.000001 + m;
    id.material = world.material();
    id.stageIndex = stageIndex;
    id.stageName = scene.stages[stageIndex].name;
    id.stageType = static_cast<std::uint32_t>(scene.stages[stageIndex].type);
    return id;
  }
  void persist(StateArchive& a) {
    a.section("specimen");
    a(engine);
    a(seed);
    a(particles);
    a(shapes);
    a(massFingerprint);
    a(material);
    a(stageIndex);
    a(stageName);
    a(stageType);
  }
};

std::string engineName(std::uint32_t engine) {
  return engine == static_cast<std::uint32_t>(SolverSpec::Engine::Box2d) ? "box2d" : "dem";
}

// The reasons a scene does not fit the specimen, in the order a user would fix them.
void checkFits(const SpecimenIdentity& saved, const SpecimenIdentity& scene, const Scene& s, const std::string& field) {
  auto refuse = [&](const std::string& why) { throw SceneError(field, why); };
  if (saved.engine != scene.engine) {
    refuse("the specimen was prepared with solver.engine \"" + engineName(saved.engine) + "\", this scene's is \"" +
           engineName(scene.engine) + "\" (a specimen's contacts belong to its engine)");
  }
  if (saved.seed != scene.seed) {
    refuse("the specimen was generated with seed " + std::to_string(saved.seed) + ", this scene's seed is " +
           std::to_string(scene.seed));
  }
  // Shapes before the count: "a disc, not a polygon" says more than two counts do.
  const std::size_t common = std::min(saved.shapes.size(), scene.shapes.size());
  for (std::size_t k = 0; k < common; ++k) {
    if (saved.shapes[k] == scene.shapes[k]) continue;
    refuse("the specimen's particle " + std::to_string(k) + " is a " + (saved.shapes[k] ? "polygon" : "disc") +
           ", this scene's is a " + (scene.shapes[k] ? "polygon" : "disc") + " (another assembly)");
  }
  if (saved.particles != scene.particles) {
    refuse("the specimen has " + std::to_string(saved.particles) + " particles, this scene's assembly makes " +
           std::to_string(scene.particles));
  }
  if (saved.massFingerprint != scene.massFingerprint) {
    refuse("the specimen's particles differ in size from those this scene's assembly makes (another grading)");
  }
  const Material &a = saved.material, &b = scene.material;
  if (a.density != b.density || a.normalStiffness != b.normalStiffness || a.tangentialStiffness != b.tangentialStiffness ||
      a.restitution != b.restitution || a.localDamping != b.localDamping) {
    refuse("the specimen was prepared with another material (density, stiffnesses, restitution or damping) than this "
           "scene's");
  }
  const std::string stageField = field == "start_from.checkpoint" ? field : "start_from.stage";
  const std::size_t k = static_cast<std::size_t>(saved.stageIndex);
  if (k >= s.stages.size() || s.stages[k].name != saved.stageName ||
      static_cast<std::uint32_t>(s.stages[k].type) != saved.stageType) {
    throw SceneError(stageField, "the specimen ended stage " + std::to_string(k) + " '" + saved.stageName +
                                     "'; this scene's stages must begin with the same stages (the specimen stands in "
                                     "for them) and go on with those to run");
  }
  if (k + 1 >= s.stages.size()) {
    throw SceneError(stageField, "this scene has no stage after '" + saved.stageName + "' to run on the specimen");
  }
}

// A run_id the server resolved to a checkpoint is still reported as the run_id the user gave.
std::string fieldOf(const StartFrom& from) {
  if (from.runId != 0) return "start_from.run_id";
  return from.checkpoint.empty() ? "start_from.run" : "start_from.checkpoint";
}

}  // namespace

std::string stageCheckpointPath(const std::string& runDirectory, const std::string& stage) {
  std::string name = stage;
  for (char& c : name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                       c == '_' || c == '.';
    if (!plain) c = '_';
  }
  if (name.empty() || name.find_first_not_of('.') == std::string::npos) name = "_" + name;  // never "." or ".."
  return (fs::path(runDirectory) / kStageCheckpointFolder / (name + ".checkpoint")).string();
}

bool keepsStageCheckpoints(const Scene& scene) {
  return scene.output.stageCheckpoints.value_or(scene.solver.engine == SolverSpec::Engine::Dem);
}

std::string startFromPath(const Scene& scene) {
  const StartFrom& from = *scene.startFrom;
  if (!from.checkpoint.empty()) {
    if (!fs::is_regular_file(from.checkpoint)) throw SceneError(fieldOf(from), from.checkpoint + ": no such file");
    return from.checkpoint;
  }
  if (from.runId != 0) {
    throw SceneError("start_from.run_id", "names a run stored by grainlab serve, which only that server can start "
                                          "from; here give start_from.run (a run's directory) or "
                                          "start_from.checkpoint");
  }
  if (!fs::is_directory(from.run)) throw SceneError("start_from.run", from.run + ": no such run directory");
  std::string stage = from.stage;
  if (stage.empty()) {
    // The preparation's end: the stage before the first shearing stage.
    for (std::size_t k = 1; k < scene.stages.size() && stage.empty(); ++k)
      if (isShearing(scene.stages[k].type)) stage = scene.stages[k - 1].name;
    if (stage.empty()) throw SceneError("start_from.stage", "this scene has no shearing stage to begin before: name the stage");
  }
  const std::string path = stageCheckpointPath(from.run, stage);
  if (!fs::is_regular_file(path)) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(fs::path(from.run) / kStageCheckpointFolder, ec))
      if (e.path().extension() == ".checkpoint") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    std::string kept;
    for (const std::string& n : names) kept += (kept.empty() ? "" : ", ") + n;
    throw SceneError("start_from.run", from.run + " kept no checkpoint of stage '" + stage + "' (" +
                                           (kept.empty() ? "it kept none: output.stage_checkpoints was off, or it "
                                                           "stopped before a stage ended"
                                                         : "it kept: " + kept) +
                                           ")");
  }
  return path;
}

void RunContext::persistSpecimen(StateArchive& a) {
  a.section("run context");
  std::uint64_t stage = stageIndex_;
  a(stage);
  a.require(stage < scene_.stages.size(), "stage " + std::to_string(stage) + " is past the scene's stages");
  stageIndex_ = static_cast<size_t>(stage);
  a(lastSampleStep_);
  a(lastSampleRate_);
  a(voidRatioAfterConsolidation_);
  world_->persist(a);
  bool ring = membrane_ != nullptr;
  a.same(ring, "whether there is a boundary ring");
  if (membrane_) membrane_->persist(a);
  sampler_->persist(a);
}

void RunContext::sampleSpecimen(RunObserver& observer) {
  world_->checkHealth();
  const Sample s = sampler_->measure(static_cast<int>(stageIndex_), scene_.stages[stageIndex_], lastSampleRate_);
  observer.onSample(s, *world_);
}

std::uint64_t writeStageCheckpoint(const std::string& path, const Scene& scene, RunContext& context,
                                   std::size_t stageIndex, const PreparedHistory& history) {
  World& world = context.world();
  world.makeResumable();
  StateArchive a;
  a.section("grainlab specimen");
  SpecimenIdentity id = SpecimenIdentity::of(scene, world, stageIndex);
  id.persist(a);
  PreparedHistory h = history;
  a(h.notes);
  a(h.timestepNoted);
  context.persistSpecimen(a);
  a.section("end");
  fs::create_directories(fs::path(path).parent_path());
  writeCheckpointFile(path, a.bytes());
  return a.bytes().size();
}

std::size_t loadPreparedSpecimen(const Scene& scene, RunContext& context, PreparedHistory& history) {
  const std::string field = fieldOf(*scene.startFrom);
  const std::string path = startFromPath(scene);
  try {
    const std::string payload = readCheckpointFile(path);
    StateArchive a(payload);
    try {
      a.section("grainlab specimen");
    } catch (const CheckpointError&) {
      throw CheckpointError(path + ": not a stage checkpoint (a run's resume checkpoint is continued with grainlab "
                                   "resume; a run keeps its stages' ends in DIR/" +
                            std::string(kStageCheckpointFolder) + ")");
    }
    SpecimenIdentity saved;
    saved.persist(a);
    checkFits(saved, SpecimenIdentity::of(scene, context.world(), 0), scene, field);
    a(history.notes);
    a(history.timestepNoted);
    context.persistSpecimen(a);
    a.section("end");
    a.expectEnd();
    // The scene's own timestep setting, not the preparation's (World::persist loads that).
    context.world().setTimestep(scene.solver.timestep);
    return static_cast<std::size_t>(saved.stageIndex) + 1;
  } catch (const CheckpointError& e) {
    throw SceneError(field, e.what());
  }
}

}  // namespace grainlab
