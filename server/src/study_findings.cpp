// GET /api/studies/{name}/findings: a paper study's findings, judged by the code `grainlab
// paper` judges them with. Each run is laid out as the CLI's run folder (scene.json,
// summary.json, series.csv: the server's series.csv is the CLI's byte for byte) and read
// back by the CLI's loader, then evaluateFindings and findingsTable as the CLI's report.
// Computed once every run has ended, and kept in the study's row.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/studies/draw/html_report.hpp"
#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/findings.hpp"
#include "grainlab/studies/paper/run_loader.hpp"
#include "api_types.hpp"
#include "repository.hpp"
#include "run_service.hpp"

namespace grainlab::server {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// A value the JSON can hold: NaN (not measured, no interval) as null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// As findings.csv's columns (html_report.cpp's findingsTable).
nlohmann::json findingsJson(const std::vector<report::Finding>& findings) {
  nlohmann::json out = nlohmann::json::array();
  for (const report::Finding& f : findings) {
    int seeds = 1;
    for (const report::Check& c : f.checks) seeds = std::max(seeds, c.runs);
    nlohmann::json checks = nlohmann::json::array();
    for (const report::Check& c : f.checks) {
      checks.push_back({{"subject", c.subject},
                        {"quantity", c.quantity},
                        {"value", number(c.value)},
                        {"seeds", c.seeds},
                        {"ci_low", number(c.ciLow)},
                        {"ci_high", number(c.ciHigh)},
                        {"holds_from", number(c.holdsFrom)},
                        {"holds_to", number(c.holdsTo)},
                        {"verdict", c.diagnostic ? std::string("measured") : report::verdictText(c.verdict, c.runs)},
                        {"measured", c.measured},
                        {"interval", report::intervalMethodText(c.interval, c.range.low, c.range.high)},
                        {"seeds_to_resolve", c.seedsToResolve > 0 ? nlohmann::json(c.seedsToResolve) : nlohmann::json(nullptr)}});
    }
    out.push_back({{"number", f.number},
                   {"claim", f.claim},
                   {"criterion", f.criterion},
                   {"verdict", report::verdictText(f.verdict, seeds)},
                   {"note", f.note},
                   {"checks", std::move(checks)}});
  }
  return out;
}

}  // namespace

std::string RunService::studyFindings(const std::string& name) {
  const auto launched = repo_.launchedStudies(name);
  if (launched.empty()) {
    if (repo_.studies(name).empty()) throw ApiError(404, "no study '" + name + "'", "study");
    throw ApiError(409, "study '" + name + "' is an imported sweep, not a paper study: it has no findings", "study");
  }
  const auto spec = nlohmann::json::parse(launched.front().spec, nullptr, false);
  if (!spec.is_object() || !spec.contains("paper"))
    throw ApiError(409, "study '" + name + "' is a sweep, not a paper study: it has no findings (its bands are at /bands)",
                   "study");
  if (auto kept = repo_.studyFindings(name)) return *kept;

  std::lock_guard lock(studyMutex_);  // one computation at a time, and not beside a resume
  if (auto kept = repo_.studyFindings(name)) return *kept;
  const auto listed = nlohmann::json::parse(launched.front().runs, nullptr, false);
  std::vector<RunRecord> runs;
  int unfinished = 0;
  for (const auto& entry : listed) {
    const auto run = storedRun(entry.value("id", std::int64_t{0}));
    if (!run) throw ApiError(409, "run " + entry.value("name", std::string()) + " was deleted: the findings need every run", "study");
    // A cancelled or interrupted run may still be resumed (POST .../resume): the findings
    // wait for it, so that the ones kept are never those of a study that went on after.
    if (!hasEnded(run->status) || live(run->id) || run->status == RunStatus::Cancelled ||
        run->status == RunStatus::Interrupted)
      ++unfinished;
    runs.push_back(*run);
  }
  if (unfinished > 0)
    throw ApiError(409, std::to_string(unfinished) + " of the study's " + std::to_string(runs.size()) +
                            " runs have not ended (or were cancelled or interrupted: resume the study): the findings "
                            "are computed once every run has completed or failed",
                   "study");

  // Each run as the CLI leaves it on disk, read back by the CLI's loader.
  const fs::path dir = fs::temp_directory_path() /
                       ("grainlab-findings-" + std::to_string(::getpid()) + "-" + name);
  std::error_code ec;
  fs::remove_all(dir, ec);
  std::vector<report::AssemblyResult> assemblies;
  try {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const RunRecord& run = runs[k];
      const auto stored = repo_.findRun(run.id);
      const fs::path runDir = dir / std::to_string(k);
      fs::create_directories(runDir);
      writeFile(runDir / "scene.json", stored->scene);
      const nlohmann::json summary{
          {"status", toString(run.status)},
          {"error", run.error},
          {"wall_seconds", run.wallSeconds.value_or(0.0)},
          {"steps", run.steps},
          {"particles", run.particles},
          {"peak_phi_mob_deg", run.peakPhiMobDeg.value_or(0.0)},
          {"void_ratio_after_consolidation", repo_.voidRatio(run.id).value_or(-1.0)},
          {"warnings", nlohmann::json::parse(run.warnings, nullptr, false)},
      };
      writeFile(runDir / "summary.json", summary.dump(2));
      std::string csv = format_.csvHeader();
      for (const SampleRecord& s : repo_.samples(run.id)) csv += format_.csvRow(s);
      writeFile(runDir / "series.csv", csv);
      assemblies.push_back(report::loadAssemblyResult(runDir.string(), listed[k]["parameters"].value("preset", run.preset)));
    }
  } catch (const std::exception& e) {
    fs::remove_all(dir, ec);
    throw ApiError(500, std::string("the runs could not be read back for the findings: ") + e.what());
  }
  fs::remove_all(dir, ec);

  const std::vector<report::Finding> findings = report::evaluateFindings(assemblies);
  const nlohmann::json out{{"study", name},
                           {"seeds", spec["paper"].value("seeds", 1)},
                           {"quick", spec["paper"].value("quick", false)},
                           {"runs", runs.size()},
                           {"findings", findingsJson(findings)},
                           {"csv", report::findingsTable(findings).text()}};
  const std::string text = out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  repo_.setStudyFindings(name, text);
  repo_.flush().get();
  return text;
}

}  // namespace grainlab::server
