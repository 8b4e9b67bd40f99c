// Engine step throughput, reported as particle-steps per second (items_per_second).
// Run: build/bench/engine_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <memory>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/world.hpp"

namespace {

std::unique_ptr<grainlab::World> settledPile(bool polygons) {
  const grainlab::Scene scene = grainlab::pileScene(50, 50, polygons);
  auto world = std::make_unique<grainlab::World>(scene.material);
  for (const auto& p : scene.particles) world->addParticle(p);
  for (const auto& w : scene.walls) world->addWall(w);
  world->setGravity(scene.gravity);
  const int settle = static_cast<int>(scene.stages.front().duration / world->timestep());
  for (int k = 0; k < settle; ++k) world->step();
  return world;
}

void stepPile(benchmark::State& state, bool polygons) {
  static std::unique_ptr<grainlab::World> worlds[2];
  auto& world = worlds[polygons];
  if (!world) world = settledPile(polygons);
  for (auto _ : state) world->step();
  state.SetItemsProcessed(state.iterations() * world->size());
}

void BM_StepDiscPile(benchmark::State& state) { stepPile(state, false); }
void BM_StepPolygonPile(benchmark::State& state) { stepPile(state, true); }

}  // namespace

BENCHMARK(BM_StepDiscPile)->MinTime(2.0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StepPolygonPile)->MinTime(2.0)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
