// GET /api/studies/{name}/bands: a study's completed runs read from their stored series, grouped
// by the value of a varied path, as ensemble bands on one strain grid (study_bands.hpp). The
// dashboard's study page draws these rather than loading every run's series.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "api_types.hpp"
#include "repository.hpp"
#include "run_service.hpp"
#include "study_bands.hpp"

namespace grainlab::server {
namespace {

// Strains on the grid: 200 steps resolve a curve to 0.5 % of its range, and keep the answer
// for a study of any size a few kilobytes per group.
constexpr int kGridPoints = 201;

std::string quantityKeys() {
  std::string keys;
  for (const BandQuantity& q : bandQuantities()) keys += (keys.empty() ? "" : ", ") + q.key;
  return keys;
}

}  // namespace

std::string RunService::studyBands(const std::string& name, const QueryParameters& query) {
  for (const auto& [key, value] : query)
    if (key != "quantity" && key != "group")
      throw ApiError(400, "unknown parameter (the bands take quantity and group)", key);
  const std::string key = query.contains("quantity") ? query.find("quantity")->second : "phi";
  const BandQuantity* quantity = bandQuantity(key);
  if (!quantity) throw ApiError(400, "no quantity '" + key + "' (one of " + quantityKeys() + ")", "quantity");

  const auto counts = repo_.studies(name);
  const auto launched = repo_.launchedStudies(name);
  if (counts.empty() && launched.empty()) throw ApiError(404, "no study '" + name + "'", "study");

  // The varied paths and each run's values: a launched study's; an imported one has none.
  std::vector<std::string> paths;
  std::map<std::int64_t, nlohmann::json> parameters;
  if (!launched.empty()) {
    const auto spec = nlohmann::ordered_json::parse(launched.front().spec, nullptr, false);
    if (spec.is_object() && spec.contains("vary") && spec["vary"].is_object())
      for (const auto& [path, values] : spec["vary"].items()) paths.push_back(path);
    if (spec.is_object() && spec.contains("paper")) paths = {"preset", "seed"};  // a paper study's runs
    if (spec.is_object() && spec.contains("tradeoff")) paths = {"setting", "preset", "seed"};  // study_tradeoff.cpp
    const auto runs = nlohmann::json::parse(launched.front().runs, nullptr, false);
    if (runs.is_array())
      for (const auto& run : runs)
        if (run.contains("id") && run.contains("parameters")) parameters[run["id"].get<std::int64_t>()] = run["parameters"];
  }
  std::string group;
  if (query.contains("group")) {
    group = query.find("group")->second;
    if (!group.empty() && std::find(paths.begin(), paths.end(), group) == paths.end())
      throw ApiError(400, "'" + group + "' is not a path the study varies" +
                              (paths.empty() ? std::string(" (it varies none it knows of)") : ""),
                     "group");
  } else {
    // The first varied path that is not the seed: seeds are what an ensemble averages over.
    for (const std::string& path : paths)
      if (path != "seed") {
        group = path;
        break;
      }
  }

  RunQuery completed;
  completed.study = name;
  completed.statuses = {RunStatus::Completed};
  completed.descending = false;
  std::vector<RunRecord> runs = repo_.listRuns(completed).runs;
  std::sort(runs.begin(), runs.end(), [](const RunRecord& a, const RunRecord& b) { return a.id < b.id; });

  // Groups in the order their first run appears; a run's value as JSON text ("0.3", "null").
  std::vector<std::string> values;
  std::vector<std::vector<std::int64_t>> ids;
  std::vector<BandCurve> curves;
  curves.reserve(runs.size());
  for (const RunRecord& run : runs) {
    std::string value = "all runs";
    if (!group.empty()) {
      const auto it = parameters.find(run.id);
      value = it != parameters.end() && it->second.contains(group) ? it->second[group].dump() : "null";
    }
    const auto at = std::find(values.begin(), values.end(), value);
    const std::size_t g = static_cast<std::size_t>(at - values.begin());
    if (at == values.end()) {
      values.push_back(value);
      ids.emplace_back();
    }
    ids[g].push_back(run.id);
    const auto stored = repo_.findRun(run.id);
    if (!stored) continue;  // deleted meanwhile
    BandCurve curve = bandCurve(repo_.samples(run.id), format_.columns(), shearingStageNames(stored->scene), *quantity);
    curve.group = g;
    curves.push_back(std::move(curve));
  }
  const std::vector<double> grid = strainGrid(curves, kGridPoints);
  const std::vector<Band> bands = ensembleBands(curves, values.size(), grid, quantity->direction);

  nlohmann::json groups = nlohmann::json::array();
  for (std::size_t g = 0; g < values.size(); ++g) {
    groups.push_back({{"value", values[g]},
                      {"ids", ids[g]},
                      {"mean", bands[g].mean},
                      {"low", bands[g].low},
                      {"high", bands[g].high},
                      {"n", bands[g].n}});
  }
  const nlohmann::json out{
      {"study", name},
      {"quantity", quantity->key},
      {"title", quantity->title},
      {"group_by", group},
      {"paths", paths},
      {"runs", runs.size()},
      {"x", "axial_strain_percent"},
      {"interval", quantity->direction ? "circular" : "t"},
      {"grid", grid},
      {"groups", std::move(groups)},
  };
  // (NaN, a strain no run of a group reaches, is written as null)
  return out.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace grainlab::server
