#include "grainlab/report/figures.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "grainlab/report/findings.hpp"
#include "grainlab/report/markup.hpp"
#include "grainlab/report/rose_chart.hpp"
#include "grainlab/report/series_stats.hpp"
#include "grainlab/report/svg_chart.hpp"

namespace grainlab::report {
namespace {

using Pick = std::function<bool(const AssemblyResult&)>;

const std::vector<std::string>& terms() {
  static const std::vector<std::string> t{"c", "n", "t", "ln", "lt"};
  return t;
}

bool completed(const AssemblyResult& a) { return a.summary.status == "completed" && a.shearing.size() > 0; }

std::vector<const AssemblyResult*> pick(std::span<const AssemblyResult> runs, const Pick& wanted) {
  std::vector<const AssemblyResult*> out;
  for (const AssemblyResult& a : runs) {
    if (completed(a) && wanted(a)) out.push_back(&a);
  }
  return out;
}

std::vector<double> percent(const std::vector<double>& strain) {
  std::vector<double> out(strain);
  for (double& v : out) v *= 100;
  return out;
}

// θ_k where a_k ≥ 2× noise floor, NaN elsewhere: the charts draw no direction made of noise.
std::vector<double> meaningful(const AssemblyResult& a, const std::string& term) {
  const auto coef = a.shearing.column("a_" + term), theta = a.shearing.column("theta_" + term + "_deg"),
             contacts = a.shearing.column("contacts");
  std::vector<double> out(theta.size(), std::nan(""));
  for (size_t r = 0; r < theta.size(); ++r) {
    if (coef[r] >= kDirectionNoiseFactor * noiseFloor(contacts[r])) out[r] = theta[r];
  }
  return out;
}

// ω where φ_mob gives the stress a principal direction, NaN elsewhere.
std::vector<double> whereSheared(const AssemblyResult& a, const std::string& column) {
  const auto phi = a.shearing.column("phi_mob_deg"), v = a.shearing.column(column);
  std::vector<double> out(v.size(), std::nan(""));
  for (size_t r = 0; r < v.size(); ++r) {
    if (phi[r] >= criteria::kMinPhiMobDeg) out[r] = v[r];
  }
  return out;
}

FigurePanel panel(const ChartSpec& spec) {
  FigurePanel p;
  p.name = spec.id;
  p.inlineSvg = renderLineChart(spec, false);
  p.fileSvg = renderLineChart(spec, true);
  return p;
}

// Strain axes end where the test ends (20 %), not at the next whole tick beyond it.
FigurePanel strainPanel(ChartSpec spec) {
  double end = 0;
  for (const LineSeries& s : spec.series) {
    for (double x : s.x) {
      if (std::isfinite(x)) end = std::max(end, x);
    }
  }
  if (end > 0 && !spec.xMax) spec.xMax = end;
  return panel(spec);
}

ChartSpec strainChart(const std::string& id, const std::string& title, const std::string& yLabel) {
  ChartSpec c;
  c.id = id;
  c.title = title;
  c.xLabel = "axial strain ε22 (%)";
  c.yLabel = yLabel;
  c.xMin = 0;
  return c;
}

ChartSpec directionChart(const std::string& id, const std::string& title, const std::string& yLabel) {
  ChartSpec c = strainChart(id, title, yLabel);
  c.yMin = 0;
  c.yMax = 180;
  c.yReferences = {90};
  c.axialY = true;
  return c;
}

std::string termLabel(const std::string& term) { return term == "c" ? "c" : term; }

Figure stressAsymmetry(std::span<const AssemblyResult> runs) {
  Figure f;
  f.id = "fig06";
  f.title = "Fig. 6. σ12 − σ21 versus axial strain, bedding assemblies";
  f.caption = "The asymmetry of the contact stress σ_ij = (1/A) Σ f_i l_j during shearing; the paper finds it close "
              "to zero. CSV columns in Pa; asymmetry_over_p = |σ12 − σ21| / p.";
  f.data = CsvTable({"assembly", "bedding_deg", "axial_strain", "sigma12_minus_sigma21_pa", "p_pa", "asymmetry_over_p"});
  ChartSpec chart = strainChart("fig06", "σ12 − σ21 during shearing", "σ12 − σ21 (kPa)");
  chart.yReferences = {0};
  for (const AssemblyResult* a : pick(runs, [](const AssemblyResult& r) { return r.kind == AssemblyKind::Bedding; })) {
    const auto strain = a->shearing.column("axial_strain"), s12 = a->shearing.column("sigma12"),
               s21 = a->shearing.column("sigma21"), p = a->shearing.column("p");
    LineSeries line{a->label(), percent(strain), {}, "", false, false};
    for (size_t r = 0; r < strain.size(); ++r) {
      const double d = s12[r] - s21[r];
      f.data.addRow({a->preset, a->beddingDeg, strain[r], d, p[r], p[r] > 0 ? std::abs(d) / p[r] : std::nan("")});
      line.y.push_back(d / 1e3);
    }
    chart.series.push_back(std::move(line));
  }
  f.panels.push_back(strainPanel(chart));
  return f;
}

Figure anisotropyOf(std::span<const AssemblyResult> runs, AssemblyKind kind, const std::string& id, const std::string& who) {
  Figure f;
  f.id = id;
  f.title = "Fig. " + std::to_string(std::stoi(id.substr(3))) + ". Anisotropy coefficients and directions, " + who;
  f.caption = "(a) a_c, a_n, a_t, a_ln, a_lt and (b) θ_c, θ_n, θ_t, θ_ln, θ_lt during shearing. Directions are drawn "
              "only where their a_k is at least twice the noise floor 1.25·√(2/N_c) (noise_floor in the CSV); below "
              "it a direction means nothing.";
  std::vector<std::string> header{"assembly", "axial_strain", "contacts", "noise_floor"};
  for (const std::string& t : terms()) header.push_back("a_" + t);
  for (const std::string& t : terms()) header.push_back("theta_" + t + "_deg");
  f.data = CsvTable(header);
  ChartSpec coef = strainChart(id + "a", "(a) anisotropy coefficients", "a_k");
  coef.yMin = 0;
  ChartSpec dirs = directionChart(id + "b", "(b) principal directions", "θ_k (°)");
  for (const AssemblyResult* a : pick(runs, [kind](const AssemblyResult& r) { return r.kind == kind; })) {
    const auto strain = a->shearing.column("axial_strain"), contacts = a->shearing.column("contacts");
    for (size_t r = 0; r < strain.size(); ++r) {
      std::vector<CsvCell> row{a->preset, strain[r], contacts[r], noiseFloor(contacts[r])};
      for (const std::string& t : terms()) row.emplace_back(a->shearing.at("a_" + t, r));
      for (const std::string& t : terms()) row.emplace_back(a->shearing.at("theta_" + t + "_deg", r));
      f.data.addRow(std::move(row));
    }
    for (const std::string& t : terms()) {
      coef.series.push_back({"a_" + termLabel(t), percent(strain), a->shearing.column("a_" + t), "", false, false});
      dirs.series.push_back({"θ_" + termLabel(t), percent(strain), meaningful(*a, t), "", false, false});
    }
  }
  f.panels.push_back(strainPanel(coef));
  f.panels.push_back(strainPanel(dirs));
  return f;
}

Figure beddingTerm(std::span<const AssemblyResult> runs, int number, const std::string& term, const std::string& what) {
  Figure f;
  f.id = (number < 10 ? "fig0" : "fig") + std::to_string(number);
  f.title = "Fig. " + std::to_string(number) + ". " + what + " anisotropy versus axial strain for the bedding angles";
  f.caption = "(a) a_" + term + " and (b) θ_" + term + " during shearing for α = 0, 30, 60, 90°. θ_" + term +
              " is drawn only where a_" + term + " is at least twice the noise floor.";
  f.data = CsvTable({"assembly", "bedding_deg", "axial_strain", "contacts", "noise_floor", "a_" + term,
                     "theta_" + term + "_deg"});
  ChartSpec coef = strainChart(f.id + "a", "(a) a_" + term, "a_" + term);
  coef.yMin = 0;
  ChartSpec dirs = directionChart(f.id + "b", "(b) θ_" + term, "θ_" + term + " (°)");
  for (const AssemblyResult* a : pick(runs, [](const AssemblyResult& r) { return r.kind == AssemblyKind::Bedding; })) {
    const auto strain = a->shearing.column("axial_strain"), contacts = a->shearing.column("contacts");
    for (size_t r = 0; r < strain.size(); ++r) {
      f.data.addRow({a->preset, a->beddingDeg, strain[r], contacts[r], noiseFloor(contacts[r]),
                     a->shearing.at("a_" + term, r), a->shearing.at("theta_" + term + "_deg", r)});
    }
    coef.series.push_back({a->label(), percent(strain), a->shearing.column("a_" + term), "", false, false});
    dirs.series.push_back({a->label(), percent(strain), meaningful(*a, term), "", false, false});
  }
  f.panels.push_back(strainPanel(coef));
  f.panels.push_back(strainPanel(dirs));
  return f;
}

Figure omegaVersusPhi(std::span<const AssemblyResult> runs) {
  Figure f;
  f.id = "fig14";
  f.title = "Fig. 14. Non-coaxiality ω versus mobilised friction angle φ_mob";
  f.caption = "ω = θσ − 90° from the stress tensor against φ_mob, following each test in strain order (all six "
              "assemblies; the paper shows the anisotropic ones). Samples with φ_mob < " +
              fixed(criteria::kMinPhiMobDeg, 0) + "° are not drawn: there the stress is nearly isotropic and has no "
              "principal direction.";
  f.data = CsvTable({"assembly", "axial_strain", "phi_mob_deg", "omega_macro_deg"});
  ChartSpec chart;
  chart.id = "fig14";
  chart.title = "ω versus φ_mob";
  chart.xLabel = "φ_mob (°)";
  chart.yLabel = "ω (°)";
  chart.xMin = 0;
  chart.yReferences = {0};
  for (const AssemblyResult* a : pick(runs, [](const AssemblyResult&) { return true; })) {
    const auto strain = a->shearing.column("axial_strain"), phi = a->shearing.column("phi_mob_deg"),
               omega = a->shearing.column("omega_macro_deg");
    for (size_t r = 0; r < strain.size(); ++r) f.data.addRow({a->preset, strain[r], phi[r], omega[r]});
    chart.series.push_back({a->label(), phi, whereSheared(*a, "omega_macro_deg"), "", false, true});
  }
  f.panels.push_back(panel(chart));
  return f;
}

Figure omegaVersusStrain(std::span<const AssemblyResult> runs) {
  Figure f;
  f.id = "fig15";
  f.title = "Fig. 15. Non-coaxiality ω versus axial strain: stress tensor and Eqs. (7), (10), (11)";
  f.caption = "ω from the stress tensor (θσ = ½ atan2(σ12 + σ21, σ11 − σ22)) and from the fabric by Eq. (7) (all five "
              "terms), Eq. (10) (unweighted mean of θ_c, θ_n, θ_t) and Eq. (11) (Eq. 7 without the ln and lt terms), "
              "one panel per assembly. Samples with φ_mob < " + fixed(criteria::kMinPhiMobDeg, 0) +
              "° are not drawn.";
  f.data = CsvTable({"assembly", "axial_strain", "phi_mob_deg", "omega_macro_deg", "omega_eq7_deg", "omega_eq10_deg",
                     "omega_eq11_deg"});
  int index = 0;
  for (const AssemblyResult* a : pick(runs, [](const AssemblyResult&) { return true; })) {
    const auto strain = a->shearing.column("axial_strain");
    for (size_t r = 0; r < strain.size(); ++r) {
      f.data.addRow({a->preset, strain[r], a->shearing.at("phi_mob_deg", r), a->shearing.at("omega_macro_deg", r),
                     a->shearing.at("omega_micro_deg", r), a->shearing.at("omega_eq10_deg", r),
                     a->shearing.at("omega_eq11_deg", r)});
    }
    const char letter = static_cast<char>('a' + index++);
    ChartSpec chart = strainChart("fig15" + std::string(1, letter), "(" + std::string(1, letter) + ") " + a->label(), "ω (°)");
    chart.yReferences = {0};
    const auto x = percent(strain);
    chart.series.push_back({"stress", x, whereSheared(*a, "omega_macro_deg"), "#000000", false, true});
    chart.series.push_back({"Eq. (7)", x, whereSheared(*a, "omega_micro_deg"), "#D55E00", false, false});
    chart.series.push_back({"Eq. (10)", x, whereSheared(*a, "omega_eq10_deg"), "#009E73", true, false});
    chart.series.push_back({"Eq. (11)", x, whereSheared(*a, "omega_eq11_deg"), "#0072B2", true, false});
    f.panels.push_back(strainPanel(chart));
  }
  return f;
}

Figure roses(std::span<const AssemblyResult> runs) {
  Figure f;
  f.id = "roses";
  f.title = "Rose diagrams at 0 %, 5 % and 20 % axial strain";
  f.caption = "Polar histograms of the contact normals (relative density, mean 1) and of the mean normal and tangential "
              "contact forces per direction (N/m), from the sample nearest each strain, mirrored over the full circle; "
              "the black curve is the fitted c0 + c1 cos 2θ + c2 sin 2θ. Negative mean f_t is drawn by its magnitude, "
              "dashed. The number at the top right of each rose is the value of its outer ring.";
  f.data = CsvTable({"assembly", "target_strain", "axial_strain", "bin", "bin_centre_deg", "count", "density",
                     "fn_mean", "ft_mean", "density_fit", "fn_fit", "ft_fit"});
  for (const AssemblyResult* a : pick(runs, [](const AssemblyResult&) { return true; })) {
    std::vector<const analysis::PolarHistograms*> snapshots;
    std::vector<std::string> captions;
    for (const RoseSnapshot& s : a->roses) {
      snapshots.push_back(s.histograms ? &*s.histograms : nullptr);
      captions.push_back("ε22 = " + fixed(s.axialStrain * 100, 1) + " %");
      if (!s.histograms) continue;
      const analysis::PolarHistograms& h = *s.histograms;
      const auto density = roseBinValues(h, RoseQuantity::Normals), fn = roseBinValues(h, RoseQuantity::NormalForce),
                 ft = roseBinValues(h, RoseQuantity::TangentialForce);
      for (int b = 0; b < h.bins; ++b) {
        const double centre = h.binCentreDeg(b);
        const size_t k = static_cast<size_t>(b);
        f.data.addRow({a->preset, s.targetStrain, s.axialStrain, b, centre, static_cast<double>(h.count[k]), density[k],
                       fn[k], ft[k], roseFitValue(h, RoseQuantity::Normals, centre),
                       roseFitValue(h, RoseQuantity::NormalForce, centre),
                       roseFitValue(h, RoseQuantity::TangentialForce, centre)});
      }
    }
    const std::string id = "roses-" + a->preset;
    const std::string title = "Rose diagrams, " + a->label();
    f.panels.push_back({id, renderRoseGrid(id, title, snapshots, captions, false),
                        renderRoseGrid(id, title, snapshots, captions, true)});
  }
  return f;
}

}  // namespace

std::vector<Figure> paperFigures(std::span<const AssemblyResult> runs) {
  std::vector<Figure> figures;
  figures.push_back(stressAsymmetry(runs));
  figures.push_back(anisotropyOf(runs, AssemblyKind::Circular, "fig07", "circular particles"));
  figures.push_back(anisotropyOf(runs, AssemblyKind::Random, "fig08", "randomly oriented elongated particles"));
  figures.push_back(beddingTerm(runs, 9, "c", "Contact normal"));
  figures.push_back(beddingTerm(runs, 10, "n", "Normal contact force"));
  figures.push_back(beddingTerm(runs, 11, "t", "Tangential contact force"));
  figures.push_back(beddingTerm(runs, 12, "ln", "Normal branch vector"));
  figures.push_back(beddingTerm(runs, 13, "lt", "Tangential branch vector"));
  figures.push_back(omegaVersusPhi(runs));
  figures.push_back(omegaVersusStrain(runs));
  figures.push_back(roses(runs));
  return figures;
}

}  // namespace grainlab::report
