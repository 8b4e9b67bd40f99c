#include "grainlab/studies/tradeoff/ensemble_plan.hpp"

#include <cstdio>
#include <stdexcept>

#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"

namespace grainlab::tradeoff {
namespace {

// The setting's scene for one seed; the strain rate is the one that gives the setting's inertial
// number on that seed's specimen.
nlohmann::json seedScene(const Setting& s, int seed) {
  nlohmann::json scene = settingScene(s);
  scene["seed"] = seed;
  scene["name"] = scene["name"].get<std::string>() + ", seed " + std::to_string(seed);
  const double rate = strainRateFor(scene, s.inertialNumber);
  for (nlohmann::json& stage : scene["stages"])
    if (stage.value("type", "") == "biaxial") stage["strain_rate"] = rate;
  return scene;
}

// Only the shearing changes: the setting can shear the reference's specimen.
bool shearingOnly(const Setting& s, const Setting& reference) {
  return s.engine == reference.engine && s.vertices == reference.vertices &&
         s.velocityIterations == reference.velocityIterations;
}

}  // namespace

size_t EnsemblePlan::referenceRun(size_t r) const {
  size_t ref = 0;
  while (!(settings[runSetting[ref]].preset == settings[runSetting[r]].preset &&
           settings[runSetting[ref]].axis == "reference"))
    ++ref;
  return ref;
}

EnsemblePlan planEnsemble(const TradeoffOptions& opt) {
  SweepPlan sweep = opt.quick ? quickPlan() : fullPlan();
  if (!opt.presets.empty()) sweep.presets = opt.presets;
  if (!opt.axes.empty()) keepAxes(sweep, opt.axes);
  for (const std::string& p : sweep.presets) presetScene(p);  // an unknown preset fails here
  EnsemblePlan plan;
  plan.presets = sweep.presets;
  plan.seeds = opt.seeds;
  plan.settings = expandPlan(sweep, box2dRefusal(sweep.presets.front()));
  // Distinct runs (the baseline sits on every axis but runs once per seed).
  plan.runOf.resize(plan.settings.size());
  for (size_t k = 0; k < plan.settings.size(); ++k) {
    size_t r = 0;
    while (r < plan.runSetting.size() && !plan.settings[plan.runSetting[r]].sameRun(plan.settings[k])) ++r;
    if (r == plan.runSetting.size()) plan.runSetting.push_back(k);
    plan.runOf[k] = r;
  }
  plan.paired.resize(plan.runSetting.size());
  for (size_t r = 0; r < plan.runSetting.size(); ++r)
    plan.paired[r] = shearingOnly(plan.settings[plan.runSetting[r]], plan.settings[plan.runSetting[plan.referenceRun(r)]]);
  return plan;
}

std::vector<EnsembleRun> ensembleRuns(const EnsemblePlan& plan, bool preparing) {
  std::vector<EnsembleRun> runs;
  for (size_t r = 0; r < plan.runSetting.size(); ++r) {
    const Setting& s = plan.settings[plan.runSetting[r]];
    if ((s.axis == "reference") != preparing) continue;
    for (int seed = 1; seed <= plan.seeds; ++seed) {
      EnsembleRun run;
      run.run = r;
      run.seed = seed;
      run.preparing = preparing;
      run.paired = !preparing && plan.paired[r];
      run.scene = seedScene(s, seed);
      if (preparing) run.scene["output"]["stage_checkpoints"] = true;
      run.name = s.preset + " " + s.axis + " " + s.value + " seed " + std::to_string(seed);
      char file[48];
      std::snprintf(file, sizeof file, "run-%02zu-seed-%d.json", r, seed);
      run.file = file;
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

std::string preparedStage(const std::string& preset) {
  const Scene scene = parseScene(presetScene(preset));
  for (size_t k = 1; k < scene.stages.size(); ++k)
    if (isShearing(scene.stages[k].type)) return scene.stages[k - 1].name;
  throw std::runtime_error(preset + ": no shearing stage after a preparation");
}

}  // namespace grainlab::tradeoff
