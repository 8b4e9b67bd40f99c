#include "grainlab/studies/draw/paper_report.hpp"

#include <chrono>
#include <filesystem>

#include "grainlab/output_writer.hpp"
#include "grainlab/studies/draw/figures.hpp"
#include "grainlab/studies/draw/html_report.hpp"

namespace grainlab::report {
namespace {

namespace fs = std::filesystem;

// Through a temporary name, so a reader never sees half a report.
void writeText(const fs::path& path, const std::string& text) { writeFileAtomically(path.string(), text); }

std::vector<Finding> writeReportFiles(const std::string& outDir, std::span<const AssemblyResult> runs,
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

}  // namespace

std::vector<Finding> writePaperReport(const PaperOptions& options, const PaperStudy& study, std::ostream* progress) {
  const auto start = std::chrono::steady_clock::now();
  const ReportContext context{options.command, options.quick, study.concurrentRuns, study.seeds, study.wallSeconds};
  std::vector<Finding> findings = writeReportFiles(options.outDir, study.runs, context);
  if (progress) {
    const double seconds = study.wallSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    *progress << "[paper] report written to " << (fs::path(options.outDir) / "report.html").string() << " after "
              << static_cast<long>(seconds) << " s\n";
  }
  return findings;
}

}  // namespace grainlab::report
