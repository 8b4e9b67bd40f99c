#include "grainlab/studies/bench/pile_speed.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <memory>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/simd_path.hpp"

namespace grainlab::bench {

double PileSpeed::medianRate() const { return median(rates); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

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
  return {pileScene(50, 50, false), general, pileScene(50, 50, true)};
}

namespace {

// The scene's world, settled (not timed): the pile is dense, with a realistic number of contacts.
std::unique_ptr<World> settledWorld(const Scene& scene, int threads, WorldSettings::Engine engine) {
  WorldSettings settings;
  settings.threads = threads;
  settings.engine = engine;
  auto world = std::make_unique<World>(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) world->addParticle(p);
  for (const Wall& w : scene.walls) world->addWall(w);
  world->setGravity(scene.gravity);
  const int settleSteps = static_cast<int>(scene.stages.front().duration / world->timestep());
  for (int k = 0; k < settleSteps; ++k) world->step();
  world->checkHealth();
  return world;
}

PileSpeed describe(const Scene& scene, const World& world) {
  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  return PileSpeed{scene.name, world.size(), 2.0 * contacts.size() / world.size(), {}, world.timestep()};
}

// Particle-steps per second over `steps` steps.
double timeSteps(World& world, int steps) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) world.step();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return world.size() * static_cast<double>(steps) / s;
}

}  // namespace

PileSpeed measurePileSpeed(const Scene& scene, int steps, int repeats, int threads, WorldSettings::Engine engine,
                           std::ostream* progress) {
  const std::unique_ptr<World> world = settledWorld(scene, threads, engine);
  PileSpeed r = describe(scene, *world);
  if (progress) *progress << "bench: " << scene.name << " settled, timing\n";
  for (int rep = 0; rep < repeats; ++rep) r.rates.push_back(timeSteps(*world, steps));
  world->checkHealth();
  return r;
}

PathSpeeds measurePathSpeeds(const Scene& scene, int steps, int repeats, int threads, std::ostream* progress) {
  const std::unique_ptr<World> world = settledWorld(scene, threads, WorldSettings::Engine::Dem);
  PathSpeeds r{describe(scene, *world), describe(scene, *world)};
  if (progress) *progress << "bench: " << scene.name << " settled, timing the wide and the baseline path in turn\n";
  for (int rep = 0; rep < repeats; ++rep) {
    for (SimdPath path : {SimdPath::Wide, SimdPath::Baseline}) {
      overrideSimdPath(path);
      const std::clock_t c0 = std::clock();
      (path == SimdPath::Wide ? r.wide : r.baseline).rates.push_back(timeSteps(*world, steps));
      const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      (path == SimdPath::Wide ? r.wideCpuRates : r.baselineCpuRates).push_back(world->size() * static_cast<double>(steps) / cpu);
    }
  }
  overrideSimdPath(std::nullopt);
  world->checkHealth();
  return r;
}

}  // namespace grainlab::bench
