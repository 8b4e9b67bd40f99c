#include "sweep_command.hpp"

#include <iostream>

#include "grainlab/errors.hpp"
#include "grainlab/studies/cluster.hpp"
#include "grainlab/studies/sweep.hpp"

namespace grainlab {
namespace {

constexpr const char* kUsage = "usage: grainlab sweep SPEC.json --out DIR [--jobs N]   (or under mpirun -np R)\n";

}  // namespace

int sweepCommand(const std::vector<std::string>& args) {
  std::string specPath;
  studies::SweepOptions options;
  bool jobsGiven = false;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool hasValue = k + 1 < args.size();
    if (args[k] == "--out" && hasValue) {
      options.outDir = args[++k];
    } else if (args[k] == "--jobs" && hasValue) {
      const std::string& value = args[++k];
      if (value.empty() || value.size() > 6 || value.find_first_not_of("0123456789") != std::string::npos ||
          std::stoul(value) == 0) {
        std::cerr << "grainlab sweep: --jobs takes a positive whole number, not \"" << value << "\"\n";
        return 2;
      }
      options.jobs = static_cast<unsigned>(std::stoul(value));
      jobsGiven = true;
    } else if (!args[k].empty() && args[k][0] != '-' && specPath.empty()) {
      specPath = args[k];
    } else {
      std::cerr << "grainlab sweep: unexpected argument " << args[k] << "\n" << kUsage;
      return 2;
    }
  }
  if (specPath.empty() || options.outDir.empty()) {
    std::cerr << "grainlab sweep: give a SPEC.json and --out DIR\n" << kUsage;
    return 2;
  }

  studies::Cluster cluster;
  if (cluster.size() > 1 && jobsGiven && options.jobs > 1) {
    if (cluster.isRoot())
      std::cerr << "grainlab sweep: under mpirun each rank runs one run at a time: give more ranks (-np), not --jobs\n";
    return 2;
  }
  if (cluster.isRoot()) options.progress = &std::cerr;
  try {
    const studies::SweepOutcome outcome = studies::runSweep(studies::loadSweepSpec(specPath), options, cluster);
    return outcome.failed == 0 ? 0 : 1;
  } catch (const SceneError& e) {
    // Every rank finds the same fault in the same spec; one of them says so.
    if (cluster.isRoot()) std::cerr << "error: " << e.field() << ": " << e.reason() << "\n";
    return 2;
  }
}

}  // namespace grainlab
