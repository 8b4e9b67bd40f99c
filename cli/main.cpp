// build/grainlab: the command line of contracts.md.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "check_command.hpp"
#include "columns_command.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/run_output.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"
#include "bench_command.hpp"
#include "lammps_command.hpp"
#include "run_command.hpp"
#include "scene_keys_command.hpp"
#include "paper_command.hpp"
#include "sweep_command.hpp"
#include "shapes_command.hpp"
#include "boundaries_command.hpp"
#include "tradeoff_command.hpp"
#ifdef GRAINLAB_HAS_SERVER
#include "grainlab/server/import.hpp"
#include "grainlab/server/serve.hpp"
#endif

namespace {

int usage(std::ostream& out, int code) {
  out << "usage: grainlab <command> [options]\n"
         "commands:\n"
         "  run SCENE.json --out DIR     run a scene headless (progress on stderr)\n"
         "  run --preset NAME --out DIR  run a preset\n"
         "      [--vtk]                  also write ParaView frames to DIR/vtk (output.vtk)\n"
         "      [--force]                run even if the estimate says it takes more than 30 days\n"
         "      [--from RUN_DIR[:STAGE]]  start from the specimen another run kept at the end of STAGE\n"
         "                               (default: the stage before the first shearing stage); the\n"
         "                               scene's stages up to it are skipped (start_from in the scene)\n"
         "                               a checkpoint is kept in DIR every output.checkpoint_every_s\n"
         "                               (60 s) and on SIGINT/SIGTERM, which stop the run resumably\n"
         "  resume DIR                   continue an interrupted run from DIR's checkpoint; its\n"
         "                               outputs end as the uninterrupted run's would\n"
         "  presets                      list the presets\n"
         "  columns [--json|--markdown]  series.csv's columns: name, unit, meaning\n"
         "  scene-keys [--json|--markdown]  every scene key the parser accepts: kind, default, range\n"
         "  check SCENE.json | --preset NAME\n"
         "                               validate a scene and estimate its run (nothing is written)\n"
         "  preset NAME                  print a preset as scene JSON\n"
         "  bench [--steps N] [--repeats N] [--threads N] [--scene NAME]\n"
         "                               speed on settled piles of discs and polygons\n"
         "  paper --out DIR [--quick] [--seeds N] [--jobs N] [--report-only]\n"
         "                               the paper's six tests (N seeds each; also under mpirun), report.html\n"
         "  sweep SPEC.json --out DIR [--jobs N]  every run of a parameter sweep (also under mpirun)\n"
         "  tradeoff --out DIR [--quick] [--jobs N]  speed against accuracy: tradeoff.csv, pareto.svg\n"         "      [--seeds N]              N seeds per setting, paired on specimens prepared once:\n"
         "                               each setting's bias with its 95% interval and a verdict\n"
         "      [--presets A,B] [--axes A,B]  other presets; only some axes (e.g. inertial_number)\n"
         "  shapes --out DIR [--full] [--seeds N] [--jobs N] [--representations A,B] [--assemblies A,B]\n"
         "                               shape fidelity: clumps-N, rolling-MU, discs against the hexagons,\n"
         "                               N seeds each: shapes.csv, calibration.csv, shapes.svg (resumes)\n"
         "  boundaries --out DIR [--full] [--seeds N] [--jobs N] [--boundaries A,B] [--assemblies A,B]\n"
         "             [--axial-strain E]  the ring and the periodic cell (cell, cell-matched) side by side,\n"
         "                               N seeds each: boundaries.csv, curves.csv, curves.svg (resumes)\n"
#ifdef GRAINLAB_HAS_SERVER
         "  serve [--host H] [--port P] [--db FILE] [--web DIR]\n"
         "        [--max-concurrent N] [--max-queued N] [--max-particles N] [--max-body BYTES]\n"
         "        [--max-run-seconds S]   refuse scenes estimated to run longer, stop runs that do (default 86400)\n"
         "        [--resume-interrupted]  resume the runs a stopped or killed server left interrupted\n"
         "        [--token-file FILE] [--read-only-token-file FILE]  (or GRAINLAB_TOKEN, GRAINLAB_READ_ONLY_TOKEN)\n"
         "        [--allowed-hosts H1,H2] [--allowed-origins O1,O2] [--import-root DIR]\n"
         "                               the HTTP/WebSocket server and dashboard (docs/security.md)\n"
         "  import DIR [--db FILE]       a sweep folder's runs into the server's database\n"
#endif
         "  export lammps (SCENE.json | --preset NAME) [--from RUN_DIR[:STAGE]] --out DIR\n"
         "        [--periodic] [--deform EXX,EYY[,GXY]] [--steps N] [--dump-every N] [--without-local-damping]\n"
         "                               a disc specimen and its run as a LAMMPS data file and input script\n"
         "  import lammps DUMPS... --out DIR [--timestep S] [--frames-every N] [--local-columns ROLE=COL,...]\n"
         "        [--db FILE [--name NAME]]\n"
         "                               a LAMMPS run's dump custom and dump local frames into grainlab's outputs\n"
         "                               (and, with --db, into the server's database as a run of origin lammps)\n"
         "  help                         this text\n";
  return code;
}

#ifdef GRAINLAB_HAS_SERVER
std::vector<std::string> commaList(const std::string& text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto comma = std::min(text.find(',', start), text.size());
    if (comma > start) items.push_back(text.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

int serveCommand(const std::vector<std::string>& args) {
  grainlab::server::ServeOptions options;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool hasValue = k + 1 < args.size();
    if (args[k] == "--host" && hasValue) options.host = args[++k];
    else if (args[k] == "--port" && hasValue) options.port = static_cast<unsigned short>(std::stoi(args[++k]));
    else if (args[k] == "--db" && hasValue) options.db = args[++k];
    else if (args[k] == "--web" && hasValue) options.webRoot = args[++k];
    else if (args[k] == "--max-concurrent" && hasValue) options.maxConcurrentRuns = std::stoi(args[++k]);
    else if (args[k] == "--max-queued" && hasValue) options.maxQueuedRuns = std::stoi(args[++k]);
    else if (args[k] == "--max-particles" && hasValue) options.maxParticles = std::stoi(args[++k]);
    else if (args[k] == "--max-run-seconds" && hasValue) options.maxRunSeconds = std::stod(args[++k]);
    else if (args[k] == "--resume-interrupted") options.resumeInterrupted = true;
    else if (args[k] == "--max-body" && hasValue) options.maxBodyBytes = std::stoul(args[++k]);
    else if (args[k] == "--token-file" && hasValue) options.tokenFile = args[++k];
    else if (args[k] == "--read-only-token-file" && hasValue) options.readOnlyTokenFile = args[++k];
    else if (args[k] == "--allowed-hosts" && hasValue) options.allowedHosts = commaList(args[++k]);
    else if (args[k] == "--allowed-origins" && hasValue) options.allowedOrigins = commaList(args[++k]);
    else if (args[k] == "--import-root" && hasValue) options.importRoot = args[++k];
    else if (args[k] == "--token" || args[k] == "--read-only-token") {
      // Every user of the machine sees a command line (ps); a file or the environment they do not.
      std::cerr << "grainlab serve: " << args[k] << " is not taken on the command line, where other users see it; "
                << "use " << args[k] << "-file FILE or the environment variable "
                << (args[k] == "--token" ? "GRAINLAB_TOKEN" : "GRAINLAB_READ_ONLY_TOKEN") << "\n";
      return 2;
    }
    else {
      std::cerr << "grainlab serve: unexpected argument " << args[k] << "\n";
      return usage(std::cerr, 2);
    }
  }
  return grainlab::server::serve(options);
}

int importCommand(const std::vector<std::string>& args) {
  std::string dir, db = grainlab::server::ServeOptions().db;
  for (size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "--db" && k + 1 < args.size()) db = args[++k];
    else if (!args[k].empty() && args[k][0] != '-' && dir.empty()) dir = args[k];
    else {
      std::cerr << "grainlab import: unexpected argument " << args[k] << "\n";
      return usage(std::cerr, 2);
    }
  }
  if (dir.empty()) {
    std::cerr << "grainlab import: give the sweep folder (grainlab sweep's --out DIR)\n";
    return 2;
  }
  try {
    const grainlab::server::ImportReport r = grainlab::server::importSweepFolder(dir, db);
    std::cout << "imported " << r.imported << " runs into " << db;
    if (r.alreadyThere) std::cout << "; " << r.alreadyThere << " were there already";
    if (r.notFinished) std::cout << "; " << r.notFinished << " have not run yet (run the sweep again to finish them)";
    std::cout << "\n";
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
}
#endif

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage(std::cerr, 2);
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "run") return grainlab::runCommand(args);
    if (command == "export" && !args.empty() && args[0] == "lammps")
      return grainlab::exportLammpsCommand({args.begin() + 1, args.end()});
    if (command == "import" && !args.empty() && args[0] == "lammps")
      return grainlab::importLammpsCommand({args.begin() + 1, args.end()});
    if (command == "resume") return grainlab::resumeCommand(args);
    if (command == "columns") return grainlab::columnsCommand(args);
    if (command == "scene-keys") return grainlab::sceneKeysCommand(args);
    if (command == "check") return grainlab::checkCommand(args);
    if (command == "presets") {
      for (const std::string& name : grainlab::presetNames()) std::cout << name << "\n";
      return 0;
    }
    if (command == "preset") {
      if (args.size() != 1) return usage(std::cerr, 2);
      std::cout << grainlab::presetScene(args[0]).dump(2) << "\n";
      return 0;
    }
    if (command == "bench") return grainlab::benchCommand(args);
    if (command == "paper") return grainlab::paperCommand(args);
    if (command == "tradeoff") return grainlab::tradeoffCommand(args);
    if (command == "shapes") return grainlab::shapesCommand(args);
    if (command == "boundaries") return grainlab::boundariesCommand(args);
    if (command == "sweep") return grainlab::sweepCommand(args);
#ifdef GRAINLAB_HAS_SERVER
    if (command == "serve") return serveCommand(args);
    if (command == "import") return importCommand(args);
#endif
    if (command == "help" || command == "--help" || command == "-h") return usage(std::cout, 0);
  } catch (const grainlab::SceneError& e) {
    std::cerr << "error: " << e.field() << ": " << e.reason() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "grainlab: unknown command " << command << "\n";
  return usage(std::cerr, 2);
}
