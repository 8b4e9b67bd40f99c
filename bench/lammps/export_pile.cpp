// Settles grainlab's benchmark pile of 2,500 discs and writes it out twice, for a run of the
// same state in grainlab and in LAMMPS (docs/benchmarks.md):
//   pile.json    a grainlab scene: the settled particles, walls, gravity, material, one free
//                stage of the requested steps at the benchmark's timestep
//   pile.data    a LAMMPS data file (atom_style sphere) with the same positions and velocities
//   pile.params  LAMMPS variable definitions (stiffnesses, dampings, friction, timestep, walls)
//                read by in.pile
// Usage: export_pile OUTDIR [STEPS]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <string>

#include <nlohmann/json.hpp>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/world.hpp"

namespace {

using grainlab::kPi;
using nlohmann::json;

/// ζ of a linear spring-dashpot whose binary collision has restitution e (the engine's law:
/// ζ = −ln e / √(π² + ln² e)); 0 for e = 1.
double dampingRatio(double e) {
  if (e >= 1) return 0;
  const double l = std::log(e);
  return -l / std::sqrt(kPi * kPi + l * l);
}

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: export_pile OUTDIR [STEPS]\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  const long steps = argc == 3 ? std::stol(argv[2]) : 20000;
  std::filesystem::create_directories(dir);

  // The pile `grainlab bench` times, settled exactly as it settles it.
  const grainlab::Scene scene = grainlab::pileScene(50, 50, false);
  grainlab::World world(scene.material);
  for (const auto& p : scene.particles) world.addParticle(p);
  for (const auto& w : scene.walls) world.addWall(w);
  world.setGravity(scene.gravity);
  const double dt = world.timestep();  // s: the default, 0.2 × critical
  const long settle = static_cast<long>(scene.stages.front().duration / dt);
  for (long k = 0; k < settle; ++k) world.step();
  world.checkHealth();
  std::vector<grainlab::ContactRecord> contacts;
  world.contacts(contacts);

  const int n = world.size();
  const auto x = world.positions();
  const auto v = world.velocities();
  const auto w = world.spins();
  const auto r = world.boundingRadii();
  const auto m = world.masses();
  const grainlab::Material& mat = scene.material;

  // ---- grainlab scene ----
  json particles = json::array();
  double top = 0, totalMass = 0, meanMass = 0;
  for (int k = 0; k < n; ++k) {
    particles.push_back({{"shape", "disc"}, {"radius", r[k]}, {"position", {x[k].x(), x[k].y()}},
                         {"velocity", {v[k].x(), v[k].y()}}, {"spin", w[k]}});
    top = std::max(top, x[k].y() + r[k]);
    totalMass += m[k];
  }
  meanMass = totalMass / n;
  json walls = json::array();
  for (const auto& wall : scene.walls) {
    walls.push_back({{"point", {wall.point.x(), wall.point.y()}}, {"normal", {wall.normal.x(), wall.normal.y()}}});
  }
  const double duration = steps * dt;
  const json grainlabScene = {
      {"name", "lammps-peer-pile"},
      {"material", {{"density", mat.density}, {"normal_stiffness", mat.normalStiffness},
                    {"tangential_stiffness", mat.tangentialStiffness}, {"friction", mat.friction},
                    {"restitution", mat.restitution}, {"local_damping", mat.localDamping}}},
      {"particles", particles},
      {"walls", walls},
      {"gravity", {scene.gravity.x(), scene.gravity.y()}},
      // The stage runs `steps` steps (plus at most one for rounding of the duration).
      {"stages", json::array({{{"type", "free"}, {"name", "timed"}, {"duration", duration * (1 - 1e-9)}}})},
      {"solver", {{"timestep", dt}}},
      // Two samples (start and end), no fabric: the timing is of the stepping.
      {"output", {{"sample_interval", duration}, {"fabric", false}, {"histograms", false}}}};
  std::ofstream(dir / "pile.json") << grainlabScene.dump(1) << "\n";

  // ---- LAMMPS data file ----
  // Walls: the floor (normal +y) and the two sides (normals ±x).
  double floorY = 0, leftX = 0, rightX = 0;
  for (const auto& wall : scene.walls) {
    if (wall.normal.y() > 0.5) floorY = wall.point.y();
    else if (wall.normal.x() > 0.5) leftX = wall.point.x();
    else if (wall.normal.x() < -0.5) rightX = wall.point.x();
  }
  const double margin = 0.002;  // m of box beyond the walls
  std::ofstream data(dir / "pile.data");
  data << "grainlab settled disc pile: " << n << " discs\n\n"
       << n << " atoms\n1 atom types\n\n"
       << number(leftX - margin) << " " << number(rightX + margin) << " xlo xhi\n"
       << number(floorY - margin) << " " << number(top + 20 * r[0]) << " ylo yhi\n"
       << "-0.001 0.001 zlo zhi\n\nAtoms # sphere\n\n";
  for (int k = 0; k < n; ++k) {
    // LAMMPS (this Debian build, 29 Sep 2021) turns the density column into a mass with the
    // sphere's 4/3 π r³ even in 2D: give it the density that makes that equal our disc's
    // ρ π r² (per metre), so the masses match to rounding. fix nve/sphere disc then uses
    // I = ½ m r², as grainlab does.
    const double lammpsDensity = m[k] / (4.0 / 3.0 * kPi * r[k] * r[k] * r[k]);
    data << k + 1 << " 1 " << number(2 * r[k]) << " " << number(lammpsDensity) << " " << number(x[k].x()) << " "
         << number(x[k].y()) << " 0\n";
  }
  data << "\nVelocities\n\n";
  for (int k = 0; k < n; ++k) {
    data << k + 1 << " " << number(v[k].x()) << " " << number(v[k].y()) << " 0 0 0 " << number(w[k]) << "\n";
  }

  // ---- LAMMPS parameters ----
  // gran/hooke/history damps with meff·γ·v, grainlab with 2ζ√(m* k)·v: the two agree for
  // the mean pair (m* = m̄/2) and, on the walls, for the mean disc (m* = m̄); a pair of
  // discs ±10% in size differs by at most ±10% in damping force (docs/benchmarks.md).
  const double zeta = dampingRatio(mat.restitution);
  const double pairMass = 0.5 * meanMass, wallMass = meanMass;
  std::ofstream params(dir / "pile.params");
  params << "# written by export_pile from grainlab's pileScene(50, 50, discs)\n"
         << "variable kn equal " << number(mat.normalStiffness) << "\n"
         << "variable kt equal " << number(mat.tangentialStiffness) << "\n"
         << "variable gamman equal " << number(2 * zeta * std::sqrt(mat.normalStiffness / pairMass)) << "\n"
         << "variable gammat equal " << number(2 * zeta * std::sqrt(mat.tangentialStiffness / pairMass)) << "\n"
         << "variable gamman_wall equal " << number(2 * zeta * std::sqrt(mat.normalStiffness / wallMass)) << "\n"
         << "variable gammat_wall equal " << number(2 * zeta * std::sqrt(mat.tangentialStiffness / wallMass)) << "\n"
         << "variable xmu equal " << number(mat.friction) << "\n"
         << "variable dt equal " << number(dt) << "\n"
         << "variable g equal " << number(-scene.gravity.y()) << "\n"
         << "variable floor equal " << number(floorY) << "\n"
         << "variable left equal " << number(leftX) << "\n"
         << "variable right equal " << number(rightX) << "\n"
         << "variable skin equal "
         << number(grainlab::WorldSettings{}.skinFraction * (std::accumulate(r.begin(), r.end(), 0.0) / n)) << "\n"
         << "variable steps equal " << steps << "\n"
         << "variable expected_mass equal " << number(totalMass) << "\n";

  std::cout << "particles " << n << "\ntimestep_s " << number(dt) << "\nsettle_steps " << settle << "\ncontacts "
            << contacts.size() << "\ntotal_mass_kg_per_m " << number(totalMass) << "\n";
  return 0;
}
