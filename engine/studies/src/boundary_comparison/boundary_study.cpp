#include "grainlab/studies/boundary_comparison/boundary_study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "grainlab/errors.hpp"
#include "grainlab/studies/boundary_comparison/run_profile.hpp"
#include "grainlab/studies/paper/csv_table.hpp"
#include "grainlab/studies/paper/parallel_runs.hpp"
#include "grainlab/studies/paper/run_loader.hpp"
#include "grainlab/studies/paper/run_plan.hpp"
#include "grainlab/studies/tradeoff/ensemble_quantities.hpp"
#include "grainlab/studies/tradeoff/paired_bias.hpp"

namespace grainlab::boundaries {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct NamedQuantity {
  std::string name;
  bool axial = false;
};

// Where φ_mob peaks and the trade-off's quantities (tradeoff/ensemble_quantities.hpp), then
// the packing each boundary consolidates to.
const std::vector<NamedQuantity>& quantities() {
  static const std::vector<NamedQuantity> q = [] {
    std::vector<NamedQuantity> all{{"peak_phi_mob_deg", false}, {"axial_strain_at_peak", false}, {"a_c_at_peak", false}};
    for (const tradeoff::Quantity& e : tradeoff::ensembleQuantities())
      if (e.name != "peak_phi_mob_deg") all.push_back({e.name, e.axial});
    all.push_back({"void_ratio_consolidated", false});
    return all;
  }();
  return q;
}

struct RunSpec {
  Boundary boundary;
  std::string assembly;
  int seed;
};

struct RunValues {
  std::string status;
  std::vector<double> values;                  // by quantities()
  std::vector<std::vector<double>> curves;     // by curveColumns(), on the grid
};

RunValues measure(const report::AssemblyResult& run, const std::vector<double>& grid) {
  RunValues r;
  r.status = std::string(toString(run.summary.status));
  const PeakPoint peak = peakOf(run.shearing);
  r.values = {run.summary.peakPhiMobDeg, peak.axialStrain, peak.aC};
  const std::vector<double> rest = tradeoff::measureQuantities(run.shearing, run.summary.peakPhiMobDeg);
  r.values.insert(r.values.end(), rest.begin() + 1, rest.end());
  const double e0 = run.summary.voidRatioAfterConsolidation;
  r.values.push_back(e0 >= 0 ? e0 : kNaN);
  for (const CurveColumn& c : curveColumns()) r.curves.push_back(curveAt(run.shearing, c, grid));
  return r;
}

// θσ lies near the vertical (90°) in a biaxial test, ω near 0.
report::MeanInterval ensembleMean(const std::vector<double>& values, const std::string& name, bool axial) {
  if (!axial) return report::meanInterval(values);
  return report::axialMeanIntervalNear(values, name.starts_with("theta_sigma_") ? 90.0 : 0.0);
}

}  // namespace

std::vector<std::string> boundaryQuantityNames() {
  std::vector<std::string> names;
  for (const NamedQuantity& q : quantities()) names.push_back(q.name);
  return names;
}

BoundaryStudy runBoundaryStudy(const BoundaryStudyOptions& opt, std::ostream* progress) {
  if (opt.outDir.empty()) throw SceneError("--out", "give the directory the study writes (and resumes) in");
  if (opt.seeds < 2) throw SceneError("--seeds", "an interval needs 2 seeds or more");
  if (opt.axialStrain < 0 || !std::isfinite(opt.axialStrain))
    throw SceneError("--axial-strain", "must be a positive strain (or 0 for the presets' own)");
  const std::vector<std::string> assemblies = opt.assemblies.empty() ? boundaryAssemblies() : opt.assemblies;
  for (const std::string& a : assemblies)
    if (std::find(boundaryAssemblies().begin(), boundaryAssemblies().end(), a) == boundaryAssemblies().end())
      throw SceneError("--assemblies", "\"" + a + "\" is not one of circular, bedding-30");
  std::vector<Boundary> boundaries{Boundary::Ring};  // the reference, first
  for (Boundary b : opt.boundaries.empty() ? std::vector<Boundary>{Boundary::Cell, Boundary::CellMatched} : opt.boundaries)
    if (std::find(boundaries.begin(), boundaries.end(), b) == boundaries.end()) boundaries.push_back(b);

  // Planned longest first: the bedded hexagons, then the discs.
  std::vector<RunSpec> specs;
  std::vector<report::PlannedRun> plan;
  const fs::path dir = opt.outDir;
  for (auto a = assemblies.rbegin(); a != assemblies.rend(); ++a)
    for (Boundary b : boundaries)
      for (int seed = 1; seed <= opt.seeds; ++seed) {
        specs.push_back({b, *a, seed});
        const std::string preset = boundaryPreset(b, *a, opt.quick);
        const std::string id = boundaryName(b) + "-" + preset + "/seed-" + std::to_string(seed);
        plan.push_back({id, preset, seed, (dir / "runs" / id).string(),
                        boundaryScene(b, *a, opt.quick, seed, opt.axialStrain)});
      }
  fs::create_directories(dir / "runs");
  const std::vector<RunSummary> summaries = report::executeRuns(plan, opt.jobs, progress);

  const double end = opt.axialStrain > 0 ? opt.axialStrain : 0.2;
  const std::vector<double> grid = strainGrid(opt.curveStep, end);
  std::vector<RunValues> runs;
  BoundaryStudy study;
  study.runs = plan.size();
  for (size_t k = 0; k < plan.size(); ++k) {
    RunValues r;
    if (summaries[k].status == RunStatus::Completed) {
      r = measure(report::loadAssemblyResult(plan[k].dir, plan[k].preset), grid);
    } else {
      r.status = std::string(toString(summaries[k].status));
      r.values.assign(quantities().size(), kNaN);
      r.curves.assign(curveColumns().size(), std::vector<double>(grid.size(), kNaN));
      ++study.failedRuns;
    }
    runs.push_back(std::move(r));
  }

  auto ensemble = [&](Boundary b, const std::string& a) {
    std::vector<const RunValues*> out;
    for (size_t k = 0; k < specs.size(); ++k)
      if (specs[k].boundary == b && specs[k].assembly == a) out.push_back(&runs[k]);
    return out;
  };
  auto column = [](const std::vector<const RunValues*>& ens, size_t q) {
    std::vector<double> v;
    for (const RunValues* r : ens) v.push_back(r->values[q]);
    return v;
  };

  const std::string size = opt.quick ? "quick" : "full";
  report::CsvTable table({"size", "assembly", "boundary", "preset", "quantity", "seeds", "mean", "mean_ci_low",
                          "mean_ci_high", "sd", "ring_seeds", "ring_mean", "difference", "difference_ci_low",
                          "difference_ci_high", "welch_t", "resolved", "failed_runs"});
  report::CsvTable curves({"size", "assembly", "boundary", "quantity", "axial_strain", "seeds", "mean", "ci_low", "ci_high"});
  for (const std::string& a : assemblies) {
    const std::vector<const RunValues*> ring = ensemble(Boundary::Ring, a);
    for (Boundary b : boundaries) {
      const std::vector<const RunValues*> ens = ensemble(b, a);
      int failed = 0;
      for (const RunValues* r : ens) failed += r->status != "completed";
      for (size_t q = 0; q < quantities().size(); ++q) {
        const NamedQuantity& qu = quantities()[q];
        const std::vector<double> values = column(ens, q), ringValues = column(ring, q);
        const report::MeanInterval ringMean = ensembleMean(ringValues, qu.name, qu.axial);
        const report::MeanInterval mean =
            qu.axial ? report::axialMeanIntervalNear(values, ringMean.mean) : report::meanInterval(values);
        const bool isRing = b == Boundary::Ring;
        const tradeoff::BiasEstimate d =
            isRing ? tradeoff::BiasEstimate{} : tradeoff::unpairedBias(values, ringValues, 1.0, qu.axial);
        std::string resolved;
        if (!isRing)
          resolved = !(std::isfinite(d.low) && std::isfinite(d.high)) ? "no interval"
                     : d.low > 0 || d.high < 0                       ? "yes"
                                                                     : "not resolved at " + std::to_string(d.seeds) + " seeds";
        table.addRow({size, a, boundaryName(b), boundaryPreset(b, a, opt.quick), qu.name, mean.n, mean.mean, mean.low,
                      mean.high, qu.axial ? kNaN : mean.sd, ringMean.n, ringMean.mean, d.bias, d.low, d.high, d.t,
                      isRing ? std::string("reference") : resolved, failed});
      }
      for (size_t c = 0; c < curveColumns().size(); ++c) {
        const CurveColumn& col = curveColumns()[c];
        EnsembleCurve curve{a, boundaryName(b), col.name, grid, {}};
        for (size_t g = 0; g < grid.size(); ++g) {
          std::vector<double> at;
          for (const RunValues* r : ens) at.push_back(r->curves[c][g]);
          const report::MeanInterval m = ensembleMean(at, col.name, col.axial);
          curve.stats.push_back(m);
          curves.addRow({size, a, boundaryName(b), col.name, grid[g], m.n, m.mean, m.low, m.high});
        }
        study.curves.push_back(std::move(curve));
      }
    }
  }
  table.write((dir / "boundaries.csv").string());
  curves.write((dir / "curves.csv").string());

  std::vector<std::string> header{"size", "assembly", "boundary", "preset", "seed", "status"};
  for (const NamedQuantity& q : quantities()) header.push_back(q.name);
  report::CsvTable runsTable(header);
  for (size_t k = 0; k < specs.size(); ++k) {
    std::vector<report::CsvCell> row{size, specs[k].assembly, boundaryName(specs[k].boundary), plan[k].preset,
                                     specs[k].seed, runs[k].status};
    for (double v : runs[k].values) row.emplace_back(v);
    runsTable.addRow(row);
  }
  runsTable.write((dir / "runs.csv").string());
  return study;
}

}  // namespace grainlab::boundaries
