// POST /api/studies with {"tradeoff": {"seeds": N, "quick": bool, "presets": [...], "axes": [...]}}:
// `grainlab tradeoff --seeds N` as a study. The runs are the CLI's own plan (planEnsemble,
// ensembleRuns: the same settings, seeds and scenes), queued in the CLI's two phases: the
// references first, each preparing its seed's specimen and keeping its stages' ends; once every
// reference has ended, the other settings, a paired one shearing its seed's reference specimen
// (start_from.run_id, where the CLI names the reference's checkpoint file). Once every run has
// ended, the table is judged by the CLI's own code (judgeEnsemble) from the stored series and
// kept in the study's row: GET /api/studies/{name}/tradeoff.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/shearing_collector.hpp"
#include "grainlab/studies/tradeoff/ensemble_judgement.hpp"
#include "grainlab/studies/tradeoff/ensemble_plan.hpp"
#include "api_types.hpp"
#include "repository.hpp"
#include "run_service.hpp"
#include "study_name.hpp"

namespace grainlab::server {
namespace {

constexpr long long kMaxSeeds = 1000;

// The study's options from its stored (or posted) spec; throws ApiError naming the field.
tradeoff::TradeoffOptions tradeoffOptions(const nlohmann::ordered_json& spec) {
  for (const auto& [key, value] : spec.items())
    if (key != "tradeoff" && key != "name")
      throw ApiError(400, "unknown key (a trade-off study takes name and tradeoff: {seeds, quick, presets, axes})", key);
  const nlohmann::ordered_json& t = spec["tradeoff"];
  if (!t.is_object())
    throw ApiError(400, "must be an object: {\"seeds\": N, \"quick\": true|false, \"presets\": [...], \"axes\": [...]}",
                   "tradeoff");
  for (const auto& [key, value] : t.items())
    if (key != "seeds" && key != "quick" && key != "presets" && key != "axes")
      throw ApiError(400, "unknown key (a trade-off study takes seeds, quick, presets and axes)", "tradeoff." + key);
  tradeoff::TradeoffOptions opt;
  if (!t.contains("seeds")) throw ApiError(400, "give the seeds per setting (2 or more: an interval needs two)", "tradeoff.seeds");
  const auto& n = t["seeds"];
  if (!n.is_number_integer() || n.get<long long>() < 2 || n.get<long long>() > kMaxSeeds)
    throw ApiError(400, "must be a whole number of seeds from 2 to " + std::to_string(kMaxSeeds) +
                            " (an interval needs two; got " + n.dump() + ")",
                   "tradeoff.seeds");
  opt.seeds = n.get<int>();
  if (t.contains("quick")) {
    if (!t["quick"].is_boolean()) throw ApiError(400, "must be true or false", "tradeoff.quick");
    opt.quick = t["quick"].get<bool>();
  }
  for (const char* list : {"presets", "axes"}) {
    if (!t.contains(list)) continue;
    const std::string field = std::string("tradeoff.") + list;
    if (!t[list].is_array()) throw ApiError(400, "must be a list of names", field);
    std::vector<std::string> names;
    for (std::size_t k = 0; k < t[list].size(); ++k) {
      const auto& item = t[list][k];
      const std::string at = field + "[" + std::to_string(k) + "]";
      if (!item.is_string() || item.get<std::string>().empty()) throw ApiError(400, "must be a name (a string)", at);
      if (std::find(names.begin(), names.end(), item.get<std::string>()) != names.end())
        throw ApiError(400, "\"" + item.get<std::string>() + "\" is listed twice", at);
      names.push_back(item.get<std::string>());
      if (std::string(list) == "presets") {
        try {
          presetScene(names.back());
        } catch (const SceneError& e) {
          throw ApiError(400, e.reason(), at);
        }
      }
    }
    if (std::string(list) == "presets" && names.empty()) throw ApiError(400, "must name at least one preset", field);
    (std::string(list) == "presets" ? opt.presets : opt.axes) = std::move(names);
  }
  return opt;
}

tradeoff::EnsemblePlan plan(const tradeoff::TradeoffOptions& opt) {
  try {
    return tradeoff::planEnsemble(opt);
  } catch (const SceneError& e) {
    throw ApiError(400, e.reason(), e.field() == "--axes" ? "tradeoff.axes" : "tradeoff.presets");
  }
}

bool isTradeoff(const StudyRecord& study) {
  const auto spec = nlohmann::json::parse(study.spec, nullptr, false);
  return spec.is_object() && spec.contains("tradeoff");
}

// What a run of the plan shows as its values: the setting (as the bands group by it), its
// preset and its seed.
nlohmann::json runParameters(const tradeoff::EnsemblePlan& plan, const tradeoff::EnsembleRun& run) {
  const tradeoff::Setting& s = plan.settings[plan.runSetting[run.run]];
  return {{"setting", s.axis + " " + s.value}, {"preset", s.preset}, {"seed", run.seed}};
}

// "run-RR-seed-N.json" -> "run-RR-seed-N": the run's id in the study (NAME/run-RR-seed-N).
std::string runId(const tradeoff::EnsembleRun& run) { return run.file.substr(0, run.file.size() - 5); }

// A value the JSON can hold: NaN as null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

std::string RunService::launchTradeoffStudy(const nlohmann::ordered_json& spec) {
  const tradeoff::TradeoffOptions opt = tradeoffOptions(spec);
  const std::string name = studyName(spec, std::string("tradeoff") + (opt.quick ? "-quick" : "") + "-" + std::to_string(opt.seeds) + "-seeds");
  const tradeoff::EnsemblePlan ensemble = plan(opt);
  const std::size_t count = ensemble.runSetting.size() * static_cast<std::size_t>(ensemble.seeds);
  const std::size_t ceiling = static_cast<std::size_t>(manager_.maxConcurrent() + std::max(0, options_.maxQueuedRuns));
  if (count > ceiling)
    throw ApiError(400,
                   "the trade-off with " + std::to_string(ensemble.seeds) + " seeds is " + std::to_string(count) +
                       " runs; this server holds at most " + std::to_string(ceiling) + " at once (" +
                       std::to_string(manager_.maxConcurrent()) + " running, " +
                       std::to_string(options_.maxQueuedRuns) + " queued: grainlab serve --max-concurrent, --max-queued)",
                   "tradeoff.seeds");
  // The second phase's scenes are checked now, as they will be admitted (less the specimen they
  // start from, which does not exist yet): a study is refused whole, not half-way through.
  const std::vector<tradeoff::EnsembleRun> later = tradeoff::ensembleRuns(ensemble, false);
  for (std::size_t k = 0; k < later.size(); ++k) {
    try {
      admit(later[k].scene, ensemble.settings[ensemble.runSetting[later[k].run]].preset);
    } catch (const ApiError& e) {
      throw ApiError(e.status(), "run " + runId(later[k]) + " (" + later[k].name + "): " + e.what(),
                     "runs[" + std::to_string(k) + "]" + (e.field().empty() ? "" : "." + e.field()));
    }
  }

  std::vector<StudyRun> runs;
  for (tradeoff::EnsembleRun& run : tradeoff::ensembleRuns(ensemble, true)) {
    const std::string preset = ensemble.settings[ensemble.runSetting[run.run]].preset;
    runs.push_back({run.scene, runId(run), preset, runParameters(ensemble, run), run.name});
  }
  // The spec kept as posted, with what was taken by default written out.
  nlohmann::ordered_json stored{{"name", name},
                                {"tradeoff", {{"seeds", opt.seeds}, {"quick", opt.quick}, {"presets", ensemble.presets}}}};
  if (!opt.axes.empty()) stored["tradeoff"]["axes"] = opt.axes;
  return storeStudy(name, stored, std::move(runs), "tradeoff.seeds", [](const std::string& field, std::size_t k) {
    return "runs[" + std::to_string(k) + "]" + (field.empty() ? "" : "." + field);
  });
}

void RunService::continueTradeoffStudy(const std::string& name) {
  if (const auto launched = repo_.launchedStudies(name); launched.empty() || !isTradeoff(launched.front())) {
    std::lock_guard waiting(waitingMutex_);
    waitingTradeoffs_.erase(name);  // deleted meanwhile (or never one)
    return;
  }
  std::lock_guard lock(studyMutex_);
  repo_.flush().get();  // the end of the run that asked is committed
  const auto launched = repo_.launchedStudies(name);
  if (launched.empty() || !isTradeoff(launched.front()) || launched.front().status == "cancelled") return;
  const auto spec = nlohmann::ordered_json::parse(launched.front().spec);
  const auto listed = nlohmann::json::parse(launched.front().runs);
  const tradeoff::EnsemblePlan ensemble = plan(tradeoffOptions(spec));
  const std::vector<tradeoff::EnsembleRun> references = tradeoff::ensembleRuns(ensemble, true);
  if (listed.size() != references.size()) return;  // the second phase is queued already
  // Each reference's stored run by its preset and seed; all of them ended (a cancelled or
  // interrupted one may still be resumed: the study waits for it).
  std::map<std::pair<std::string, int>, RunRecord> reference;
  for (std::size_t k = 0; k < listed.size(); ++k) {
    const auto run = storedRun(listed[k].value("id", std::int64_t{0}));
    if (!run || !hasEnded(run->status) || run->status == RunStatus::Cancelled || run->status == RunStatus::Interrupted)
      return;
    reference[{ensemble.settings[ensemble.runSetting[references[k].run]].preset, references[k].seed}] = *run;
  }

  // Room for all of them now, or wait: a run that ends frees a slot and asks again (the run
  // asking now still holds its slot; a study is launched only if its whole plan fits an idle
  // server, so its second phase fits one with its references ended).
  const std::size_t count = tradeoff::ensembleRuns(ensemble, false).size();
  const long room = std::max(0, manager_.maxConcurrent() - manager_.running()) +
                    std::max(0L, static_cast<long>(options_.maxQueuedRuns) - static_cast<long>(manager_.queued()));
  {
    std::lock_guard waiting(waitingMutex_);
    if (static_cast<long>(count) > room) {
      waitingTradeoffs_.insert(name);
      return;
    }
    waitingTradeoffs_.erase(name);
  }

  nlohmann::json entries = nlohmann::json::array();
  std::vector<RunRecord> records;
  std::vector<std::optional<AdmittedRun>> admitted;
  std::vector<std::string> refusals;  // why a run could not be queued: it is stored failed
  for (tradeoff::EnsembleRun& run : tradeoff::ensembleRuns(ensemble, false)) {
    const std::string preset = ensemble.settings[ensemble.runSetting[run.run]].preset;
    const RunRecord& parent = reference.at({preset, run.seed});
    if (run.paired) run.scene["start_from"] = {{"run_id", parent.id}, {"stage", tradeoff::preparedStage(preset)}};
    run.scene["name"] = name + "/" + runId(run);
    std::string refusal;
    if (run.paired && parent.status != RunStatus::Completed) {
      refusal = "its seed's reference run " + parent.name + " " + std::string(toString(parent.status)) +
                (parent.error.empty() ? "" : " (" + parent.error + ")") + ": there is no specimen to shear";
    } else {
      try {
        admitted.emplace_back(admit(run.scene, preset));
      } catch (const ApiError& e) {
        refusal = e.what();
      }
    }
    RunRecord record;
    if (refusal.empty()) {
      record = admitted.back()->record;
    } else {
      admitted.emplace_back(std::nullopt);
      record.name = run.scene["name"].get<std::string>();
      record.preset = preset;
      record.scene = run.scene.dump();
      record.createdAt = unixNow();
    }
    record.study = name;
    records.push_back(record);
    refusals.push_back(refusal);
    entries.push_back({{"name", record.name}, {"parameters", runParameters(ensemble, run)}});
  }
  std::vector<std::int64_t> ids;
  try {
    ids = repo_.appendStudyRuns(name, entries.dump(), records).get();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "grainlab serve: study %s: its runs after the references could not be stored (%s)\n",
                 name.c_str(), e.what());
    return;  // asked again at the next run's end or the next GET of its table
  }
  for (std::size_t k = 0; k < ids.size(); ++k) {
    if (refusals[k].empty()) {
      try {
        startAdmitted(ids[k], *admitted[k]);
        continue;
      } catch (const ApiError& e) {
        // The server is stopping: the run stays queued, and the next start queues it.
        if (e.status() == 503) continue;
        refusals[k] = e.what();  // the queue filled meanwhile
      }
    }
    RunEnd end;
    end.status = RunStatus::Failed;
    end.error = "not run: " + refusals[k];
    end.finishedAt = unixNow();
    repo_.finishRun(ids[k], end, nullptr);
  }
  repo_.flush().get();
}

void RunService::continueTradeoffStudies(const std::string& study) {
  std::vector<std::string> names;
  if (!study.empty()) names.push_back(study);
  {
    std::lock_guard waiting(waitingMutex_);
    for (const std::string& name : waitingTradeoffs_)
      if (name != study) names.push_back(name);
  }
  for (const std::string& name : names) {
    try {
      continueTradeoffStudy(name);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "grainlab serve: study %s: %s\n", name.c_str(), e.what());
    }
  }
}

std::string RunService::studyTradeoff(const std::string& name) {
  const auto launched = repo_.launchedStudies(name);
  if (launched.empty()) {
    if (repo_.studies(name).empty()) throw ApiError(404, "no study '" + name + "'", "study");
    throw ApiError(409, "study '" + name + "' is an imported sweep, not a trade-off study: it has no trade-off table", "study");
  }
  if (!isTradeoff(launched.front()))
    throw ApiError(409, "study '" + name + "' is not a trade-off study: it has no trade-off table", "study");
  if (auto kept = repo_.studyFindings(name)) return *kept;
  continueTradeoffStudy(name);  // its second phase, if the references ended while nobody asked

  std::lock_guard lock(studyMutex_);  // one computation at a time, and not beside a resume
  if (auto kept = repo_.studyFindings(name)) return *kept;
  const StudyRecord study = repo_.launchedStudies(name).front();
  const auto spec = nlohmann::ordered_json::parse(study.spec);
  const tradeoff::TradeoffOptions opt = tradeoffOptions(spec);
  const tradeoff::EnsemblePlan ensemble = plan(opt);
  std::vector<tradeoff::EnsembleRun> planned = tradeoff::ensembleRuns(ensemble, true);
  for (tradeoff::EnsembleRun& run : tradeoff::ensembleRuns(ensemble, false)) planned.push_back(std::move(run));
  const auto listed = nlohmann::json::parse(study.runs);
  if (listed.size() < planned.size())
    throw ApiError(409, "the study's reference runs have not all ended (or were cancelled or interrupted: resume the "
                        "study): the other settings are queued once they have",
                   "study");

  std::map<std::string, std::int64_t> idOf;  // NAME/run-RR-seed-N -> the stored run
  for (const auto& entry : listed) idOf[entry.value("name", std::string())] = entry.value("id", std::int64_t{0});
  std::vector<std::vector<tradeoff::EnsembleRunResult>> results(
      ensemble.runSetting.size(), std::vector<tradeoff::EnsembleRunResult>(static_cast<std::size_t>(ensemble.seeds)));
  int unfinished = 0;
  for (const tradeoff::EnsembleRun& run : planned) {
    const auto stored = storedRun(idOf[name + "/" + runId(run)]);
    if (!stored) throw ApiError(409, "run " + name + "/" + runId(run) + " was deleted: the table needs every run", "study");
    // As for a paper study's findings: a cancelled or interrupted run may still be resumed.
    if (!hasEnded(stored->status) || live(stored->id) || stored->status == RunStatus::Cancelled ||
        stored->status == RunStatus::Interrupted) {
      ++unfinished;
      continue;
    }
    tradeoff::EnsembleRunResult& r = results[run.run][static_cast<std::size_t>(run.seed - 1)];
    r.status = stored->status;
    r.error = stored->error;
    r.wallSeconds = stored->wallSeconds.value_or(0.0);
    // Split where the CLI splits it: the thread's CPU time at the shearing stage's start.
    if (stored->cpuSeconds && stored->preparationCpuSeconds) {
      r.preparationCpuSeconds = *stored->preparationCpuSeconds;
      r.cpuSeconds = *stored->cpuSeconds - *stored->preparationCpuSeconds;
    }
    // The shearing stage from the stored samples, exactly as the CLI's recorder keeps it live.
    const Scene scene = parseScene(run.scene);
    report::AssemblyResult shearing;
    report::ShearingCollector collector(shearing, report::biaxialStageIndex(scene));
    for (const SampleRecord& s : repo_.samples(stored->id)) collector.add(s.step, s.values, nullptr);
    double pressure = tradeoff::EnsembleRunResult::kNaN;
    for (const StageSpec& stage : scene.stages)
      if (stage.type == StageSpec::Type::Biaxial) {
        pressure = stage.pressure;
        break;
      }
    tradeoff::measureEnsembleRun(r, shearing.shearing, stored->peakPhiMobDeg.value_or(0.0), pressure);
  }
  if (unfinished > 0)
    throw ApiError(409, std::to_string(unfinished) + " of the study's " + std::to_string(planned.size()) +
                            " runs have not ended (or were cancelled or interrupted: resume the study): the table "
                            "is judged once every run has completed or failed",
                   "study");

  const tradeoff::EnsembleTables tables = tradeoff::judgeEnsemble(ensemble, results);
  nlohmann::json panels = nlohmann::json::array();
  for (const tradeoff::ParetoPanel& panel : tables.study.panels) {
    nlohmann::json points = nlohmann::json::array();
    for (const tradeoff::ParetoPoint& p : panel.points)
      points.push_back({{"cpu_s", number(p.seconds)},
                        {"error_deg", number(p.error)},
                        {"error_low_deg", number(p.errorLow)},
                        {"error_high_deg", number(p.errorHigh)},
                        {"label", p.label},
                        {"axis", p.axis},
                        {"on_front", p.onFront}});
    panels.push_back({{"title", panel.title}, {"noise_floor_deg", number(panel.noiseFloor)}, {"points", std::move(points)}});
  }
  const nlohmann::json out{{"study", name},
                           {"seeds", ensemble.seeds},
                           {"quick", opt.quick},
                           {"runs", planned.size()},
                           {"failed_runs", tables.study.failedRuns},
                           {"panels", std::move(panels)},
                           {"csv", tables.tradeoff.text()},
                           {"runs_csv", tables.runs.text()}};
  const std::string text = out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  repo_.setStudyFindings(name, text);
  repo_.flush().get();
  return text;
}

}  // namespace grainlab::server
