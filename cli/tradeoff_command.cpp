#include "tradeoff_command.hpp"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "grainlab/studies/draw/pareto_plot.hpp"
#include "grainlab/studies/tradeoff/tradeoff_study.hpp"

namespace grainlab {
namespace {

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
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
