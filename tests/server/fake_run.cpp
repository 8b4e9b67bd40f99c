#include "fake_run.hpp"

#include <cmath>
#include <thread>

#include "grainlab/world.hpp"

namespace grainlab::server::testing {

RunFunction fakeRun(FakeRun spec) {
  return [spec](const RunRequest& request, RunObserver& observer) {
    const Scene& scene = request.scene;
    World world(scene.material);
    ParticleSpec p;
    p.radius = 0.002;
    for (int i = 0; i < 3; ++i) {
      p.position = Vec2(0.005 * i, 0);
      world.addParticle(p);
    }
    observer.onStart(scene, world);
    RunSummary summary;
    summary.particles = world.size();
    const auto& columns = seriesColumns();
    for (int s = 0; s < spec.samples; ++s) {
      for (int k = 0; k < spec.stepsPerSample; ++k) world.step();
      std::this_thread::sleep_for(spec.delayPerSample);
      observer.onProgress(double(s + 1) / spec.samples, "free", world);
      const bool stop = observer.stopRequested();  // a clean stop, as the engine's: interrupted
      if (stop || observer.cancelRequested()) {
        summary.status = stop ? RunStatus::Interrupted : RunStatus::Cancelled;
        observer.onFinish(summary, world);
        return summary;
      }
      Sample sample;
      sample.step = world.stepCount();
      sample.time = world.time();
      sample.stage = "free";
      for (std::size_t c = 0; c < columns.size(); ++c)
        sample.values.push_back(columns[c] == "step"    ? double(sample.step)
                                : columns[c] == "time"  ? sample.time
                                : columns[c] == "stage" ? NAN
                                                        : double(c + s));
      observer.onSample(sample, world);
    }
    summary.steps = world.stepCount();
    if (spec.fail) {
      summary.status = RunStatus::Failed;
      summary.error = "particle 1 has a non-finite position (timestep too large?)";
    }
    observer.onFinish(summary, world);
    return summary;
  };
}

}  // namespace grainlab::server::testing
