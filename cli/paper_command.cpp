#include "paper_command.hpp"

#include <iostream>

#include "grainlab/studies/draw/paper_report.hpp"
#include "grainlab/studies/paper/paper_study.hpp"
#include "grainlab/studies/cluster.hpp"

namespace grainlab {

int paperCommand(const std::vector<std::string>& args) {
  report::PaperOptions options;
  options.command = "grainlab paper";
  for (const std::string& a : args) options.command += " " + a;
  for (size_t k = 0; k < args.size(); ++k) {
    const bool hasValue = k + 1 < args.size();
    if (args[k] == "--out" && hasValue) {
      options.outDir = args[++k];
    } else if (args[k] == "--quick") {
      options.quick = true;
    } else if (args[k] == "--report-only") {
      options.reportOnly = true;
    } else if ((args[k] == "--jobs" || args[k] == "--seeds") && hasValue) {
      const std::string& name = args[k];
      const std::string& value = args[++k];
      if (value.empty() || value.size() > 6 || value.find_first_not_of("0123456789") != std::string::npos ||
          std::stoul(value) == 0) {
        std::cerr << "grainlab paper: " << name << " takes a positive whole number, not \"" << value << "\"\n";
        return 2;
      }
      if (name == "--jobs") options.jobs = static_cast<unsigned>(std::stoul(value));
      else options.seeds = static_cast<int>(std::stoul(value));
    } else {
      std::cerr << "grainlab paper: unexpected argument " << args[k] << "\n"
                << "usage: grainlab paper --out DIR [--quick] [--seeds N] [--jobs N] [--report-only]\n";
      return 2;
    }
  }
  if (options.outDir.empty()) {
    std::cerr << "grainlab paper: give --out DIR\n";
    return 2;
  }
  // Under mpirun the ensemble's runs spread over the ranks, as a sweep's do; rank 0 reports.
  const studies::Cluster cluster;
  options.cluster = &cluster;
  if (options.reportOnly && cluster.size() > 1) {
    if (cluster.isRoot()) std::cerr << "grainlab paper: --report-only runs nothing: run it without mpirun\n";
    return 2;
  }
  const report::PaperStudy study = report::runPaperStudy(options, cluster.isRoot() ? &std::cerr : nullptr);
  if (!cluster.isRoot()) return 0;  // rank 0 writes the report
  report::writePaperReport(options, study, &std::cerr);
  int failed = 0;
  for (const report::AssemblyResult& a : study.runs) {
    if (a.summary.status == RunStatus::Completed) continue;
    ++failed;
    std::cerr << "error: " << a.preset << " seed " << a.seed << " " << a.summary.status
              << (a.summary.error.empty() ? "" : ": " + a.summary.error) << "\n";
  }
  return failed ? 1 : 0;
}

}  // namespace grainlab
