// grainlab's own analysis of a scene's packing as it stands before the first step, for the
// LAMMPS round trip (round_trip.sh): the engine's contacts between particles (the walls'
// contacts left out, as LAMMPS's pair/local has none), measured by measureFabric and
// contactStress over the area of the walls' rectangle. Prints NAME VALUE lines (%.17g).
// Usage: lammps_fabric_reference SCENE.json
#include <cstdio>
#include <iostream>
#include <limits>
#include <vector>

#include "grainlab/analysis/fabric.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: lammps_fabric_reference SCENE.json\n";
    return 2;
  }
  const grainlab::Scene scene = grainlab::loadSceneFile(argv[1]);
  grainlab::World world(scene.material);
  for (const auto& p : scene.particles) world.addParticle(p);
  for (const auto& w : scene.walls) world.addWall(w);
  world.initialize();
  std::vector<grainlab::ContactRecord> all, pairs;
  world.contacts(all);
  for (const auto& c : all)
    if (!c.isWall()) pairs.push_back(c);
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const auto& w : scene.walls) {
    if (w.normal.x() != 0) xlo = std::min(xlo, w.point.x()), xhi = std::max(xhi, w.point.x());
    else ylo = std::min(ylo, w.point.y()), yhi = std::max(yhi, w.point.y());
  }
  const std::vector<unsigned char> inside(static_cast<size_t>(world.size()), 1);
  const auto f = grainlab::analysis::measureFabric(pairs, world.positions(), inside);
  const auto s = grainlab::contactStress(pairs, world.positions(), inside, (xhi - xlo) * (yhi - ylo));
  const auto print = [](const char* name, double v) { std::printf("%s %.17g\n", name, v); };
  print("contacts", static_cast<double>(pairs.size()));
  print("a_c", f.a_c);
  print("theta_c_deg", f.theta_c_deg);
  print("a_n", f.a_n);
  print("theta_n_deg", f.theta_n_deg);
  print("a_t", f.a_t);
  print("a_w", f.a_w);
  print("a_ln", f.a_ln);
  print("theta_ln_deg", f.theta_ln_deg);
  print("a_lt", f.a_lt);
  print("f0", f.f0);
  print("l0", f.l0);
  print("sigma11", s.s11);
  print("sigma22", s.s22);
  print("sigma12", s.s12);
  print("sigma21", s.s21);
  return 0;
}
