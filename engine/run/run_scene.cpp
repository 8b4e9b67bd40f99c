#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/prepared_specimen.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"
#include "prepared_specimen.hpp"
#include "run_context.hpp"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Progress is reported, cancellation polled and checkpoints considered this often (steps).
// It divides RigidBodySolver::kRebuildEvery, so box2d runs reach a resumable step here.
constexpr int kProgressEvery = 200;
// Health (finite state, no runaway overlap) is checked this often (steps), and at every
// sample: often enough to stop a blow-up within a few steps of its start, at ~1% of the cost.
constexpr int kHealthEvery = 100;

// A timestep under the single-contact critical one can still be above the packing's own
// bound once particles carry several contacts: the run then gains energy without diverging.
// Say so once, in the summary's notes, rather than let it pass silently.
bool notePackingTimestep(const World& world, RunSummary& summary) {
  int particle = -1, contacts = 0;
  const double bound = world.packingTimestep(&particle, &contacts);
  if (world.timestep() <= bound) return false;
  std::ostringstream os;
  os << "timestep " << world.timestep() << " s is above the packing's stability bound " << bound << " s at step "
     << world.stepCount() << " (particle " << particle << " with " << contacts
     << " contacts, with viscous damping): the contacts can gain energy; lower solver.timestep_safety below "
     << std::floor(100 * bound / world.criticalTimestep()) / 100;
  summary.notes.push_back(os.str());
  return true;
}

// Where the run loop stands between two steps: with the RunContext's state, what a
// checkpoint holds.
struct LoopState {
  std::uint64_t stage = 0;     // the stage under way
  double workDone = 0;         // of the stages before it
  bool timestepNoted = false;
  double wallBefore = 0;       // s of wall time in earlier sessions of this run (before a resume)
  void persist(StateArchive& a, RunSummary& summary) {
    a.section("loop");
    a(stage);
    a(workDone);
    a(timestepNoted);
    a(wallBefore);
    a(summary.notes);
    a(summary.checkpoints);
    a(summary.checkpointSeconds);
    // The stages' ends kept so far stay on disk: a resumed run counts them as its own.
    a(summary.stageCheckpoints);
    a(summary.stageCheckpointBytes);
    a(summary.stageCheckpointSeconds);
  }
};

// One run from wherever `loop` stands: from the first stage, or (resumed) inside loop.stage,
// whose stage object the context already holds.
class RunLoop {
 public:
  RunLoop(const Scene& scene, RunContext& context, RunObserver& observer, const CheckpointPolicy& policy,
          const std::string& stageDirectory, Clock::time_point start)
      : scene_(scene), context_(context), world_(context.world()), observer_(observer), policy_(policy),
        stageDirectory_(stageDirectory), start_(start), lastCheckpoint_(Clock::now()) {}

  void run(LoopState& loop, RunSummary& summary, bool resumed) {
    const double totalWork = context_.totalWork();
    bool stopping = false;
    const size_t first = loop.stage;
    for (size_t s = first; s < scene_.stages.size(); ++s) {
      loop.stage = s;
      const bool midStage = resumed && s == first;
      Stage& stage = midStage ? context_.stage() : context_.beginStage(s);
      if (!midStage) context_.sample(observer_);  // the state the stage starts from
      while (!stage.finished()) {
        stage.beforeStep();
        world_.step();
        stage.afterStep();
        const std::int64_t step = world_.stepCount();
        if (step % kHealthEvery == 0) {
          world_.checkHealth();
          if (!loop.timestepNoted) loop.timestepNoted = notePackingTimestep(world_, summary);
        }
        if (context_.sampleDue()) context_.sample(observer_);
        if (step % kProgressEvery != 0) continue;
        observer_.onProgress((loop.workDone + stage.progress() * stage.work()) / totalWork, stage.name(), world_);
        if (observer_.cancelRequested()) {
          summary.status = RunStatus::Cancelled;
          return;
        }
        stopping = stopping || observer_.stopRequested();
        if (const int threads = scene_.solver.threads + observer_.threadsLent(); threads != world_.threads()) {
          world_.setThreads(threads);
        }
        if (!world_.resumable()) continue;
        if (stopping) {
          checkpoint(loop, summary);
          summary.status = RunStatus::Interrupted;
          return;
        }
        if (!policy_.path.empty() && since(lastCheckpoint_) >= policy_.everySeconds) checkpoint(loop, summary);
      }
      context_.sample(observer_);  // the state the stage ends in
      if (const std::string note = stage.endNote(); !note.empty()) summary.notes.push_back(note);
      loop.workDone += stage.work();
      context_.endStage();
      keepStage(s, loop, summary);
    }
  }

 private:
  // A checkpoint that cannot be written (disk full) does not stop the run: it is said in the
  // summary, and the previous checkpoint, untouched, is still there to resume from.
  void checkpoint(LoopState& loop, RunSummary& summary) {
    if (policy_.path.empty()) return;
    const auto t0 = Clock::now();
    try {
      ++summary.checkpoints;
      StateArchive a;
      a.section("grainlab run");
      std::string sceneJson = policy_.sceneJson;
      a(sceneJson);
      LoopState saved = loop;
      saved.wallBefore = loop.wallBefore + since(start_);
      saved.persist(a, summary);
      context_.persist(a);
      a.section("output");
      observer_.persistOutput(a);
      a.section("end");
      writeCheckpointFile(policy_.path, a.bytes());
      summary.checkpointError.clear();
    } catch (const std::exception& e) {
      --summary.checkpoints;
      summary.checkpointError = e.what();
    }
    summary.checkpointSeconds += since(t0);
    lastCheckpoint_ = Clock::now();
  }

  // The specimen as this stage left it, for runs that start from it (prepared_specimen.hpp).
  // Like a checkpoint, one that cannot be written is said and the run goes on.
  void keepStage(size_t s, const LoopState& loop, RunSummary& summary) {
    if (stageDirectory_.empty() || !keepsStageCheckpoints(scene_)) return;
    const auto t0 = Clock::now();
    try {
      summary.stageCheckpointBytes +=
          writeStageCheckpoint(stageCheckpointPath(stageDirectory_, scene_.stages[s].name), scene_, context_, s,
                               PreparedHistory{summary.notes, loop.timestepNoted});
      ++summary.stageCheckpoints;
    } catch (const std::exception& e) {
      summary.checkpointError = e.what();
    }
    summary.stageCheckpointSeconds += since(t0);
  }

  const Scene& scene_;
  RunContext& context_;
  World& world_;
  RunObserver& observer_;
  const CheckpointPolicy& policy_;
  const std::string& stageDirectory_;
  Clock::time_point start_;
  Clock::time_point lastCheckpoint_;
};

// Runs the loop, turns what it throws into a failed summary, and finishes the summary.
RunSummary finish(const Scene& scene, RunContext& context, RunObserver& observer, const CheckpointPolicy& policy,
                  const std::string& stageDirectory, LoopState& loop, RunSummary summary, bool resumed,
                  Clock::time_point start) {
  World& world = context.world();
  try {
    RunLoop(scene, context, observer, policy, stageDirectory, start).run(loop, summary, resumed);
  } catch (const std::exception& e) {
    summary.status = RunStatus::Failed;
    // A run that fails for physical reasons names the scene field most likely responsible;
    // the engine's own reason follows.
    const std::string cause = likelyCause(scene, world);
    summary.error = cause.empty() ? e.what() : cause + "; the run stopped: " + e.what();
  }
  summary.warnings = context.runWarnings();
  summary.steps = world.stepCount();
  summary.particles = world.size();
  summary.peakPhiMobDeg = context.peakPhiMobDeg();
  summary.voidRatioAfterConsolidation = context.voidRatioAfterConsolidation();
  summary.sampleSeconds = context.sampleSeconds();
  summary.wallSeconds = loop.wallBefore + since(start);
  if (summary.status == RunStatus::Completed) {
    observer.onProgress(1.0, "done", world);
    // A finished run has nothing to resume: its checkpoints would only take space.
    if (!policy.path.empty()) {
      std::error_code ec;
      std::filesystem::remove(policy.path, ec);
      std::filesystem::remove(policy.path + ".previous", ec);
    }
  }
  observer.onFinish(summary, world);
  return summary;
}

// The payload of the checkpoint at `path`, or if it cannot be read, of the one before it;
// `note` (if given) then says why, and the unreadable one is moved aside to `.refused`, so the
// next checkpoint does not push the good one out as `.previous`.
std::string readNewestCheckpoint(const std::string& path, std::string* note) {
  try {
    return readCheckpointFile(path);
  } catch (const CheckpointError& newest) {
    std::string payload;
    try {
      payload = readCheckpointFile(path + ".previous");
    } catch (const CheckpointError& previous) {
      throw CheckpointError(std::string(newest.what()) + "; and " + previous.what());
    }
    if (note) {
      *note = std::string(newest.what()) + ": resumed from the checkpoint before it";
      std::error_code ec;
      std::filesystem::rename(path, path + ".refused", ec);
    }
    return payload;
  }
}

}  // namespace

Scene checkpointScene(const std::string& path) {
  const std::string payload = readNewestCheckpoint(path, nullptr);  // the archive only views it
  StateArchive a(payload);
  a.section("grainlab run");
  std::string json;
  a(json);
  return parseScene(nlohmann::json::parse(json));
}

RunSummary runScene(const Scene& scene, RunObserver& observer, const RunLimits& limits, const CheckpointPolicy& checkpoint,
                    const std::string& stageDirectory) {
  const auto start = Clock::now();
  RunSummary summary;
  std::unique_ptr<RunContext> context;
  // Refused by field: past a hard limit of what the scene alone decides, or unbuildable.
  auto refuse = [&](const std::string& why) {
    summary.status = RunStatus::Failed;
    summary.refused = summary.refusedInvalid = true;
    summary.error = why;
    summary.wallSeconds = since(start);
    return summary;
  };
  if (const ValidityAssessment alone = assessSceneAlone(scene); !alone.refusals.empty())
    return refuse(alone.refusalMessage());
  try {
    context = std::make_unique<RunContext>(scene);
  } catch (const SceneError& e) {
    return refuse(e.field() + ": " + e.reason());
  } catch (const std::exception& e) {
    summary.status = RunStatus::Failed;
    summary.error = e.what();
    return summary;
  }
  LoopState loop;
  if (scene.startFrom) {
    // A prepared specimen stands in for the scene's first stages; one that is missing or does
    // not fit the scene is refused before anything is written.
    try {
      PreparedHistory history;
      loop.stage = loadPreparedSpecimen(scene, *context, history);
      for (size_t s = 0; s < loop.stage; ++s) loop.workDone += stageWork(scene.stages[s].type);
      loop.timestepNoted = history.timestepNoted;
      summary.notes = history.notes;
    } catch (const std::exception& e) {
      return refuse(e.what());
    }
  }
  World& world = context->world();
  summary.particles = world.size();
  const RunCost cost = estimateRunCost(scene, world, loop.stage);
  observer.onEstimate(cost);
  // The validity envelope: refused past a hard limit, naming the field; warned past a soft one.
  const ValidityAssessment validity = assessValidity(scene, world, cost, std::numeric_limits<double>::infinity());
  if (!validity.refusals.empty()) return refuse(validity.refusalMessage());
  context->addWarnings(validity.warnings);  // kept with the run's state: a resumed run has them
  observer.onWarnings(validity.warnings);
  if (cost.certainSeconds() > limits.maxSeconds) {
    std::ostringstream os;
    os << cost.field << ": the run would take at least about " << humanDuration(cost.certainSeconds()) << " (" << cost.describe()
       << "), more than the limit of " << humanDuration(limits.maxSeconds) << "; change " << cost.field
       << ", or raise the limit if you mean it";
    summary.status = RunStatus::Failed;
    summary.refused = true;
    summary.error = os.str();
    summary.wallSeconds = since(start);
    return summary;
  }
  observer.onStart(scene, world);
  if (scene.startFrom) {
    try {
      context->sampleSpecimen(observer);  // the series begins where the preparation's ended
    } catch (const std::exception& e) {
      summary.status = RunStatus::Failed;
      summary.error = e.what();
      observer.onFinish(summary, world);
      return summary;
    }
  }
  return finish(scene, *context, observer, checkpoint, stageDirectory, loop, summary, false, start);
}

RunSummary resumeRun(const std::string& path, RunObserver& observer, const CheckpointPolicy& checkpoint,
                     const std::string& stageDirectory) {
  const auto start = Clock::now();
  RunSummary summary;
  std::string payload;
  Scene scene;
  std::unique_ptr<RunContext> context;
  LoopState loop;
  CheckpointPolicy policy = checkpoint;
  try {
    payload = readNewestCheckpoint(path, &summary.resumeNote);
    StateArchive a(payload);
    a.section("grainlab run");
    a(policy.sceneJson);
    scene = parseScene(nlohmann::json::parse(policy.sceneJson));
    context = std::make_unique<RunContext>(scene);
    loop.persist(a, summary);
    context->persist(a);
    a.section("output");
    observer.persistOutput(a);
    a.section("end");
    a.expectEnd();
  } catch (const std::exception& e) {
    summary.status = RunStatus::Failed;
    summary.error = e.what();
    summary.refused = true;  // nothing was run or written
    return summary;
  }
  World& world = context->world();
  summary.resumedFromStep = world.stepCount();
  summary.resumedFromTime = world.time();
  // The stages still to run, from the one it resumes in (that one counted whole).
  observer.onEstimate(estimateRunCost(scene, world, loop.stage));
  try {
    observer.onResume(scene, world);
  } catch (const std::exception& e) {
    summary.status = RunStatus::Failed;
    summary.error = e.what();
    summary.refused = true;
    return summary;
  }
  return finish(scene, *context, observer, policy, stageDirectory, loop, summary, true, start);
}

}  // namespace grainlab
