#include "grainlab/report/paper_report.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "grainlab/presets.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/report/figures.hpp"
#include "grainlab/report/parallel_runs.hpp"
#include "grainlab/report/run_loader.hpp"
#include "grainlab/report/run_plan.hpp"
#include "grainlab/studies/cluster.hpp"

namespace grainlab::report {
namespace {

namespace fs = std::filesystem;

// Through a temporary name, so a reader never sees half a report.
void writeText(const fs::path& path, const std::string& text) { writeFileAtomically(path.string(), text); }

}  // namespace

std::vector<std::string> paperPresets(bool quick) {
  std::vector<std::string> names{"circular",           "elongated-random",     "elongated-bedding-0",
                                 "elongated-bedding-30", "elongated-bedding-60", "elongated-bedding-90"};
  if (quick) {
    for (std::string& n : names) n += "-quick";
  }
  return names;
}

std::vector<Finding> writePaperReport(const std::string& outDir, std::span<const AssemblyResult> runs,
                                      const ReportContext& context) {
  const fs::path dir(outDir);
  fs::create_directories(dir / "svg");
  const std::vector<Figure> figures = paperFigures(runs);
  const std::vector<Finding> findings = evaluateFindings(runs);
  for (const Figure& f : figures) {
    f.data.write((dir / (f.id + ".csv")).string());
    for (const FigurePanel& p : f.panels) writeText(dir / "svg" / (p.name + ".svg"), p.fileSvg);
  }
  runsTable(runs).write((dir / "runs.csv").string());
  findingsTable(findings).write((dir / "findings.csv").string());
  writeText(dir / "report.html", renderReportHtml(runs, findings, figures, context));
  return findings;
}

PaperOutcome runPaper(const PaperOptions& options, std::ostream* progress) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> presets = paperPresets(options.quick);
  const fs::path runsDir = fs::path(options.outDir) / "runs";
  fs::create_directories(runsDir);
  const size_t planned = presets.size() * static_cast<size_t>(std::max(1, options.seeds));
  const bool ranks = options.cluster && options.cluster->size() > 1;
  const unsigned concurrent = options.reportOnly ? 0
                              : ranks            ? static_cast<unsigned>(options.cluster->size())
                                                 : concurrentRuns(options.jobs, planned);
  if (progress) {
    if (options.reportOnly) *progress << "[paper] rebuilding the report from " << runsDir.string() << "\n";
    else *progress << "[paper] " << presets.size() << " assemblies × " << options.seeds << " seed(s), " << concurrent
                   << " run(s) at a time" << (ranks ? " (MPI ranks)" : "") << ", into " << options.outDir << "\n";
  }
  // (1) the runs, (2) executed, each into its own directory.
  std::vector<std::pair<std::string, int>> toLoad;
  if (options.reportOnly) {
    for (const std::string& preset : presets) {
      const std::vector<int> seeds = seedsOnDisk(runsDir.string(), preset);
      for (int seed : seeds) toLoad.emplace_back(preset, seed);
      if (seeds.empty()) toLoad.emplace_back(preset, 0);  // 0: the single-run layout runs/<preset>/
    }
  } else {
    const std::vector<PlannedRun> plan = planRuns(presets, options.seeds, runsDir.string());
    executeRuns(plan, options.jobs, progress, options.cluster);
    if (options.cluster && !options.cluster->isRoot()) return {};  // rank 0 writes the report
    for (const PlannedRun& r : plan) toLoad.emplace_back(r.preset, r.seed);
  }
  // (3) the report from what is on disk.
  PaperOutcome outcome;
  for (const auto& [preset, seed] : toLoad) {
    const fs::path dir = seed > 0 ? runsDir / preset / ("seed-" + std::to_string(seed)) : runsDir / preset;
    try {
      outcome.runs.push_back(loadAssemblyResult(dir.string(), preset));
      outcome.runs.back().seed = std::max(seed, 1);
    } catch (const std::exception& e) {
      AssemblyResult failed;
      try {
        failed = describeAssembly(preset, parseScene(presetScene(preset)));
      } catch (const std::exception&) {
        failed.preset = preset;
      }
      failed.seed = std::max(seed, 1);
      failed.summary.status = RunStatus::Failed;
      failed.summary.error = e.what();
      outcome.runs.push_back(std::move(failed));
    }
  }
  outcome.allCompleted = true;
  for (const AssemblyResult& a : outcome.runs) outcome.allCompleted = outcome.allCompleted && a.summary.status == RunStatus::Completed;

  ReportContext context;
  context.command = options.command;
  context.quick = options.quick;
  context.concurrentRuns = concurrent;
  // Seeds per assembly as found (the --report-only case included).
  context.seeds = 0;
  for (const std::string& preset : presets) {
    context.seeds = std::max<int>(context.seeds, static_cast<int>(std::count_if(
        outcome.runs.begin(), outcome.runs.end(), [&](const AssemblyResult& a) { return a.preset == preset; })));
  }
  context.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.findings = writePaperReport(options.outDir, outcome.runs, context);
  outcome.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress) {
    *progress << "[paper] report written to " << (fs::path(options.outDir) / "report.html").string() << " after "
              << static_cast<long>(outcome.wallSeconds) << " s\n";
  }
  return outcome;
}

}  // namespace grainlab::report
