#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"
#include "run_context.hpp"

namespace grainlab {
namespace {

using Clock = std::chrono::steady_clock;

// Progress is reported, and cancellation polled, this often (steps).
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

}  // namespace

RunSummary runScene(const Scene& scene, RunObserver& observer, const RunLimits& limits) {
  const auto start = Clock::now();
  RunSummary summary;
  std::unique_ptr<RunContext> context;
  try {
    context = std::make_unique<RunContext>(scene);
  } catch (const std::exception& e) {
    summary.status = "failed";
    summary.error = e.what();
    return summary;
  }
  World& world = context->world();
  summary.particles = world.size();
  const RunCost cost = estimateRunCost(scene, world);
  observer.onEstimate(cost);
  if (cost.certainSeconds() > limits.maxSeconds) {
    std::ostringstream os;
    os << cost.field << ": the run would take about " << humanDuration(cost.certainSeconds()) << " (" << cost.describe()
       << "), more than the limit of " << humanDuration(limits.maxSeconds) << "; change " << cost.field
       << ", or raise the limit if you mean it";
    summary.status = "failed";
    summary.refused = true;
    summary.error = os.str();
    summary.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    return summary;
  }
  observer.onStart(scene, world);
  try {
    const double totalWork = context->totalWork();
    double workDone = 0;
    bool timestepNoted = false;
    for (size_t s = 0; s < scene.stages.size(); ++s) {
      Stage& stage = context->beginStage(s);
      context->sample(observer);  // the state the stage starts from
      while (!stage.finished()) {
        stage.beforeStep();
        world.step();
        stage.afterStep();
        const std::int64_t step = world.stepCount();
        if (step % kHealthEvery == 0) {
          world.checkHealth();
          if (!timestepNoted) timestepNoted = notePackingTimestep(world, summary);
        }
        if (context->sampleDue()) context->sample(observer);
        if (step % kProgressEvery == 0) {
          observer.onProgress((workDone + stage.progress() * stage.work()) / totalWork, stage.name(), world);
          if (observer.cancelRequested()) {
            summary.status = "cancelled";
            break;
          }
        }
      }
      if (summary.status == "cancelled") break;
      context->sample(observer);  // the state the stage ends in
      if (const std::string note = stage.endNote(); !note.empty()) summary.notes.push_back(note);
      workDone += stage.work();
      context->endStage();
    }
  } catch (const std::exception& e) {
    summary.status = "failed";
    summary.error = e.what();
  }
  summary.steps = world.stepCount();
  summary.peakPhiMobDeg = context->peakPhiMobDeg();
  summary.voidRatioAfterConsolidation = context->voidRatioAfterConsolidation();
  summary.sampleSeconds = context->sampleSeconds();
  summary.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (summary.status == "completed") observer.onProgress(1.0, "done", world);
  observer.onFinish(summary, world);
  return summary;
}

}  // namespace grainlab
