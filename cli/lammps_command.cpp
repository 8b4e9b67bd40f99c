#include "lammps_command.hpp"

#include <charconv>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "grainlab/errors.hpp"
#include "grainlab/lammps/export.hpp"
#include "grainlab/lammps/import.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/starting_specimen.hpp"
#ifdef GRAINLAB_HAS_SERVER
#include "grainlab/server/lammps_import.hpp"
#endif

namespace grainlab {
namespace {

// --from DIR[:STAGE], as `grainlab run` reads it: the stage follows the last ':' when what
// follows it names no folder.
nlohmann::json startFromArgument(const std::string& from) {
  const size_t colon = from.rfind(':');
  if (colon == std::string::npos || from.find('/', colon) != std::string::npos) return {{"run", from}};
  return {{"run", from.substr(0, colon)}, {"stage", from.substr(colon + 1)}};
}

bool parseNumber(const std::string& text, double& v) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

bool parseCount(const std::string& text, long& v) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  return r.ec == std::errc() && r.ptr == text.data() + text.size() && v > 0;
}

}  // namespace

int exportLammpsCommand(const std::vector<std::string>& args) {
  std::string scenePath, preset, from, out;
  lammps::ExportOptions options;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool hasValue = k + 1 < args.size();
    if (args[k] == "--out" && hasValue) out = args[++k];
    else if (args[k] == "--preset" && hasValue) preset = args[++k];
    else if (args[k] == "--from" && hasValue) from = args[++k];
    else if (args[k] == "--periodic") options.periodic = true;
    else if (args[k] == "--without-local-damping") options.withoutLocalDamping = true;
    else if (args[k] == "--steps" && hasValue) {
      long n = 0;
      if (!parseCount(args[++k], n)) {
        std::cerr << "grainlab export lammps: --steps needs a positive whole number, not " << args[k] << "\n";
        return 2;
      }
      options.steps = n;
    } else if (args[k] == "--dump-every" && hasValue) {
      long n = 0;
      if (!parseCount(args[++k], n)) {
        std::cerr << "grainlab export lammps: --dump-every needs a positive whole number, not " << args[k] << "\n";
        return 2;
      }
      options.dumpEvery = n;
    } else if (args[k] == "--deform" && hasValue) {
      std::array<double, 3> rates{0, 0, 0};
      std::stringstream in(args[++k]);
      std::string item;
      int count = 0;
      bool ok = true;
      while (std::getline(in, item, ',')) ok = ok && count < 3 && parseNumber(item, rates[static_cast<size_t>(count++)]);
      if (!ok || count < 2) {
        std::cerr << "grainlab export lammps: --deform needs EXX,EYY[,GXY] in 1/s, not " << args[k] << "\n";
        return 2;
      }
      options.deform = rates;
    } else if (!args[k].empty() && args[k][0] != '-' && scenePath.empty()) scenePath = args[k];
    else {
      std::cerr << "grainlab export lammps: unexpected argument " << args[k] << " (grainlab help lists the options)\n";
      return 2;
    }
  }
  if (out.empty() || scenePath.empty() == preset.empty()) {
    std::cerr << "grainlab export lammps: give a SCENE.json or --preset NAME (with --from DIR[:STAGE] to start "
                 "from a prepared specimen), and --out DIR\n";
    return 2;
  }
  nlohmann::json json = preset.empty() ? loadSceneJson(scenePath) : presetScene(preset);
  if (!from.empty() && json.is_object()) json["start_from"] = startFromArgument(from);
  const Scene scene = parseScene(json);
  options.origin = (preset.empty() ? scenePath : "--preset " + preset) + (from.empty() ? "" : " --from " + from);
  try {
    const StartingSpecimen specimen = startingSpecimen(scene);
    const lammps::ExportSummary s = lammps::exportLammps(scene, specimen, options, out);
    std::cout << "wrote " << out << "/specimen.data, in.grainlab, export.json: " << s.particles << " discs, "
              << s.steps << " steps of " << s.timestep << " s, " << (s.periodic ? "periodic cell" : "walls")
              << ", dumps every " << s.dumpEvery << " steps\n"
              << "run it there with: mpirun -np 2 lmp -in in.grainlab -log log.lammps\n";
  } catch (const lammps::ExportRefused& e) {
    std::cerr << "grainlab export lammps: not exported: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

int importLammpsCommand(const std::vector<std::string>& args) {
  std::vector<std::string> dumps;
  std::string out, db, name;
  lammps::ImportOptions options;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool hasValue = k + 1 < args.size();
    if (args[k] == "--out" && hasValue) out = args[++k];
    else if (args[k] == "--db" && hasValue) db = args[++k];
    else if (args[k] == "--name" && hasValue) name = args[++k];
    else if (args[k] == "--timestep" && hasValue) {
      double dt = 0;
      if (!parseNumber(args[++k], dt) || !(dt > 0)) {
        std::cerr << "grainlab import lammps: --timestep needs a positive number of seconds, not " << args[k] << "\n";
        return 2;
      }
      options.timestep = dt;
    } else if (args[k] == "--frames-every" && hasValue) {
      long n = 0;
      if (args[k + 1] == "0") {
        options.framesEvery = 0;
        ++k;
      } else if (!parseCount(args[++k], n)) {
        std::cerr << "grainlab import lammps: --frames-every needs a whole number, not " << args[k] << "\n";
        return 2;
      } else {
        options.framesEvery = static_cast<int>(n);
      }
    } else if (args[k] == "--local-columns" && hasValue) {
      // ROLE=NAME,...: which dump local columns hold patom1, patom2, dist, fx, fy, p1, p2.
      std::stringstream in(args[++k]);
      std::string item;
      while (std::getline(in, item, ',')) {
        const auto eq = item.find('=');
        const std::string role = item.substr(0, eq), name = eq == std::string::npos ? "" : item.substr(eq + 1);
        std::string* slot = role == "patom1" ? &options.columns.patom1
                            : role == "patom2" ? &options.columns.patom2
                            : role == "dist"   ? &options.columns.dist
                            : role == "fx"     ? &options.columns.fx
                            : role == "fy"     ? &options.columns.fy
                            : role == "p1"     ? &options.columns.p1
                            : role == "p2"     ? &options.columns.p2
                                               : nullptr;
        if (!slot || name.empty()) {
          std::cerr << "grainlab import lammps: --local-columns takes ROLE=COLUMN items with ROLE one of patom1, "
                       "patom2, dist, fx, fy, p1, p2; not "
                    << item << "\n";
          return 2;
        }
        *slot = name;
      }
    } else if (!args[k].empty() && args[k][0] != '-') dumps.push_back(args[k]);
    else {
      std::cerr << "grainlab import lammps: unexpected argument " << args[k] << " (grainlab help lists the options)\n";
      return 2;
    }
  }
  if (out.empty() || dumps.empty()) {
    std::cerr << "grainlab import lammps: give the dumps (a dump custom and a dump local file) and --out DIR\n";
    return 2;
  }
  if (!name.empty() && db.empty()) {
    std::cerr << "grainlab import lammps: --name names the run in the database: give --db FILE too\n";
    return 2;
  }
#ifndef GRAINLAB_HAS_SERVER
  if (!db.empty()) {
    std::cerr << "grainlab import lammps: --db needs the server, and this grainlab was built without it\n";
    return 2;
  }
#endif
  try {
    lammps::ImportReport r;
    std::int64_t runId = 0;
#ifdef GRAINLAB_HAS_SERVER
    if (!db.empty()) {
      const server::LammpsRunImport stored = server::importLammpsRun(dumps, out, db, options, name);
      r = stored.report;
      runId = stored.runId;
    } else
#endif
      r = lammps::importLammps(dumps, out, options);
    if (!r.warning.empty()) std::cerr << "warning: " << r.warning << "\n";
    std::cout << "imported " << r.frames << " frames (timesteps " << r.firstTimestep << " to " << r.lastTimestep
              << ", " << r.particles << " particles) into " << out << " in " << r.seconds << " s\n";
    if (runId > 0) std::cout << "stored as run " << runId << " in " << db << " (origin lammps)\n";
  } catch (const std::invalid_argument& e) {  // --db without a clock for the rows
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const lammps::DumpError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {  // a file that cannot be read or written, a folder in the way
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace grainlab
