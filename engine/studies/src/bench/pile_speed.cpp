#include "grainlab/studies/bench/pile_speed.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/state_archive.hpp"
#include "grainlab/thread_cpu_clock.hpp"

namespace grainlab::bench {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  if (n == 0) return 0;
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

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

namespace {

// The scene's world as built, not stepped.
std::unique_ptr<World> builtWorld(const Scene& scene, int threads, WorldSettings::Engine engine) {
  WorldSettings settings;
  settings.threads = threads;
  settings.engine = engine;
  auto world = std::make_unique<World>(scene.material, settings);
  for (const ParticleSpec& p : scene.particles) world->addParticle(p);
  for (const Wall& w : scene.walls) world->addWall(w);
  world->setGravity(scene.gravity);
  return world;
}

// The scene's world, settled (not timed): the pile is dense, with a realistic number of contacts.
std::unique_ptr<World> settledWorld(const Scene& scene, int threads, WorldSettings::Engine engine) {
  std::unique_ptr<World> world = builtWorld(scene, threads, engine);
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

// One timed repeat of `steps` steps: its particle-steps per wall-clock second, and with one
// thread per second of the stepping thread's CPU time.
void timeRepeat(World& world, int steps, int threads, PileSpeed& into) {
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = threadCpuSeconds();
  for (int k = 0; k < steps; ++k) world.step();
  const double cpu = threadCpuSeconds() - cpu0;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  into.rates.push_back(world.size() * static_cast<double>(steps) / s);
  if (threads == 1) into.cpuRates.push_back(world.size() * static_cast<double>(steps) / cpu);
}

// The settled pile's solid fraction away from its walls, floor and free surface: the discs
// whose centres lie in a window (the middle half of the width, 15-65 % of the top centre's
// height) over the window's area; discs cut by the window's edges balance on average.
double bulkSolidFraction(const World& world) {
  const auto x = world.positions();
  const auto r = world.boundingRadii();
  double left = x[0].x(), right = left, top = x[0].y();
  for (const Vec2& p : x) {
    left = std::min(left, p.x());
    right = std::max(right, p.x());
    top = std::max(top, p.y());
  }
  const double x0 = left + 0.25 * (right - left), x1 = left + 0.75 * (right - left), y0 = 0.15 * top, y1 = 0.65 * top;
  double solid = 0;
  for (size_t k = 0; k < x.size(); ++k) {
    if (x[k].x() >= x0 && x[k].x() < x1 && x[k].y() >= y0 && x[k].y() < y1) solid += kPi * r[k] * r[k];
  }
  return solid / ((x1 - x0) * (y1 - y0));
}

// The cell's discs compressed isotropically (L = −D I, D = 2 /s) until their solid fraction
// reaches `fraction`, then at rest (L = 0) for 0.01 s (not timed).
std::unique_ptr<World> compressedCell(const Scene& scene, double fraction, int threads) {
  WorldSettings settings;
  settings.threads = threads;
  auto world = std::make_unique<World>(scene.material, settings);
  Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
  h(0, 0) = scene.boundary.cellSize->x();
  h(1, 1) = scene.boundary.cellSize->y();
  world->setPeriodicCell(h);
  double solid = 0;
  for (const ParticleSpec& p : scene.particles) {
    world->addParticle(p);
    solid += kPi * p.radius * p.radius;
  }
  world->initialize();
  world->setCellVelocityGradient(-2.0 * Eigen::Matrix2d::Identity());
  while (solid / world->periodicCell()->area() < fraction) world->step();
  world->setCellVelocityGradient(Eigen::Matrix2d::Zero());
  const int rest = static_cast<int>(0.01 / world->timestep());
  for (int k = 0; k < rest; ++k) world->step();
  world->checkHealth();
  return world;
}

}  // namespace

CellSpeeds measureCellAgainstPile(const Scene& pile, const Scene& cell, double shearRate, int steps, int repeats,
                                  int threads, std::ostream* progress) {
  const std::unique_ptr<World> pileWorld = settledWorld(pile, threads, WorldSettings::Engine::Dem);
  CellSpeeds r;
  r.solidFraction = bulkSolidFraction(*pileWorld);
  if (progress) *progress << "bench: " << pile.name << " settled (bulk solid fraction " << r.solidFraction
                          << "), compressing " << cell.name << " to it\n";
  const std::unique_ptr<World> cellWorld = compressedCell(cell, r.solidFraction, threads);
  Eigen::Matrix2d shear = Eigen::Matrix2d::Zero();
  shear(0, 1) = shearRate;
  cellWorld->setCellVelocityGradient(shear);
  r.pile = describe(pile, *pileWorld);
  r.cell = describe(cell, *cellWorld);
  if (progress) *progress << "bench: timing " << pile.name << " and " << cell.name << " in turn\n";
  for (int rep = 0; rep < repeats; ++rep) {
    timeRepeat(*pileWorld, steps, threads, r.pile);
    timeRepeat(*cellWorld, steps, threads, r.cell);
  }
  pileWorld->checkHealth();
  cellWorld->checkHealth();
  return r;
}

ThreadSpeeds measureThreadScaling(const Scene& scene, int threads, int steps, int repeats, std::ostream* progress) {
  if (progress) *progress << "bench: " << scene.name << " (" << scene.particles.size() << " particles) settling on "
                          << threads << " threads\n";
  const std::unique_ptr<World> threaded = settledWorld(scene, threads, WorldSettings::Engine::Dem);
  StateArchive saved;
  threaded->persist(saved);
  const std::unique_ptr<World> serial = builtWorld(scene, 1, WorldSettings::Engine::Dem);
  serial->initialize();
  StateArchive load(saved.bytes());
  serial->persist(load);
  ThreadSpeeds r{describe(scene, *serial), describe(scene, *threaded)};
  if (progress) *progress << "bench: timing 1 and " << threads << " threads in turn\n";
  for (int rep = 0; rep < repeats; ++rep) {
    timeRepeat(*serial, steps, 1, r.serial);
    timeRepeat(*threaded, steps, threads, r.threaded);
  }
  serial->checkHealth();
  threaded->checkHealth();
  return r;
}

PileSpeed measurePileSpeed(const Scene& scene, int steps, int repeats, int threads, WorldSettings::Engine engine,
                           std::ostream* progress) {
  const std::unique_ptr<World> world = settledWorld(scene, threads, engine);
  PileSpeed r = describe(scene, *world);
  if (progress) *progress << "bench: " << scene.name << " settled, timing\n";
  for (int rep = 0; rep < repeats; ++rep) timeRepeat(*world, steps, threads, r);
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
      timeRepeat(*world, steps, threads, path == SimdPath::Wide ? r.wide : r.baseline);
    }
  }
  overrideSimdPath(std::nullopt);
  world->checkHealth();
  return r;
}

std::vector<PileSpeed> measureInTurn(const std::vector<Scene>& scenes, int steps, int repeats, int threads,
                                     std::ostream* progress) {
  std::vector<std::unique_ptr<World>> worlds;
  std::vector<PileSpeed> r;
  for (const Scene& scene : scenes) {
    worlds.push_back(settledWorld(scene, threads, WorldSettings::Engine::Dem));
    r.push_back(describe(scene, *worlds.back()));
  }
  if (progress) *progress << "bench: " << scenes.size() << " piles settled, timing them in turn\n";
  for (int rep = 0; rep < repeats; ++rep) {
    for (size_t k = 0; k < worlds.size(); ++k) timeRepeat(*worlds[k], steps, threads, r[k]);
  }
  for (const auto& world : worlds) world->checkHealth();
  return r;
}

}  // namespace grainlab::bench
