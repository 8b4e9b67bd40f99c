#include "grainlab/studies/sweep.hpp"

#include <exception>
#include <fstream>
#include <optional>

#include "grainlab/errors.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/studies/cluster.hpp"
#include "grainlab/studies/run_batch.hpp"
#include "grainlab/studies/sweep_preparation.hpp"
#include "grainlab/studies/sweep_table.hpp"

namespace grainlab::studies {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSweepFile = "sweep.json";
constexpr const char* kTableFile = "sweep.csv";

nlohmann::ordered_json describeSweep(const SweepSpec& spec, const std::vector<SweepRun>& runs) {
  nlohmann::ordered_json doc;
  doc["spec"] = spec.source;
  doc["runs"] = nlohmann::ordered_json::array();
  for (const SweepRun& run : runs) {
    nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
    for (const auto& [path, value] : run.parameters) parameters[path] = nlohmann::ordered_json::parse(value.dump());
    doc["runs"].push_back({{"id", run.id}, {"parameters", parameters}});
  }
  return doc;
}

// A DIR that already holds a sweep may only be resumed with the same spec.
void checkResumable(const fs::path& dir, const SweepSpec& spec) {
  std::ifstream in(dir / kSweepFile);
  if (!in) return;
  nlohmann::ordered_json earlier;
  try {
    earlier = nlohmann::ordered_json::parse(in);
  } catch (const std::exception&) {
    throw SceneError("--out", (dir / kSweepFile).string() + " is not a sweep this program wrote: choose another DIR");
  }
  if (!earlier.contains("spec") || earlier["spec"] != spec.source)
    throw SceneError("--out", dir.string() + " holds a different sweep (its sweep.json has another spec): resume it "
                              "with that spec, or choose another DIR");
}

}  // namespace

SweepOutcome runSweep(const SweepSpec& spec, const SweepOptions& options, const Cluster& cluster) {
  // Every rank expands the same spec to the same runs, so only indices travel over MPI.
  std::vector<SweepRun> runs = expandSweep(spec);
  const fs::path runsDir = options.outDir / "runs";
  std::optional<SweepPreparation> preparation;
  if (spec.prepare) preparation = prepareSweep(spec, runs, options.outDir);  // refuses before anything is written

  std::exception_ptr refusal;
  if (cluster.isRoot()) {
    try {
      checkResumable(options.outDir, spec);
      fs::create_directories(runsDir);
      writeFileAtomically((options.outDir / kSweepFile).string(), describeSweep(spec, runs).dump(2) + "\n");
    } catch (...) {
      refusal = std::current_exception();
    }
  }
  if (!cluster.agree(refusal == nullptr)) {
    if (refusal) std::rethrow_exception(refusal);
    return {};
  }

  if (preparation) {
    // A batch is collective, so under MPI every specimen exists before any run starts from one.
    BatchOptions prepareOptions;
    prepareOptions.jobs = options.jobs;
    prepareOptions.progress = options.progress;
    prepareOptions.label = "prepare";
    runBatch(preparation->specimens, prepareOptions, cluster);
  }

  std::vector<BatchRun> batch;
  batch.reserve(runs.size());
  for (const SweepRun& run : runs) batch.push_back({run.id, runsDir / run.id, run.scene});
  BatchOptions batchOptions;
  batchOptions.jobs = options.jobs;
  batchOptions.progress = options.progress;
  batchOptions.label = "sweep";
  const std::vector<BatchRunResult> results = runBatch(batch, batchOptions, cluster);
  if (!cluster.isRoot()) return {};

  writeFileAtomically((options.outDir / kTableFile).string(), sweepTable(runs, results, runsDir));
  SweepOutcome outcome;
  outcome.runs = runs.size();
  for (const BatchRunResult& r : results) (r.status == RunStatus::Completed ? outcome.completed : outcome.failed) += 1;
  if (options.progress) {
    *options.progress << "[sweep] " << outcome.completed << " of " << outcome.runs << " runs completed"
                      << (outcome.failed ? ", " + std::to_string(outcome.failed) + " failed or cancelled" : "")
                      << "; table in " << (options.outDir / kTableFile).string() << "\n";
  }
  return outcome;
}

}  // namespace grainlab::studies
