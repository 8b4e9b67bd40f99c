#include "run_command.hpp"

#include <csignal>
#include <filesystem>
#include <iostream>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/run_output.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

// SIGINT or SIGTERM asks the run to stop at its next checkpoint (a clean stop); a second
// one ends the program at once, as it would have without this handler.
volatile std::sig_atomic_t stopSignals = 0;
extern "C" void onStopSignal(int signal) {
  stopSignals = stopSignals + 1;  // ++ on a volatile is deprecated in C++20
  if (stopSignals > 1) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}

// The CLI's files, plus the stop request from a signal.
class CliRunOutput : public RunOutput {
 public:
  using RunOutput::RunOutput;
  bool stopRequested() override { return stopSignals > 0 || RunOutput::stopRequested(); }
  // Said before the run goes on, so a resume that started afresh (step 0) shows at once.
  void onResume(const Scene& scene, const World& world) override {
    RunOutput::onResume(scene, world);
    std::cerr << "resumed from step " << world.stepCount() << " at t = " << world.time() << " s\n";
  }
};

std::string checkpointPath(const std::string& dir) { return (fs::path(dir) / "checkpoint.bin").string(); }

// The exit code and last words of a finished run (also said: a checkpoint that could not be
// written, and how to continue an interrupted run).
int report(const RunSummary& summary, const RunOutput& output, const std::string& dir) {
  if (const VtkWriter* vtk = output.vtk()) {
    std::cerr << "vtk: " << vtk->frames() << " frames, " << vtk->bytesWritten() / 1e6 << " MB in " << vtk->writeSeconds()
              << " s (" << 100 * vtk->writeSeconds() / summary.wallSeconds << "% of the run): " << dir << "/vtk/run.pvd\n";
  }
  if (!summary.checkpointError.empty()) std::cerr << "warning: the last checkpoint failed: " << summary.checkpointError << "\n";
  if (summary.status == RunStatus::Completed) return 0;
  std::cerr << "error: run " << summary.status << (summary.error.empty() ? "" : ": " + summary.error) << "\n";
  if (summary.status == RunStatus::Interrupted) {
    std::cerr << "continue it with: grainlab resume " << dir << "\n";
    return 4;
  }
  return summary.status == RunStatus::Cancelled ? 3 : 1;
}

// A run whose last files could not be written (a full disk: OutputWriter::onFinish throws
// after recording it in summary.json). A checkpoint it kept can still continue it.
int failedWriting(const std::exception& e, const std::string& dir) {
  std::cerr << "error: " << e.what() << "\n";
  const std::string path = checkpointPath(dir);
  if (fs::exists(path) || fs::exists(path + ".previous"))
    std::cerr << "its last checkpoint is kept: grainlab resume " << dir << " continues it (with space to write)\n";
  return 1;
}

// --from DIR[:STAGE]: the scene's start_from. The stage follows the last ':' when what follows
// it names no folder (a directory may itself contain ':').
nlohmann::json startFromArgument(const std::string& from) {
  const size_t colon = from.rfind(':');
  if (colon == std::string::npos || from.find('/', colon) != std::string::npos) return {{"run", from}};
  return {{"run", from.substr(0, colon)}, {"stage", from.substr(colon + 1)}};
}

void catchStopSignals() {
  std::signal(SIGINT, onStopSignal);
  std::signal(SIGTERM, onStopSignal);
}

}  // namespace

int runCommand(const std::vector<std::string>& args) {
  std::string scenePath, preset, out, from;
  bool vtk = false, force = false;
  for (size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "--out" && k + 1 < args.size()) out = args[++k];
    else if (args[k] == "--vtk") vtk = true;
    else if (args[k] == "--force") force = true;
    else if (args[k] == "--preset" && k + 1 < args.size()) preset = args[++k];
    else if (args[k] == "--from" && k + 1 < args.size()) from = args[++k];
    else if (!args[k].empty() && args[k][0] != '-' && scenePath.empty()) scenePath = args[k];
    else {
      std::cerr << "grainlab run: unexpected argument " << args[k] << " (grainlab help lists the options)\n";
      return 2;
    }
  }
  if (out.empty() || scenePath.empty() == preset.empty()) {
    std::cerr << "grainlab run: give a SCENE.json or --preset NAME, and --out DIR\n";
    return 2;
  }
  nlohmann::json json = preset.empty() ? loadSceneJson(scenePath) : presetScene(preset);
  if (vtk && json.is_object()) json["output"]["vtk"] = true;
  if (!from.empty() && json.is_object()) json["start_from"] = startFromArgument(from);
  const Scene scene = parseScene(json);  // the whole scene is validated before anything is written
  CliRunOutput output(out, scene, &std::cerr);
  // A run estimated to take longer than this is refused unless --force: it is a typo (a
  // stiffness of 1e30, a strain rate of 1e-12) far more often than a plan.
  RunLimits limits;
  if (!force) limits.maxSeconds = 30 * 86400.0;
  const CheckpointPolicy checkpoint{checkpointPath(out), scene.output.checkpointEverySeconds, json.dump()};
  catchStopSignals();
  RunSummary summary;
  try {
    summary = runScene(scene, output, limits, checkpoint, out);
  } catch (const std::exception& e) {
    return failedWriting(e, out);
  }
  if (summary.refused) {
    std::cerr << "error: " << summary.error << (summary.refusedInvalid ? "" : " (grainlab run --force runs it anyway)")
              << "\n";
    return 2;
  }
  return report(summary, output, out);
}

int resumeCommand(const std::vector<std::string>& args) {
  if (args.size() != 1 || args[0].empty() || args[0][0] == '-') {
    std::cerr << "grainlab resume: give the run's directory (where grainlab run wrote its outputs)\n";
    return 2;
  }
  const std::string dir = args[0];
  const std::string path = checkpointPath(dir);
  if (!fs::exists(path) && !fs::exists(path + ".previous")) {
    const bool finished = fs::exists(fs::path(dir) / "summary.json");
    std::cerr << "error: " << path << ": no checkpoint"
              << (finished ? " (the run has finished: summary.json is there)" : " (the run wrote none before it stopped)")
              << "\n";
    return 2;
  }
  // What to write (VTK frames or not) is the checkpoint's scene's; if no checkpoint can be
  // read, resumeRun says why.
  Scene scene;
  try {
    scene = checkpointScene(path);
  } catch (const std::exception&) {
  }
  CliRunOutput output(dir, scene, &std::cerr);
  catchStopSignals();
  RunSummary summary;
  try {
    summary = resumeRun(path, output, CheckpointPolicy{path, scene.output.checkpointEverySeconds, {}}, dir);
  } catch (const std::exception& e) {
    return failedWriting(e, dir);
  }
  if (!summary.resumeNote.empty()) std::cerr << "note: " << summary.resumeNote << "\n";
  if (summary.refused) {
    std::cerr << "error: cannot resume: " << summary.error << "\n";
    return 2;
  }
  return report(summary, output, dir);
}

}  // namespace grainlab
