#pragma once
// Running a scene end to end: build the world, go through the stages, sample the series.
// Whoever watches (the CLI's file writer, the server) does so through a RunObserver.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "grainlab/checkpoint.hpp"
#include "grainlab/run_cost.hpp"
#include "grainlab/run_status.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/series_column.hpp"
#include "grainlab/validity.hpp"

namespace grainlab {

class World;
namespace analysis { struct PolarHistograms; }

struct Sample {
  std::int64_t step = 0;
  double time = 0;
  std::string stage;
  std::vector<double> values;                       ///< one per seriesColumns() entry
  const analysis::PolarHistograms* histograms = nullptr;  ///< null unless output.histograms
};

struct RunSummary {
  /// Completed, Failed, Cancelled or Interrupted (stopped on request; resumable from its
  /// checkpoint if it had one).
  RunStatus status = RunStatus::Completed;
  std::string error;                  ///< why it failed
  bool refused = false;               ///< failed before its first step: its cost is over the limit
  /// refused for what the scene itself says: the validity envelope's hard limits say its
  /// results would mean nothing (grainlab/validity.hpp), or its prepared specimen (start_from)
  /// is missing or does not fit; a larger cost limit does not lift these
  bool refusedInvalid = false;
  /// The validity envelope's warnings: before the first step, then the first crossings measured
  /// during the run (with their step).
  std::vector<ValidityWarning> warnings;
  double wallSeconds = 0;
  double sampleSeconds = 0;           ///< of wallSeconds, spent measuring samples (analysis)
  std::int64_t steps = 0;
  int particles = 0;
  double peakPhiMobDeg = 0;
  double voidRatioAfterConsolidation = -1;  ///< -1 if the scene has no isotropic stage
  std::vector<std::string> notes;           ///< stages that ended at a limit, and similar
  /// Of the run's checkpoints: how many were written, the wall time spent writing them, and
  /// the last one's error if one could not be written (the run goes on; the previous good
  /// checkpoint stays).
  int checkpoints = 0;
  double checkpointSeconds = 0;
  std::string checkpointError;
  /// Of the stage checkpoints (runScene's stageDirectory): how many were written, their
  /// payload bytes in all, and the wall time spent writing them.
  int stageCheckpoints = 0;
  std::uint64_t stageCheckpointBytes = 0;
  double stageCheckpointSeconds = 0;
  /// resumeRun: said when the newest checkpoint could not be read and the one before it was
  /// used (not part of summary.json: the outputs are the same either way).
  std::string resumeNote;
  /// resumeRun: the step and simulated time (s) of the checkpoint the run continued from; -1
  /// and 0 for a run that started afresh. The sign that a resume used its checkpoint (not part
  /// of summary.json either).
  std::int64_t resumedFromStep = -1;
  double resumedFromTime = 0;
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// Once the world is built and its cost estimated, before onStart (and instead of it when
  /// the run is refused for its cost).
  virtual void onEstimate(const RunCost&) {}
  /// After onEstimate, when the scene is inside the validity envelope's hard limits: its
  /// warnings (possibly none). Not called on resume.
  virtual void onWarnings(const std::vector<ValidityWarning>&) {}
  /// Once the world is built, before the first step.
  virtual void onStart(const Scene&, const World&) {}
  /// At every sample; the world is in the state the sample describes.
  virtual void onSample(const Sample&, const World&) {}
  /// Every few hundred steps: overall progress in [0, 1] and the stage's name. Cheap calls
  /// only (the simulation waits for it); a frame grabber checks its own clock here.
  virtual void onProgress(double /*fraction*/, std::string_view /*stage*/, const World&) {}
  /// Polled with onProgress; true stops the run as cancelled.
  virtual bool cancelRequested() { return false; }
  /// Polled with onProgress; true stops the run as interrupted, after a checkpoint (a
  /// clean stop: SIGTERM, a server shutting down), so it can be resumed.
  virtual bool stopRequested() { return false; }
  /// Polled with onProgress: threads lent to the run beyond its scene's solver.threads (a
  /// batch lends a run the cores its finished runs leave idle). The run takes them at once;
  /// they change no result, only how soon it comes.
  virtual int threadsLent() { return 0; }
  /// Checkpoints: the observer's own part of the run's state. Saving, it first makes what
  /// it has written so far durable, then records where it stands (a file's length, a sample
  /// count); loading, before onResume, it reads that back.
  virtual void persistOutput(StateArchive&) {}
  /// Instead of onStart when a run resumes from a checkpoint: the observer cuts its outputs
  /// back to where the checkpoint stood (a crash may have written past it) and carries on.
  virtual void onResume(const Scene& scene, const World& world) { onStart(scene, world); }
  virtual void onFinish(const RunSummary&, const World&) {}
};

/// Never throws for a failing simulation: the summary says failed and why. A run certain to
/// take longer than `limits.maxSeconds` (RunCost::certainSeconds) is refused before its first
/// step: the summary says failed, names the field that drives the cost and gives the figures,
/// and the observer sees only onEstimate (nothing is written).
///
/// With a `checkpoint` path, the run's state is written there every checkpoint.everySeconds of
/// wall time (at the next step where the world is resumable) and when it stops on request.
///
/// With a `stageDirectory`, the run keeps its state at the end of each stage in
/// stageDirectory/stages/ if the scene keeps them (output.stage_checkpoints), for runs that
/// start from it (grainlab/prepared_specimen.hpp).
RunSummary runScene(const Scene& scene, RunObserver& observer, const RunLimits& limits = {},
                    const CheckpointPolicy& checkpoint = {}, const std::string& stageDirectory = {});

/// Continues the run saved in the checkpoint at `path` (its scene is inside it) as if it had
/// never stopped: the same steps, samples and outputs, bit for bit. Goes on writing
/// checkpoints to checkpoint.path (usually `path` again) if set. A checkpoint that cannot be
/// read fails the run with the reason, before onStart or onResume.
RunSummary resumeRun(const std::string& path, RunObserver& observer, const CheckpointPolicy& checkpoint = {},
                     const std::string& stageDirectory = {});
/// The scene of the checkpoint that resumeRun(path) would resume (the newest readable one).
/// Throws CheckpointError if none can be read.
Scene checkpointScene(const std::string& path);

}  // namespace grainlab
