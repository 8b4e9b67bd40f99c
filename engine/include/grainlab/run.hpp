#pragma once
// Running a scene end to end: build the world, go through the stages, sample the series.
// Whoever watches (the CLI's file writer, the server) does so through a RunObserver.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "grainlab/scene.hpp"

namespace grainlab {

class World;
namespace analysis { struct PolarHistograms; }

/// The columns of series.csv, in order (contracts.md plus extensions).
const std::vector<std::string>& seriesColumns();
/// The position of a column in seriesColumns(); throws std::logic_error for an unknown name.
std::size_t seriesColumnIndex(std::string_view name);

struct Sample {
  std::int64_t step = 0;
  double time = 0;
  std::string stage;
  std::vector<double> values;                       ///< one per seriesColumns() entry
  const analysis::PolarHistograms* histograms = nullptr;  ///< null unless output.histograms
};

struct RunSummary {
  std::string status = "completed";   ///< completed | failed | cancelled
  std::string error;                  ///< why it failed
  double wallSeconds = 0;
  double sampleSeconds = 0;           ///< of wallSeconds, spent measuring samples (analysis)
  std::int64_t steps = 0;
  int particles = 0;
  double peakPhiMobDeg = 0;
  double voidRatioAfterConsolidation = -1;  ///< -1 if the scene has no isotropic stage
  std::vector<std::string> notes;           ///< stages that ended at a limit, and similar
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// Once the world is built, before the first step.
  virtual void onStart(const Scene&, const World&) {}
  /// At every sample; the world is in the state the sample describes.
  virtual void onSample(const Sample&, const World&) {}
  /// Every few hundred steps: overall progress in [0, 1] and the stage's name. Cheap calls
  /// only (the simulation waits for it); a frame grabber checks its own clock here.
  virtual void onProgress(double /*fraction*/, std::string_view /*stage*/, const World&) {}
  /// Polled with onProgress; true stops the run as cancelled.
  virtual bool cancelRequested() { return false; }
  virtual void onFinish(const RunSummary&, const World&) {}
};

/// Never throws for a failing simulation: the summary says failed and why.
RunSummary runScene(const Scene& scene, RunObserver& observer);

}  // namespace grainlab
