#include "grainlab/lammps/export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "grainlab/lammps/cell_deformation.hpp"
#include "grainlab/lammps/granular_parameters.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/output_writer.hpp"

namespace grainlab::lammps {
namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// For messages: as the user would write it.
std::string shortNum(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

// One axis of the box: a wall at each end or none.
struct Side {
  std::optional<double> wall;  // m
};

struct Box {
  double xlo = 0, xhi = 0, ylo = 0, yhi = 0;
  std::string boundary;  // LAMMPS `boundary` letters for x and y
  // Walls kept as fix wall/gran (wall mode): the planes of each axis, "NULL" where none.
  std::string xplane, yplane;
};

void refuseUnfaithful(const Scene& scene, const StartingSpecimen& s, const ExportOptions& options) {
  int polygons = 0, clumps = 0, boundary = 0, held = 0;
  for (std::size_t k = 0; k < s.shapes.size(); ++k) {
    polygons += s.shapes[k] == ShapeKind::Polygon;
    clumps += s.shapes[k] == ShapeKind::Clump;
    boundary += s.boundary[k] != 0;
    held += s.motions[k] != Motion::Dynamic && !s.boundary[k];
  }
  if (scene.boundary.type == BoundarySpec::Type::Membrane || boundary > 0)
    throw ExportRefused("the membrane ring and its pressure servo (boundary.type \"membrane\", " +
                        std::to_string(boundary) + " ring particles) have no LAMMPS equivalent");
  // A scene's own cell is exported with its stages (cell_deformation.hpp); --periodic and
  // --deform make a cell of four walls.
  const bool cell = scene.boundary.type == BoundarySpec::Type::Periodic;
  if (cell && (options.periodic || options.deform))
    throw ExportRefused(std::string(options.deform ? "--deform" : "--periodic") +
                        " with a periodic cell (boundary.type \"periodic\"): the cell and its stages are exported as they are");
  if (polygons > 0)
    throw ExportRefused(std::to_string(polygons) +
                        " polygon particles: pair_style gran/hooke/history has discs only");
  if (clumps > 0)
    throw ExportRefused(std::to_string(clumps) +
                        " clump particles: the export writes single discs, not rigid bodies of several");
  if (held > 0)
    throw ExportRefused(std::to_string(held) + " fixed or kinematic particles (particles[].motion)");
  if (s.material.rollingFriction > 0)
    throw ExportRefused("material.rolling_friction = " + shortNum(s.material.rollingFriction) +
                        ": pair_style gran/hooke/history has no rolling resistance");
  if (s.material.localDamping > 0 && !options.withoutLocalDamping)
    throw ExportRefused("material.local_damping = " + shortNum(s.material.localDamping) +
                        ": LAMMPS has no Cundall local damping (--without-local-damping exports without it)");
  if (!options.steps && !cell) {
    for (std::size_t k = s.firstStage; k < scene.stages.size(); ++k) {
      const StageSpec& stage = scene.stages[k];
      if (stage.type != StageSpec::Type::Free)
        throw ExportRefused("stage \"" + stage.name + "\" (" + std::string(toString(stage.type)) +
                            ") is driven by a boundary servo; only free stages are exported (or give --steps)");
      if (stage.friction)
        throw ExportRefused("stage \"" + stage.name + "\" overrides the friction; LAMMPS keeps one pair_style");
    }
  }
  if (options.deform && !options.periodic)
    throw ExportRefused("--deform needs a periodic cell (--periodic): fix wall/gran planes do not follow the box");
}

Box boxOf(const StartingSpecimen& s, bool periodic) {
  if (s.cell) return {0, (*s.cell)(0, 0), 0, (*s.cell)(1, 1), "p p", "", ""};
  Side left, right, floor, top;
  for (std::size_t k = 0; k < s.walls.size(); ++k) {
    const Wall& w = s.walls[k];
    const Vec2 n = w.normal;
    auto& side = n.x() == 1 && n.y() == 0    ? left
                 : n.x() == -1 && n.y() == 0 ? right
                 : n.x() == 0 && n.y() == 1  ? floor
                 : n.x() == 0 && n.y() == -1 ? top
                                             : throw ExportRefused("wall " + std::to_string(k) + " (normal " +
                                                                   shortNum(n.x()) + ", " + shortNum(n.y()) +
                                                                   ") is not axis-aligned: fix wall/gran takes x and y planes only");
    if (side.wall) throw ExportRefused("two walls face the same way (wall " + std::to_string(k) + ")");
    side.wall = (n.x() != 0) ? w.point.x() : w.point.y();
  }
  double minX = std::numeric_limits<double>::infinity(), maxX = -minX, minY = minX, maxY = -minX, rMax = 0;
  for (std::size_t k = 0; k < s.positions.size(); ++k) {
    minX = std::min(minX, s.positions[k].x() - s.radii[k]);
    maxX = std::max(maxX, s.positions[k].x() + s.radii[k]);
    minY = std::min(minY, s.positions[k].y() - s.radii[k]);
    maxY = std::max(maxY, s.positions[k].y() + s.radii[k]);
    rMax = std::max(rMax, s.radii[k]);
  }
  Box b;
  if (periodic) {
    if (!left.wall || !right.wall || !floor.wall || !top.wall)
      throw ExportRefused("--periodic needs four walls (left, right, floor, top) whose rectangle becomes the cell");
    b = {*left.wall, *right.wall, *floor.wall, *top.wall, "p p", "", ""};
    return b;
  }
  // A side without a wall is shrink-wrapped ('m') from the particles' extent.
  const double margin = rMax;
  b.xlo = left.wall.value_or(minX - margin);
  b.xhi = right.wall.value_or(maxX + margin);
  b.ylo = floor.wall.value_or(minY - margin);
  b.yhi = top.wall.value_or(maxY + margin);
  auto letters = [](const Side& lo, const Side& hi) {
    const std::string a = lo.wall ? "f" : "m", c = hi.wall ? "f" : "m";
    return a == c ? a : a + c;
  };
  b.boundary = letters(left, right) + " " + letters(floor, top);
  auto plane = [](const Side& lo, const Side& hi) -> std::string {
    if (!lo.wall && !hi.wall) return "";
    return (lo.wall ? num(*lo.wall) : "NULL") + " " + (hi.wall ? num(*hi.wall) : "NULL");
  };
  b.xplane = plane(left, right);
  b.yplane = plane(floor, top);
  return b;
}

}  // namespace

ExportSummary exportLammps(const Scene& scene, const StartingSpecimen& s, const ExportOptions& options,
                           const std::string& directory) {
  refuseUnfaithful(scene, s, options);
  const Box box = boxOf(s, options.periodic);
  const int n = static_cast<int>(s.positions.size());
  if (n == 0) throw ExportRefused("the scene has no particles");

  const double dt = s.timestep;
  long steps = 0;
  const bool cell = s.cell.has_value();
  std::vector<CellRun> cellStages;
  if (cell) {
    cellStages = cellRuns(scene, s);
    for (const CellRun& r : cellStages) steps += r.steps;
  }
  // A cell's run is cut at --steps; walls run --steps in place of the scene's stages.
  if (options.steps && cell) {
    steps = std::min(steps, *options.steps);
  } else if (options.steps) {
    steps = *options.steps;
  } else if (!cell) {
    for (std::size_t k = s.firstStage; k < scene.stages.size(); ++k)
      steps += std::lround(scene.stages[k].duration / dt);
  }
  if (steps <= 0) throw ExportRefused("nothing to run: no free stage is left (give --steps N)");
  const long every = options.dumpEvery.value_or(std::max(1L, steps / 100));
  if (every <= 0) throw ExportRefused("--dump-every must be at least 1");

  double totalMass = 0, sumRadius = 0;
  for (int k = 0; k < n; ++k) {
    totalMass += s.masses[k];
    sumRadius += s.radii[k];
  }
  const double meanMass = totalMass / n, meanRadius = sumRadius / n;
  // The mean pair (m* = m̄/2) and the mean disc on a wall (m* = m̄): exact for equal discs.
  // The friction the exported stages run with: the scene's. A specimen prepared by a stage with
  // its own friction (a frictionless consolidation) still carries that stage's value.
  Material material = s.material;
  material.friction = scene.material.friction;
  const GranularParameters g = granularParameters(material, 0.5 * meanMass, meanMass);
  const bool triclinic = cell || (options.deform && (*options.deform)[2] != 0);
  // The cell's velocity gradient (diagonal) and the point it deforms about: LAMMPS's fix deform
  // keeps the box's centre (xlo + lx/2, ylo + ly/2) fixed, so the streaming velocity of a
  // point x is L (x − c), and remap v carries it across the edges.
  const double rate11 = cellStages.empty() ? 0 : cellStages.front().rate11;
  const double rate22 = cellStages.empty() ? 0 : cellStages.front().rate22;
  const Vec2 centre = cell ? Vec2(0.5 * (*s.cell)(0, 0), 0.5 * (*s.cell)(1, 1)) : Vec2(0, 0);
  std::optional<PeriodicCell> periodicCell;
  if (cell) periodicCell.emplace(*s.cell);
  auto position = [&](int k) { return periodicCell ? periodicCell->wrap(s.positions[k]) : s.positions[k]; };

  // ---- specimen.data ----
  std::ostringstream data;
  data << "grainlab specimen for LAMMPS (" << options.origin << "): " << n << " discs\n\n"
       << n << " atoms\n1 atom types\n\n"
       << num(box.xlo) << " " << num(box.xhi) << " xlo xhi\n"
       << num(box.ylo) << " " << num(box.yhi) << " ylo yhi\n"
       << "-0.5 0.5 zlo zhi\n";
  if (triclinic) data << num(cell ? (*s.cell)(0, 1) : 0.0) << " 0 0 xy xz yz\n";
  data << "\nAtoms # sphere\n\n";
  for (int k = 0; k < n; ++k) {
    // This LAMMPS (Debian's, 7 Jan 2022) makes the mass 4/3 π r³ ρ even in 2D: the density
    // column is chosen so that it equals grainlab's disc mass ρ π r² per metre.
    const double r = s.radii[k];
    const double density = s.masses[k] / (4.0 / 3.0 * kPi * r * r * r);
    const Vec2 x = position(k);
    data << k + 1 << " 1 " << num(2 * r) << " " << num(density) << " " << num(x.x()) << " " << num(x.y()) << " 0\n";
  }
  data << "\nVelocities\n\n";
  for (int k = 0; k < n; ++k) {
    // grainlab keeps the fluctuation; LAMMPS (remap v) the whole velocity, streaming included.
    const Vec2 x = position(k) - centre;
    const Vec2 v = s.velocities[k] + Vec2(rate11 * x.x(), rate22 * x.y());
    data << k + 1 << " " << num(v.x()) << " " << num(v.y()) << " 0 0 0 " << num(s.spins[k]) << "\n";
  }

  // ---- in.grainlab ----
  std::ostringstream in;
  in << "# LAMMPS input written by grainlab export lammps (" << options.origin << ").\n"
     << "# " << n << " discs, " << steps << " steps of " << num(dt) << " s, dumps every " << every << " steps.\n"
     << "# Run in this folder:  mpirun -np 4 lmp -in in.grainlab -log log.lammps\n"
     << "# Then:                grainlab import lammps particles.dump contacts.dump --out RUN_DIR\n"
     << "# The material mapping is in docs/lammps.md of grainlab's repository.\n"
     << (s.material.localDamping > 0 ? "# Exported WITHOUT grainlab's local damping (--without-local-damping).\n" : "")
     << "units           si\n"
     << "dimension       2\n"
     << "atom_style      sphere\n"
     << "atom_modify     map array\n"
     << "boundary        " << box.boundary << " p\n"
     << "newton          off\n"
     << "comm_modify     vel yes\n"
     << "read_data       specimen.data\n"
     << "# Verlet skin: 0.3 x the mean radius (grainlab's in a periodic cell), rebuilt when needed.\n"
     << "neighbor        " << num(0.3 * meanRadius) << " bin\n"
     << "neigh_modify    delay 0 every 1 check yes\n"
     << "# kn kt gamman gammat xmu dampflag: grainlab's k_n, k_t, damping for the mean pair, mu.\n"
     << "pair_style      gran/hooke/history " << num(g.kn) << " " << num(g.kt) << " " << num(g.gammaN) << " "
     << num(g.gammaT) << " " << num(g.friction) << " 1\n"
     << "pair_coeff      * *\n";
  if (!box.xplane.empty())
    in << "fix             xwalls all wall/gran hooke/history " << num(g.kn) << " " << num(g.kt) << " "
       << num(g.gammaNWall) << " " << num(g.gammaTWall) << " " << num(g.friction) << " 1 xplane " << box.xplane << "\n";
  if (!box.yplane.empty())
    in << "fix             ywalls all wall/gran hooke/history " << num(g.kn) << " " << num(g.kt) << " "
       << num(g.gammaNWall) << " " << num(g.gammaTWall) << " " << num(g.friction) << " 1 yplane " << box.yplane << "\n";
  const double gMag = scene.gravity.norm();
  if (gMag > 0)
    in << "fix             gravity all gravity " << num(gMag) << " vector " << num(scene.gravity.x() / gMag) << " "
       << num(scene.gravity.y() / gMag) << " 0\n";
  in << "fix             integrate all nve/sphere disc\n"
     << "fix             plane all enforce2d\n";
  if (cell && (rate11 != 0 || rate22 != 0)) {
    // grainlab's cell follows ḣ = L h (exponential stretches): LAMMPS's trate, the tilt at
    // L11 as ḣ12 = L11 h12. remap v, as grainlab: the contact sees the whole relative velocity,
    // the images' affine velocity included (docs/periodic-cell.md, "Against LAMMPS").
    in << "# The scene's constant-volume biaxial stage: L = diag(" << num(rate11) << ", " << num(rate22)
       << ") 1/s, true strain rates.\n"
       << "fix             deform all deform 1 x trate " << num(rate11) << " y trate " << num(rate22);
    // LAMMPS refuses trate on a zero tilt (which stays zero: ḣ12 = L11 h12).
    if ((*s.cell)(0, 1) != 0) in << " xy trate " << num(rate11);
    in << " remap v\n";
  }
  if (options.deform) {
    const auto& d = *options.deform;
    in << "# Strain-controlled deformation of the periodic cell (rates in 1/s, extension positive).\n"
       << "fix             deform all deform 1 x erate " << num(d[0]) << " y erate " << num(d[1]);
    if (triclinic) in << " xy erate " << num(d[2]);
    // remap v: positions are not moved after the forces are computed, so the dumped contacts
    // are the ones the forces (and LAMMPS's virial) were computed on; particles crossing a
    // boundary take the cell's velocity jump (Lees-Edwards).
    in << " remap v\n";
  }
  in << "timestep        " << num(dt) << "\n"
     << "# The contacts: touching pairs only (cutoff radius), both computes over the same pairs.\n"
     << "compute         pairs all pair/local dist fx fy p1 p2 cutoff radius\n"
     << "compute         ends all property/local patom1 patom2 cutoff radius\n"
     << "dump            particles all custom " << every << " particles.dump id type x y vx vy omegaz radius\n"
     << "dump_modify     particles format float %.17g sort id\n"
     << "dump            contacts all local " << every
     << " contacts.dump c_ends[1] c_ends[2] c_pairs[1] c_pairs[2] c_pairs[3] c_pairs[4] c_pairs[5]\n"
     << "dump_modify     contacts format float %.17g\n"
     << "# LAMMPS's own contact stress (pair virial over the cell's area, compression positive),\n"
     << "# to check grainlab's import against: pxx = sigma11, pyy = sigma22, pxy = sigma21.\n"
     << "compute         stress all pressure NULL pair\n"
     << "thermo_style    custom step time c_stress[1] c_stress[2] c_stress[4]\n"
     << "thermo_modify   format float %.17g norm no lost error\n"
     << "thermo          " << every << "\n"
     << "run             " << steps << "\n";

  // ---- export.json ----
  nlohmann::json meta = {
      {"origin", options.origin},
      {"particles", n},
      {"timestep_s", dt},
      {"steps", steps},
      {"dump_every", every},
      {"boundary", cell ? "cell" : options.periodic ? "periodic" : "walls"},
      {"start_time_s", s.time},
      {"pair_style", {{"kn", g.kn}, {"kt", g.kt}, {"gamman", g.gammaN}, {"gammat", g.gammaT}, {"xmu", g.friction},
                      {"dampflag", 1}}},
      {"wall", {{"gamman", g.gammaNWall}, {"gammat", g.gammaTWall}}},
      {"damping_exact_for", {{"pair_effective_mass", 0.5 * meanMass}, {"wall_particle_mass", meanMass}}},
      {"material", {{"density", s.material.density}, {"normal_stiffness", s.material.normalStiffness},
                    {"tangential_stiffness", s.material.tangentialStiffness}, {"friction", material.friction},
                    {"restitution", s.material.restitution}, {"local_damping", s.material.localDamping}}}};
  if (options.deform) meta["deform_erate"] = *options.deform;
  if (cell) {
    meta["cell_h"] = {{(*s.cell)(0, 0), (*s.cell)(0, 1)}, {(*s.cell)(1, 0), (*s.cell)(1, 1)}};
    meta["deform_trate"] = {rate11, rate22};
  }

  std::filesystem::create_directories(directory);
  const std::filesystem::path dir(directory);
  writeFileAtomically((dir / "specimen.data").string(), data.str());
  writeFileAtomically((dir / "in.grainlab").string(), in.str());
  writeFileAtomically((dir / "export.json").string(), meta.dump(2) + "\n");
  return {n, steps, every, dt, options.periodic || cell};
}

}  // namespace grainlab::lammps
