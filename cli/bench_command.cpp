#include "bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

struct Result {
  std::string name;
  int particles = 0;
  double coordination = 0;  // contacts per particle (×2) when timing starts
  std::vector<double> rates;  // particle-steps per second, one per repeat
  double timestep = 0;        // s
};


Result measure(const Scene& scene, int steps, int repeats, int threads,
               WorldSettings::Engine engine = WorldSettings::Engine::Dem) {
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
  Result r{scene.name, world.size(), 2.0 * contacts.size() / world.size(), {}, world.timestep()};
  std::cerr << "bench: " << scene.name << " settled, timing\n";
  for (int rep = 0; rep < repeats; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k) world.step();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.rates.push_back(world.size() * static_cast<double>(steps) / s);
  }
  world.checkHealth();
  return r;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int benchCommand(const std::vector<std::string>& args) {
  int steps = 2000, repeats = 5, threads = 1;
  std::string only;  // one scene by name, for profiling
  for (size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "--steps" && k + 1 < args.size()) steps = std::stoi(args[++k]);
    else if (args[k] == "--scene" && k + 1 < args.size()) only = args[++k];
    else if (args[k] == "--repeats" && k + 1 < args.size()) repeats = std::stoi(args[++k]);
    else if (args[k] == "--threads" && k + 1 < args.size()) threads = std::stoi(args[++k]);
    else {
      std::cerr << "grainlab bench: unexpected argument " << args[k] << "\n";
      return 2;
    }
  }
  // The same disc pile once more with one far-away polygon: it takes the general path (shape
  // dispatch per pair) instead of the discs-only one, so the two measure what modelling only
  // what the scene needs is worth.
  Scene general = pileScene(50, 50, false);
  general.name = "disc-pile+1poly";
  ParticleSpec far;
  far.shape = ShapeKind::Polygon;
  far.vertices = {{-0.002, -0.002}, {0.002, -0.002}, {0.002, 0.002}, {-0.002, 0.002}};
  far.position = Vec2(10.0, 10.0);
  far.motion = Motion::Fixed;
  general.particles.push_back(far);
  const std::vector<Scene> scenes{pileScene(50, 50, false), general, pileScene(50, 50, true)};
  std::vector<Result> results;
  for (const Scene& scene : scenes) {
    if (!only.empty() && scene.name != only) continue;
    std::cerr << "bench: " << scene.name << " settling, then " << repeats << " x " << steps << " steps\n";
    results.push_back(measure(scene, steps, repeats, threads));
  }
  std::cout << std::left << std::setw(16) << "scene" << std::setw(11) << "particles" << std::setw(14)
            << "coordination" << "median particle-steps/s"
            << "   (min .. max)\n";
  for (const Result& r : results) {
    std::cout << std::setw(16) << r.name << std::setw(11) << r.particles << std::setw(14) << std::setprecision(3)
              << r.coordination << std::setprecision(4) << median(r.rates) / 1e6
              << " M" << std::setw(17) << " " << "(" << *std::min_element(r.rates.begin(), r.rates.end()) / 1e6
              << " .. " << *std::max_element(r.rates.begin(), r.rates.end()) / 1e6 << " M)\n";
  }
  if (results.empty()) {
    std::cerr << "grainlab bench: no scene named " << only << " (disc-pile, disc-pile+1poly, polygon-pile)\n";
    return 2;
  }
  if (results.size() == scenes.size()) {
    std::cout << "discs-only path / general path: " << median(results[0].rates) / median(results[1].rates) << "\n";
    std::cout << "polygons / discs: " << median(results[2].rates) / median(results[0].rates) << "\n";
    // The box2d engine on the same settled piles, at its default timestep (10x the DEM's): per
    // step it is slower, per simulated second the timestep ratio counts too.
    for (size_t k : {size_t{0}, size_t{2}}) {
      std::cerr << "bench: " << scenes[k].name << " with box2d\n";
      const Result b = measure(scenes[k], std::max(1, steps / 10), repeats, threads, WorldSettings::Engine::Box2d);
      const double perStep = median(b.rates) / median(results[k].rates);
      std::cout << "box2d " << std::setw(14) << b.name << std::setprecision(4) << median(b.rates) / 1e6
                << " M particle-steps/s: " << perStep << "x the dem per step, "
                << perStep * b.timestep / results[k].timestep << "x per simulated second (timestep "
                << b.timestep / results[k].timestep << "x)\n";
    }
  }
  return 0;
}

}  // namespace grainlab
