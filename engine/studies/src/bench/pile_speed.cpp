#include "grainlab/studies/bench/pile_speed.hpp"

#include <algorithm>
#include <chrono>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::bench {

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  if (n == 0) return 0;
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

double PileSpeed::medianRate() const { return median(rates); }
double PileSpeed::medianCpuRate() const { return median(cpuRates); }

std::vector<Scene> benchPiles() {
  // The disc pile once more with one far-away polygon: it takes the general path instead of
  // the discs-only one, so the two measure what modelling only what the scene needs is worth.
  Scene general = pileScene(50, 50, false);
  general.name = "disc-pile+1poly";
  ParticleSpec far;
  far.shape = ShapeKind::Polygon;
  far.vertices = {{-0.002, -0.002}, {0.002, -0.002}, {0.002, 0.002}, {-0.002, 0.002}};
  far.position = Vec2(10.0, 10.0);
  far.motion = Motion::Fixed;
  general.particles.push_back(far);
  // The disc pile with rolling resistance, as the circular-rolling preset's material has it:
  // what the rolling couple and its history cost per step.
  Scene rolling = pileScene(50, 50, false);
  rolling.name = "disc-pile-rolling";
  rolling.material.rollingFriction = 0.1;
  rolling.material.rollingDamping = 0.3;
  return {pileScene(50, 50, false), general, pileScene(50, 50, true), rolling, clumpPileScene(50, 50)};
}

PileSpeed measurePileSpeed(const Scene& scene, int steps, int repeats, int threads, WorldSettings::Engine engine,
                           std::ostream* progress) {
  WorldSettings settings;
  settings.threads = threads;
  settings.engine = engine;
  World world(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) world.addParticle(p);
  for (const Wall& w : scene.walls) world.addWall(w);
  world.setGravity(scene.gravity);
  // Settle first (not timed): the pile is dense, with a realistic number of contacts.
  const int settleSteps = static_cast<int>(scene.stages.front().duration / world.timestep());
  for (int k = 0; k < settleSteps; ++k) world.step();
  world.checkHealth();
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  PileSpeed r{scene.name, world.size(), 2.0 * contacts.size() / world.size(), {}, world.timestep()};
  if (progress) *progress << "bench: " << scene.name << " settled, timing\n";
  for (int rep = 0; rep < repeats; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = threadCpuSeconds();
    for (int k = 0; k < steps; ++k) world.step();
    const double cpu = threadCpuSeconds() - cpu0;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.rates.push_back(world.size() * static_cast<double>(steps) / s);
    if (threads == 1) r.cpuRates.push_back(world.size() * static_cast<double>(steps) / cpu);
  }
  world.checkHealth();
  return r;
}

}  // namespace grainlab::bench
