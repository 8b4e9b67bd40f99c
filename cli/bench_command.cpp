#include "bench_command.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/simd_path.hpp"
#include "grainlab/studies/bench/pile_speed.hpp"
#include "grainlab/studies/bench/ring_cell_speed.hpp"
#include "grainlab/studies/boundary_comparison/boundary.hpp"

namespace grainlab {

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
  // Issue-sized: 20,000 discs (the disc pile's, 200 × 100), on one thread and on --threads
  // (2 unless given) in turn. Only when asked for by name: settling it takes minutes.
  if (only == "disc-pile-20k") {
    Scene large = pileScene(200, 100, false);
    large.name = only;
    const int n = threads > 1 ? threads : 2;
    const bench::ThreadSpeeds t = bench::measureThreadScaling(large, n, steps, repeats, &std::cerr);
    std::cout << only << " " << t.serial.particles << " discs, coordination " << std::setprecision(3)
              << t.serial.coordination << ": 1 thread " << std::setprecision(4) << t.serial.medianRate() / 1e6 << " M, "
              << n << " threads " << t.threaded.medianRate() / 1e6 << " M particle-steps/s in turn: "
              << t.threaded.medianRate() / t.serial.medianRate() << "x\n";
    return 0;
  }
  // The paper's circular specimen in its ring against the same discs in a periodic cell at the
  // ring's density (the boundaries study's cell-matched scene), both prepared by their scenes'
  // stages and timed in turn while they shear. Only when asked for by name: preparing takes
  // about a minute.
  if (only == "ring-cell") {
    using boundaries::Boundary;
    const Scene ring = parseScene(boundaries::boundaryScene(Boundary::Ring, "circular", false, 1));
    const Scene cell = parseScene(boundaries::boundaryScene(Boundary::CellMatched, "circular", false, 1));
    const bench::RingCellSpeeds c = bench::measureCellAgainstRing(ring, cell, steps, repeats, threads, &std::cerr);
    for (const bench::ShearingSpeed* s : {&c.ring, &c.cell}) {
      std::cout << std::setprecision(4) << s->speed.name << ": " << s->speed.particles << " particles ("
                << s->specimenParticles << " specimen, " << s->speed.particles - s->specimenParticles
                << " ring), void ratio " << s->voidRatio << ", coordination " << std::setprecision(3)
                << s->speed.coordination << ", axial strain " << s->axialStrainTimed << " over the timed steps: "
                << std::setprecision(4) << s->speed.medianRate() / 1e6 << " M particle-steps/s\n";
    }
    // Every particle the world steps counts, the ring's own included; per specimen particle,
    // the ratio is that of the two specimens' times per step.
    const double all = c.cell.speed.medianRate() / c.ring.speed.medianRate();
    const double specimen = all * c.ring.speed.particles / c.ring.specimenParticles;
    std::cout << "ring-cell in turn: cell / ring " << all << " per particle-step (the cell costs " << 1 / all
              << "x), " << specimen << " per specimen particle-step (" << 1 / specimen << "x)";
    if (threads == 1) {
      const double cpu = c.cell.speed.medianCpuRate() / c.ring.speed.medianCpuRate();
      std::cout << "; by CPU time " << cpu << " (" << 1 / cpu << "x), " << cpu * c.ring.speed.particles / c.ring.specimenParticles
                << " (" << c.ring.specimenParticles / (cpu * c.ring.speed.particles) << "x)";
    }
    std::cout << "\n";
    return 0;
  }
  const std::vector<Scene> scenes = bench::benchPiles();
  std::vector<bench::PileSpeed> results;
  for (const Scene& scene : scenes) {
    if (!only.empty() && scene.name != only) continue;
    std::cerr << "bench: " << scene.name << " settling, then " << repeats << " x " << steps << " steps\n";
    results.push_back(bench::measurePileSpeed(scene, steps, repeats, threads, WorldSettings::Engine::Dem, &std::cerr));
  }
  std::cout << std::left << std::setw(18) << "scene" << std::setw(11) << "particles" << std::setw(14)
            << "coordination" << "median particle-steps/s"
            << "   (min .. max)\n";
  for (const bench::PileSpeed& r : results) {
    std::cout << std::setw(18) << r.name << std::setw(11) << r.particles << std::setw(14) << std::setprecision(3)
              << r.coordination << std::setprecision(4) << r.medianRate() / 1e6
              << " M" << std::setw(17) << " " << "(" << *std::min_element(r.rates.begin(), r.rates.end()) / 1e6
              << " .. " << *std::max_element(r.rates.begin(), r.rates.end()) / 1e6 << " M)\n";
  }
  if (results.empty() && only != "periodic-pile") {
    std::cerr << "grainlab bench: no scene named " << only
              << " (disc-pile, disc-pile+1poly, polygon-pile, disc-pile-rolling, clump-pile, periodic-pile, ring-cell, disc-pile-20k)\n";
    return 2;
  }
  if (results.size() == scenes.size()) {
    std::cout << "discs-only path / general path: " << results[0].medianRate() / results[1].medianRate() << "\n";
    std::cout << "polygons / discs: " << results[2].medianRate() / results[0].medianRate() << "\n";
    std::cout << "discs / discs with rolling resistance (cost per step): "
              << results[0].medianRate() / results[3].medianRate();
    if (threads == 1) {  // the same by CPU time, which other programs on the machine move far less
      std::cout << " (by CPU time: " << results[0].medianCpuRate() / results[3].medianCpuRate() << ")";
    }
    std::cout << "\n";
    std::cout << "3-disc clumps / discs (per clump-step): " << results[4].medianRate() / results[0].medianRate() << "\n";
    // The same ratios with the piles timed in turn, so that all see the same load.
    const std::vector<bench::PileSpeed> turn =
        bench::measureInTurn({scenes[0], scenes[3], scenes[4], scenes[2]}, steps, repeats, threads, &std::cerr);
    std::cout << "in turn: disc-pile " << std::setprecision(4) << turn[0].medianRate() / 1e6 << " M, disc-pile-rolling "
              << turn[1].medianRate() / 1e6 << " M, clump-pile " << turn[2].medianRate() / 1e6
              << " M: rolling cost " << turn[0].medianRate() / turn[1].medianRate() << ", clumps / discs "
              << turn[2].medianRate() / turn[0].medianRate();
    if (threads == 1) {
      std::cout << " (by CPU time: " << turn[0].medianCpuRate() / turn[1].medianCpuRate() << ", "
                << turn[2].medianCpuRate() / turn[0].medianCpuRate() << ")";
    }
    std::cout << "\n";
    std::cout << "in turn: polygon-pile " << turn[3].medianRate() / 1e6 << " M: polygons / discs "
              << turn[3].medianRate() / turn[0].medianRate();
    if (threads == 1) std::cout << " (by CPU time: " << turn[3].medianCpuRate() / turn[0].medianCpuRate() << ")";
    std::cout << "\n";
    // The box2d engine on the same settled piles, at its default timestep (10x the DEM's): per
    // step it is slower, per simulated second the timestep ratio counts too.
    for (size_t k : {size_t{0}, size_t{2}}) {
      std::cerr << "bench: " << scenes[k].name << " with box2d\n";
      const bench::PileSpeed b = bench::measurePileSpeed(scenes[k], std::max(1, steps / 10), repeats, threads,
                                                         WorldSettings::Engine::Box2d, &std::cerr);
      const double perStep = b.medianRate() / results[k].medianRate();
      std::cout << "box2d " << std::setw(14) << b.name << std::setprecision(4) << b.medianRate() / 1e6
                << " M particle-steps/s: " << perStep << "x the dem per step, "
                << perStep * b.timestep / results[k].timestep << "x per simulated second (timestep "
                << b.timestep / results[k].timestep << "x)\n";
    }
  }
  // The disc pile's discs in a periodic cell, shearing at 1 /s, against the pile in turn: what
  // the cell costs per particle-step (images, the cell's update, its rebuilds).
  if (only.empty() || only == "periodic-pile") {
    const bench::CellSpeeds c = bench::measureCellAgainstPile(scenes[0], periodicPileScene(50, 50), 1.0, steps,
                                                              repeats, threads, &std::cerr);
    std::cout << "periodic-pile " << c.cell.particles << " discs at solid fraction " << std::setprecision(3)
              << c.solidFraction << ", coordination " << c.cell.coordination << " (disc-pile " << c.pile.coordination
              << "): " << std::setprecision(4) << c.cell.medianRate() / 1e6 << " M against disc-pile "
              << c.pile.medianRate() / 1e6 << " M particle-steps/s in turn: cell / pile "
              << c.cell.medianRate() / c.pile.medianRate();
    if (threads == 1) std::cout << " (by CPU time: " << c.cell.medianCpuRate() / c.pile.medianCpuRate() << ")";
    std::cout << "\n";
  }
  // Each contact path on the same settled piles in one process, repeats in alternation: the
  // ratio is what the wide path is worth, whatever else the machine is doing.
  if (hasWidePath()) {
    for (size_t k : {size_t{0}, size_t{2}, size_t{3}, size_t{4}}) {
      if (!only.empty() && scenes[k].name != only) continue;
      const bench::PathSpeeds p = bench::measurePathSpeeds(scenes[k], steps, repeats, threads, &std::cerr);
      overrideSimdPath(SimdPath::Wide);
      const std::string target = simdTargetName();
      overrideSimdPath(std::nullopt);
      std::cout << "paths " << std::setw(18) << scenes[k].name << "wide (" << target << ") "
                << std::setprecision(4) << p.wide.medianRate() / 1e6 << " M, baseline "
                << p.baseline.medianRate() / 1e6 << " M particle-steps/s: wide/baseline "
                << p.wide.medianRate() / p.baseline.medianRate();
      if (threads == 1) {  // by the stepping thread's CPU time, which other programs move far less
        std::cout << "; per CPU-second " << p.wide.medianCpuRate() / 1e6 << " M, " << p.baseline.medianCpuRate() / 1e6
                  << " M: wide/baseline " << p.wide.medianCpuRate() / p.baseline.medianCpuRate();
      }
      std::cout << "\n";
    }
  }
  return 0;
}

}  // namespace grainlab
