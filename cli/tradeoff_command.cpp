#include "tradeoff_command.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "grainlab/studies/draw/pareto_plot.hpp"
#include "grainlab/studies/tradeoff/ensemble_tradeoff.hpp"
#include "grainlab/studies/tradeoff/tradeoff_study.hpp"
#include "option_list.hpp"

namespace grainlab {
namespace {

// --seeds N: biases with intervals (tradeoff.csv per setting and quantity); stdout gives each
// setting's cost and how many quantities it biases.
int ensembleTradeoff(const tradeoff::TradeoffOptions& opt) {
  const tradeoff::EnsembleStudy study = tradeoff::runEnsembleTradeoff(opt, &std::cerr);
  const std::filesystem::path dir = opt.outDir;
  std::ofstream(dir / "pareto.svg") << tradeoff::renderParetoSvg(
      study.panels, "CPU time of the shearing per run (s, log scale)",
      "mean |angle difference| from the same seed's reference (°), 95% interval");
  std::cout << std::left << std::setw(28) << "preset" << std::setw(17) << "axis" << std::setw(36) << "value"
            << std::setw(8) << "paired" << std::setw(10) << "cpu s" << std::setw(8) << "biased" << std::setw(11)
            << "undecided" << "no bias found\n";
  for (size_t k = 0; k < study.judgements.size();) {
    const tradeoff::EnsembleJudgement& first = study.judgements[k];
    int biased = 0, undecided = 0, clean = 0;
    for (; k < study.judgements.size() && study.judgements[k].setting.axis == first.setting.axis &&
           study.judgements[k].setting.value == first.setting.value && study.judgements[k].setting.preset == first.setting.preset;
         ++k) {
      const std::string& v = study.judgements[k].estimate.verdict;
      (v.rfind("biased", 0) == 0 ? biased : v.rfind("no bias", 0) == 0 ? clean : undecided)++;
    }
    std::cout << std::setw(28) << first.setting.preset << std::setw(17) << first.setting.axis << std::setw(36)
              << first.setting.value << std::setw(8) << (first.paired ? "yes" : "no") << std::setw(10)
              << std::setprecision(3) << first.cpuSeconds << std::setw(8) << biased << std::setw(11) << undecided << clean
              << "\n";
  }
  std::cerr << "tradeoff: wrote " << (dir / "tradeoff.csv").string() << ", runs.csv and pareto.svg\n";
  return study.failedRuns == 0 ? 0 : 1;
}

}  // namespace

int tradeoffCommand(const std::vector<std::string>& args) {
  tradeoff::TradeoffOptions opt;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool value = k + 1 < args.size();
    if (args[k] == "--out" && value) opt.outDir = args[++k];
    else if (args[k] == "--quick") opt.quick = true;
    else if (args[k] == "--jobs" && value) opt.jobs = static_cast<unsigned>(std::stoul(args[++k]));
    else if (args[k] == "--presets" && value) opt.presets = splitList(args[++k]);
    else if (args[k] == "--axes" && value) opt.axes = splitList(args[++k]);
    else if (args[k] == "--seeds" && value) opt.seeds = std::stoi(args[++k]);
    else if (args[k] == "--cost" && value && (args[k + 1] == "cpu" || args[k + 1] == "wall")) opt.cost = args[++k];
    else {
      std::cerr << "grainlab tradeoff: unexpected argument " << args[k] << "\n";
      return 2;
    }
  }
  if (opt.outDir.empty()) {
    std::cerr << "grainlab tradeoff: give --out DIR\n";
    return 2;
  }
  if (opt.seeds < 0 || opt.seeds == 1) {
    std::cerr << "grainlab tradeoff: --seeds needs 2 or more (an interval needs two seeds)\n";
    return 2;
  }
  if (opt.seeds > 0) return ensembleTradeoff(opt);
  const tradeoff::TradeoffStudy study = tradeoff::runTradeoff(opt, &std::cerr);
  const std::filesystem::path dir = opt.outDir;
  const std::string xLabel = opt.cost == "cpu" ? "CPU time per run (s, log scale): its wall time on an idle core"
                                               : "wall time per run (s, log scale)";
  std::ofstream(dir / "pareto.svg") << tradeoff::renderParetoSvg(study.panels, xLabel, "mean angle error vs reference (°)");

  // A short table on stdout: cost and error of every setting.
  std::cout << std::left << std::setw(28) << "preset" << std::setw(17) << "axis" << std::setw(36) << "value"
            << std::setw(10) << "wall s" << std::setw(10) << "cpu s" << std::setw(12) << "mean err °" << std::setw(11)
            << "max err °" << std::setw(11) << "Δ void" << "front\n";
  for (const tradeoff::SettingOutcome& s : study.settings) {
    std::cout << std::setw(28) << s.setting.preset << std::setw(17) << s.setting.axis << std::setw(36)
              << s.setting.value << std::setw(10) << std::setprecision(3) << s.wallSeconds
              << std::setw(10) << std::setprecision(3) << s.cpuSeconds
              << std::setw(12) << std::setprecision(3) << s.meanAngleErrorDeg << std::setw(11) << s.maxAngleErrorDeg
              << std::setw(11) << std::setprecision(2)
              << s.voidRatioError << (s.onFront ? "*" : "") << "\n";
  }
  std::cerr << "tradeoff: wrote " << (dir / "tradeoff.csv").string() << " and " << (dir / "pareto.svg").string() << "\n";
  return study.failedRuns == 0 ? 0 : 1;
}

}  // namespace grainlab
