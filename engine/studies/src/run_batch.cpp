#include "grainlab/studies/run_batch.hpp"

#include <atomic>
#include <fstream>
#include <sstream>
#include <thread>

#include "batch_execution.hpp"
#include "grainlab/checkpoint.hpp"
#include "grainlab/run_output.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/cluster.hpp"

namespace grainlab::studies {
namespace {

namespace fs = std::filesystem;

// Passes every event on to the run's own observer, tells the progress line how far it is, and
// hands the run the cores it is lent.
class ProgressRelay : public RunObserver {
 public:
  ProgressRelay(RunObserver& inner, BatchProgress& progress, const std::string& id, CoreLending* lending)
      : inner_(inner), progress_(progress), id_(id), lending_(lending) {}
  void onEstimate(const RunCost& c) override { inner_.onEstimate(c); }
  void onStart(const Scene& s, const World& w) override { inner_.onStart(s, w); }
  void onSample(const Sample& s, const World& w) override { inner_.onSample(s, w); }
  void onProgress(double fraction, std::string_view stage, const World& w) override {
    inner_.onProgress(fraction, stage, w);
    progress_.advanced(id_, fraction);
    if (lending_) lending_->advanced(id_, fraction);
  }
  int threadsLent() override { return lending_ ? lending_->threadsLent(id_) : 0; }
  bool cancelRequested() override { return inner_.cancelRequested(); }
  bool stopRequested() override { return inner_.stopRequested(); }
  void persistOutput(StateArchive& a) override { inner_.persistOutput(a); }
  void onResume(const Scene& s, const World& w) override { inner_.onResume(s, w); }
  void onFinish(const RunSummary& s, const World& w) override { inner_.onFinish(s, w); }

 private:
  RunObserver& inner_;
  BatchProgress& progress_;
  const std::string& id_;
  CoreLending* lending_;
};

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// For a run that ended before its observer wrote a summary (its world could not be built, or
// its directory could not be written): the same file, saying why.
void writeFailureSummary(const fs::path& dir, const BatchRunResult& result) {
  const nlohmann::json summary{{"status", toString(result.status)}, {"error", result.error}, {"wall_seconds", result.wallSeconds}};
  writeText(dir / "summary.json", summary.dump(2) + "\n");
}

// The run's folder was written for this very scene (a changed preset or spec means a new run).
bool sameScene(const fs::path& dir, const nlohmann::json& scene) {
  std::ifstream in(dir / kSceneFile);
  if (!in) return false;
  try {
    return nlohmann::json::parse(in) == scene;
  } catch (const std::exception&) {
    return false;
  }
}

void runLocally(const std::vector<BatchRun>& runs, const std::vector<size_t>& pending, BatchOptions options,
                BatchProgress& progress, std::vector<BatchRunResult>& results, const Cluster& cluster) {
  // A launcher binds each rank to a core: under `mpirun -np 1` two runs would share one.
  if (options.jobs == 0 && cluster.joinedMpi()) options.jobs = 1;
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const size_t cores = options.jobs == 0 ? hardware : options.jobs;
  const size_t threads = std::min<size_t>(cores, pending.size());
  std::atomic<size_t> next{0};
  CoreLending lending;
  // Cores beyond the runs (more jobs than runs, up to the machine's) are idle from the start.
  lending.release(static_cast<int>(std::min<size_t>(cores, hardware)) - static_cast<int>(threads));
  auto worker = [&] {
    for (size_t k = next++; k < pending.size(); k = next++) {
      results[pending[k]] = executeRun(runs[pending[k]], options.observer, progress, &lending);
    }
    lending.release(1);  // no run left to start: this worker's core goes to the runs still going
  };
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();  // this thread works too
  for (std::thread& t : pool) t.join();
}

}  // namespace

BatchRunResult executeRun(const BatchRun& run, const ObserverFactory& factory, BatchProgress& progress,
                          CoreLending* lending) {
  const fs::path work = run.dir.parent_path() / ("." + run.dir.filename().string() + ".partial");
  progress.started(run.id);
  if (lending) lending->started(run.id);
  BatchRunResult result;
  try {
    // Runs writing what `grainlab run` writes keep a checkpoint in their partial directory:
    // an attempt killed half-way (a preempted machine) is resumed from it by the next
    // invocation, with the same outputs. Other observers (a study's own) start over.
    const std::string checkpoint = (work / "checkpoint.bin").string();
    const bool resumable = !factory && sameScene(work, run.scene) &&
                           (fs::exists(checkpoint) || fs::exists(checkpoint + ".previous"));
    auto startOver = [&] {
      fs::remove_all(work);  // what an interrupted attempt left
      fs::create_directories(work);
      writeText(work / kSceneFile, run.scene.dump(2) + "\n");
    };
    if (!resumable) startOver();  // before parsing: a bad scene's failure is recorded there
    const Scene scene = parseScene(run.scene);
    auto makeObserver = [&]() -> std::unique_ptr<RunObserver> {
      return factory ? factory(run, work) : std::make_unique<RunOutput>(work.string(), scene, nullptr);
    };
    const CheckpointPolicy policy =
        factory ? CheckpointPolicy{} : CheckpointPolicy{checkpoint, scene.output.checkpointEverySeconds, run.scene.dump()};
    // Like `grainlab run`, it keeps its stages' ends in stages/ (a sweep's "prepare" starts from them).
    const std::string stageDirectory = factory ? std::string() : work.string();
    RunSummary summary;
    std::unique_ptr<RunObserver> observer;
    if (resumable) {
      observer = makeObserver();
      ProgressRelay relay(*observer, progress, run.id, lending);
      summary = resumeRun(checkpoint, relay, policy, stageDirectory);
      result.resumed = !summary.refused;
    }
    if (!result.resumed) {  // nothing to resume from, or its checkpoints could not be read
      if (resumable) startOver();
      observer = makeObserver();
      ProgressRelay relay(*observer, progress, run.id, lending);
      summary = runScene(scene, relay, {}, policy, stageDirectory);
    }
    result.status = summary.status;
    result.error = summary.error;
    result.wallSeconds = summary.wallSeconds;
    if (!fs::exists(work / "summary.json")) writeFailureSummary(work, result);
  } catch (const std::exception& e) {
    result.status = RunStatus::Failed;
    result.error = e.what();
    try {
      writeFailureSummary(work, result);
    } catch (const std::exception&) {
      // Nothing more can be recorded; without a summary the run counts as not finished.
    }
  }
  try {
    // Under its own name a run is finished: nothing there to resume.
    for (const char* suffix : {"", ".previous", ".tmp", ".refused"}) fs::remove(work / (std::string("checkpoint.bin") + suffix));
    fs::remove_all(run.dir);  // an earlier failed attempt
    fs::rename(work, run.dir);
  } catch (const std::exception& e) {
    result.status = RunStatus::Failed;
    result.error = "cannot move the run into " + run.dir.string() + ": " + e.what();
  }
  if (lending) result.threadsLent = lending->finished(run.id);
  progress.finished(run.id, result.status, result.wallSeconds, result.threadsLent);
  return result;
}

std::optional<BatchRunResult> finishedRun(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (!in) return std::nullopt;
  try {
    const nlohmann::json summary = nlohmann::json::parse(in);
    BatchRunResult result;
    const std::optional<RunStatus> status = parseRunStatus(summary.at("status").get<std::string>());
    if (!status) return std::nullopt;
    result.status = *status;
    result.error = summary.value("error", std::string());
    result.wallSeconds = summary.value("wall_seconds", 0.0);
    return result;
  } catch (const std::exception&) {
    return std::nullopt;  // not a summary this code wrote: not a finished run
  }
}

std::vector<BatchRunResult> runBatch(const std::vector<BatchRun>& runs, const BatchOptions& options,
                                     const Cluster& cluster) {
  std::vector<BatchRunResult> results(runs.size());
  if (!cluster.isRoot()) {
#ifdef GRAINLAB_HAS_MPI
    BatchProgress quiet(nullptr, options.label, 0, 0);
    runDistributed(runs, {}, options, quiet, results, cluster);
#endif
    return {};
  }
  std::vector<size_t> pending;
  for (size_t k = 0; k < runs.size(); ++k) {
    const std::optional<BatchRunResult> earlier = finishedRun(runs[k].dir);
    if (earlier && earlier->status == RunStatus::Completed && sameScene(runs[k].dir, runs[k].scene)) {
      results[k] = *earlier;
      results[k].reused = true;
    } else {
      pending.push_back(k);
    }
  }
  BatchProgress progress(options.progress, options.label, pending.size(), runs.size() - pending.size());
#ifdef GRAINLAB_HAS_MPI
  if (cluster.size() > 1) {
    runDistributed(runs, pending, options, progress, results, cluster);
    return results;
  }
#endif
  runLocally(runs, pending, options, progress, results, cluster);
  return results;
}

}  // namespace grainlab::studies
