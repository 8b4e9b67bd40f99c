#include "grainlab/studies/draw/figures.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "grainlab/studies/paper/ensemble_series.hpp"
#include "grainlab/studies/paper/findings.hpp"
#include "grainlab/studies/paper/number_text.hpp"
#include "grainlab/studies/draw/rose_chart.hpp"
#include "grainlab/studies/paper/series_stats.hpp"
#include "grainlab/studies/draw/svg_chart.hpp"

namespace grainlab::report {
namespace {

const std::vector<std::string>& terms() {
  static const std::vector<std::string> t{"c", "n", "t", "ln", "lt"};
  return t;
}

using Values = std::function<std::vector<double>(const AssemblyResult&)>;

// One plotted quantity: a name (the CSV's column stem), how to read it from a run, and how to
// average it over seeds.
struct Quantity {
  std::string name;
  Values values;
  bool axial = false;   // a direction: averaged on 2θ
  bool quorum = false;  // drawn only where at least half the seeds measured it
};

Quantity column(const std::string& name) {
  return {name, [name](const AssemblyResult& a) { return a.shearing.column(name); }, false, false};
}

std::vector<const Ensemble*> pick(const std::vector<Ensemble>& all, const std::function<bool(const Ensemble&)>& wanted) {
  std::vector<const Ensemble*> out;
  for (const Ensemble& e : all) {
    if (!e.runs.empty() && wanted(e)) out.push_back(&e);
  }
  return out;
}

std::vector<double> percent(const std::vector<double>& strain) {
  std::vector<double> out(strain);
  for (double& v : out) v *= 100;
  return out;
}

std::vector<double> scaled(std::vector<double> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
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

Quantity direction(const std::string& term) {
  return {"theta_" + term + "_deg", [term](const AssemblyResult& a) { return meaningful(a, term); }, true, true};
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

Quantity sheared(const std::string& name) {
  return {name, [name](const AssemblyResult& a) { return whereSheared(a, name); }, false, true};
}

Quantity noiseFloorQuantity() {
  return {"noise_floor", [](const AssemblyResult& a) {
            auto v = a.shearing.column("contacts");
            for (double& c : v) c = noiseFloor(c);
            return v;
          }};
}

// The CSV behind a figure: one row per assembly and strain of its common strain axis, with
// each quantity's mean over the seeds and the 95 % interval of that mean.
std::vector<std::string> ensembleHeader(bool bedding, const std::vector<Quantity>& quantities) {
  std::vector<std::string> h{"assembly"};
  if (bedding) h.push_back("bedding_deg");
  h.push_back("seeds");
  h.push_back("axial_strain");
  for (const Quantity& q : quantities) {
    h.push_back(q.name + "_mean");
    h.push_back(q.name + "_ci_low");
    h.push_back(q.name + "_ci_high");
  }
  return h;
}

std::vector<EnsembleBand> bandsOf(const Ensemble& e, const std::vector<Quantity>& quantities) {
  std::vector<EnsembleBand> bands;
  for (const Quantity& q : quantities) bands.push_back(ensembleBand(e, q.values, q.axial, q.quorum));
  return bands;
}

void addEnsembleRows(CsvTable& t, const Ensemble& e, bool bedding, const std::vector<EnsembleBand>& bands) {
  if (bands.empty()) return;
  for (size_t k = 0; k < bands.front().strain.size(); ++k) {
    std::vector<CsvCell> row{e.preset};
    if (bedding) row.emplace_back(e.beddingDeg);
    row.emplace_back(static_cast<int>(e.runs.size()));
    row.emplace_back(bands.front().strain[k]);
    for (const EnsembleBand& b : bands) {
      row.emplace_back(b.stats[k].mean);
      row.emplace_back(b.stats[k].low);
      row.emplace_back(b.stats[k].high);
    }
    t.addRow(std::move(row));
  }
}

// The ensemble on a chart: each seed's run thin and pale, then the mean with its 95 % band
// (`spread` false: the mean alone).
void drawBand(ChartSpec& chart, const std::string& label, const std::string& colour, const EnsembleBand& b,
              double yFactor = 1, bool dashed = false, bool markers = false, bool spread = true) {
  const auto x = percent(b.strain);
  if (spread && b.perRun.size() > 1) {
    for (const auto& run : b.perRun) {
      LineSeries faint{"", x, scaled(run, yFactor), colour, false, false};
      faint.faint = true;
      chart.series.push_back(std::move(faint));
    }
  }
  LineSeries mean{label, x, scaled(b.mean(), yFactor), colour, dashed, markers};
  if (spread) {
    mean.low = scaled(b.low(), yFactor);
    mean.high = scaled(b.high(), yFactor);
  }
  chart.series.push_back(std::move(mean));
}

std::string seedsText(const std::vector<const Ensemble*>& chosen) {
  size_t lo = 0, hi = 0;
  for (const Ensemble* e : chosen) {
    lo = lo ? std::min(lo, e->runs.size()) : e->runs.size();
    hi = std::max(hi, e->runs.size());
  }
  if (hi <= 1) return " One seed per assembly: no interval is drawn.";
  return " Each line is the mean over " + (lo == hi ? std::to_string(hi) : std::to_string(lo) + "-" + std::to_string(hi)) +
         " seeds (different random packings), the shading its 95 % interval (circular for directions), the pale lines the single runs.";
}

const std::string kBandCsv = " The CSV holds, per assembly and strain, each quantity's mean over the seeds and its 95 % "
                             "interval (_mean, _ci_low, _ci_high); each seed's own series is in runs/<preset>/seed-<s>/.";

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

bool isBeddingEnsemble(const Ensemble& e) { return e.kind == AssemblyKind::Bedding; }

Figure stressAsymmetry(const std::vector<Ensemble>& all) {
  Figure f;
  f.id = "fig06";
  f.title = "Fig. 6. σ12 − σ21 versus axial strain, bedding assemblies";
  const auto chosen = pick(all, isBeddingEnsemble);
  f.caption = "The asymmetry of the contact stress σ_ij = (1/A) Σ f_i l_j during shearing; the paper finds it close "
              "to zero. CSV columns in Pa; asymmetry_over_p = |σ12 − σ21| / p." + seedsText(chosen) + kBandCsv;
  const std::vector<Quantity> quantities{
      {"sigma12_minus_sigma21_pa",
       [](const AssemblyResult& a) {
         auto d = a.shearing.column("sigma12");
         const auto s21 = a.shearing.column("sigma21");
         for (size_t r = 0; r < d.size(); ++r) d[r] -= s21[r];
         return d;
       }},
      column("p"),
      {"asymmetry_over_p", [](const AssemblyResult& a) {
         const auto s12 = a.shearing.column("sigma12"), s21 = a.shearing.column("sigma21"), p = a.shearing.column("p");
         std::vector<double> v(p.size(), std::nan(""));
         for (size_t r = 0; r < p.size(); ++r) {
           if (p[r] > 0) v[r] = std::abs(s12[r] - s21[r]) / p[r];
         }
         return v;
       }}};
  f.data = CsvTable(ensembleHeader(true, quantities));
  ChartSpec chart = strainChart("fig06", "σ12 − σ21 during shearing", "σ12 − σ21 (kPa)");
  chart.yReferences = {0};
  for (size_t i = 0; i < chosen.size(); ++i) {
    const auto bands = bandsOf(*chosen[i], quantities);
    addEnsembleRows(f.data, *chosen[i], true, bands);
    drawBand(chart, chosen[i]->label(), paletteColour(i), bands[0], 1e-3);
  }
  f.panels.push_back(strainPanel(chart));
  return f;
}

Figure anisotropyOf(const std::vector<Ensemble>& all, AssemblyKind kind, const std::string& id, const std::string& who) {
  Figure f;
  f.id = id;
  f.title = "Fig. " + std::to_string(std::stoi(id.substr(3))) + ". Anisotropy coefficients and directions, " + who;
  const auto chosen = pick(all, [kind](const Ensemble& e) { return e.kind == kind; });
  f.caption = "(a) a_c, a_n, a_t, a_ln, a_lt and (b) θ_c, θ_n, θ_t, θ_ln, θ_lt during shearing. A run's direction "
              "counts only where its a_k is at least twice the noise floor 1.25·√(2/N_c) (noise_floor in the CSV); "
              "below it a direction means nothing, and a mean direction is drawn only where at least half the seeds "
              "have a meaningful one." + seedsText(chosen) + kBandCsv;
  std::vector<Quantity> quantities{column("contacts"), noiseFloorQuantity()};
  for (const std::string& t : terms()) quantities.push_back(column("a_" + t));
  for (const std::string& t : terms()) quantities.push_back(direction(t));
  f.data = CsvTable(ensembleHeader(false, quantities));
  ChartSpec coef = strainChart(id + "a", "(a) anisotropy coefficients", "a_k");
  coef.yMin = 0;
  ChartSpec dirs = directionChart(id + "b", "(b) principal directions", "θ_k (°)");
  for (const Ensemble* e : chosen) {
    const auto bands = bandsOf(*e, quantities);
    addEnsembleRows(f.data, *e, false, bands);
    for (size_t k = 0; k < terms().size(); ++k) {
      drawBand(coef, "a_" + terms()[k], paletteColour(k), bands[2 + k]);
      drawBand(dirs, "θ_" + terms()[k], paletteColour(k), bands[2 + terms().size() + k]);
    }
  }
  f.panels.push_back(strainPanel(coef));
  f.panels.push_back(strainPanel(dirs));
  return f;
}

Figure beddingTerm(const std::vector<Ensemble>& all, int number, const std::string& term, const std::string& what) {
  Figure f;
  f.id = (number < 10 ? "fig0" : "fig") + std::to_string(number);
  f.title = "Fig. " + std::to_string(number) + ". " + what + " anisotropy versus axial strain for the bedding angles";
  const auto chosen = pick(all, isBeddingEnsemble);
  f.caption = "(a) a_" + term + " and (b) θ_" + term + " during shearing for α = 0, 30, 60, 90°. A run's θ_" + term +
              " counts only where its a_" + term + " is at least twice the noise floor; a mean direction is drawn "
              "only where at least half the seeds have a meaningful one." + seedsText(chosen) + kBandCsv;
  const std::vector<Quantity> quantities{column("contacts"), noiseFloorQuantity(), column("a_" + term), direction(term)};
  f.data = CsvTable(ensembleHeader(true, quantities));
  ChartSpec coef = strainChart(f.id + "a", "(a) a_" + term, "a_" + term);
  coef.yMin = 0;
  ChartSpec dirs = directionChart(f.id + "b", "(b) θ_" + term, "θ_" + term + " (°)");
  for (size_t i = 0; i < chosen.size(); ++i) {
    const auto bands = bandsOf(*chosen[i], quantities);
    addEnsembleRows(f.data, *chosen[i], true, bands);
    drawBand(coef, chosen[i]->label(), paletteColour(i), bands[2]);
    drawBand(dirs, chosen[i]->label(), paletteColour(i), bands[3]);
  }
  f.panels.push_back(strainPanel(coef));
  f.panels.push_back(strainPanel(dirs));
  return f;
}

Figure omegaVersusPhi(const std::vector<Ensemble>& all) {
  Figure f;
  f.id = "fig14";
  f.title = "Fig. 14. Non-coaxiality ω versus mobilised friction angle φ_mob";
  const auto chosen = pick(all, [](const Ensemble&) { return true; });
  f.caption = "ω = θσ − 90° from the stress tensor against φ_mob, following each test in strain order (all six "
              "assemblies; the paper shows the anisotropic ones): the mean ω over the seeds with its 95 % band, "
              "against the mean φ_mob at the same strain. Samples with φ_mob < " +
              fixed(criteria::kMinPhiMobDeg, 0) + "° are not drawn: there the stress is nearly isotropic and has no "
              "principal direction." + seedsText(chosen) + kBandCsv;
  const std::vector<Quantity> quantities{column("phi_mob_deg"), sheared("omega_macro_deg")};
  f.data = CsvTable(ensembleHeader(false, quantities));
  ChartSpec chart;
  chart.id = "fig14";
  chart.title = "ω versus φ_mob";
  chart.xLabel = "φ_mob (°)";
  chart.yLabel = "ω (°)";
  chart.xMin = 0;
  chart.yReferences = {0};
  for (size_t i = 0; i < chosen.size(); ++i) {
    const auto bands = bandsOf(*chosen[i], quantities);
    addEnsembleRows(f.data, *chosen[i], false, bands);
    LineSeries line{chosen[i]->label(), bands[0].mean(), bands[1].mean(), paletteColour(i), false, true};
    line.low = bands[1].low();
    line.high = bands[1].high();
    chart.series.push_back(std::move(line));
  }
  f.panels.push_back(panel(chart));
  return f;
}

Figure omegaVersusStrain(const std::vector<Ensemble>& all) {
  Figure f;
  f.id = "fig15";
  f.title = "Fig. 15. Non-coaxiality ω versus axial strain: stress tensor and Eqs. (7), (10), (11)";
  const auto chosen = pick(all, [](const Ensemble&) { return true; });
  f.caption = "ω from the stress tensor (θσ = ½ atan2(σ12 + σ21, σ11 − σ22)) and from the fabric by Eq. (7) (all five "
              "terms), Eq. (10) (unweighted mean of θ_c, θ_n, θ_t) and Eq. (11) (Eq. 7 without the ln and lt terms), "
              "one panel per assembly; the band and the pale single runs are the stress tensor's. Samples with "
              "φ_mob < " + fixed(criteria::kMinPhiMobDeg, 0) + "° are not drawn." + seedsText(chosen) + kBandCsv;
  const std::vector<Quantity> quantities{column("phi_mob_deg"), sheared("omega_macro_deg"), sheared("omega_micro_deg"),
                                         sheared("omega_eq10_deg"), sheared("omega_eq11_deg")};
  std::vector<std::string> header = ensembleHeader(false, quantities);
  // The CSV keeps the paper's names for the equations' columns.
  for (std::string& h : header) {
    if (h.starts_with("omega_micro_deg")) h.replace(0, 15, "omega_eq7_deg");
  }
  f.data = CsvTable(header);
  int index = 0;
  for (const Ensemble* e : chosen) {
    const auto bands = bandsOf(*e, quantities);
    addEnsembleRows(f.data, *e, false, bands);
    const char letter = static_cast<char>('a' + index++);
    ChartSpec chart = strainChart("fig15" + std::string(1, letter), "(" + std::string(1, letter) + ") " + e->label(), "ω (°)");
    chart.yReferences = {0};
    // Only the stress tensor's ω has its band and runs: four overlapping bands would hide each other.
    drawBand(chart, "stress", "#000000", bands[1], 1, false, true);
    drawBand(chart, "Eq. (7)", "#D55E00", bands[2], 1, false, false, false);
    drawBand(chart, "Eq. (10)", "#009E73", bands[3], 1, true, false, false);
    drawBand(chart, "Eq. (11)", "#0072B2", bands[4], 1, true, false, false);
    f.panels.push_back(strainPanel(chart));
  }
  return f;
}

Figure roses(const std::vector<Ensemble>& all) {
  Figure f;
  f.id = "roses";
  f.title = "Rose diagrams at 0 %, 5 % and 20 % axial strain";
  f.caption = "Polar histograms of the contact normals (relative density, mean 1) and of the mean normal and tangential "
              "contact forces per direction (N/m), from the sample nearest each strain, mirrored over the full circle; "
              "the black curve is the fitted c0 + c1 cos 2θ + c2 sin 2θ. Negative mean f_t is drawn by its magnitude, "
              "dashed. The number at the top right of each rose is the value of its outer ring.";
  f.data = CsvTable({"assembly", "target_strain", "axial_strain", "bin", "bin_centre_deg", "count", "density",
                     "fn_mean", "ft_mean", "density_fit", "fn_fit", "ft_fit"});
  for (const Ensemble* e : pick(all, [](const Ensemble&) { return true; })) {
    // One packing's roses: the lowest seed's. Histograms of different packings are not averaged.
    const AssemblyResult* a = e->runs.front();
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
    const std::string title = "Rose diagrams, " + a->label() + (e->runs.size() > 1 ? ", seed " + std::to_string(a->seed) : "");
    f.panels.push_back({id, renderRoseGrid(id, title, snapshots, captions, false),
                        renderRoseGrid(id, title, snapshots, captions, true)});
  }
  return f;
}

}  // namespace

std::vector<Figure> paperFigures(std::span<const AssemblyResult> runs) {
  const std::vector<Ensemble> all = groupEnsembles(runs);
  std::vector<Figure> figures;
  figures.push_back(stressAsymmetry(all));
  figures.push_back(anisotropyOf(all, AssemblyKind::Circular, "fig07", "circular particles"));
  figures.push_back(anisotropyOf(all, AssemblyKind::Random, "fig08", "randomly oriented elongated particles"));
  figures.push_back(beddingTerm(all, 9, "c", "Contact normal"));
  figures.push_back(beddingTerm(all, 10, "n", "Normal contact force"));
  figures.push_back(beddingTerm(all, 11, "t", "Tangential contact force"));
  figures.push_back(beddingTerm(all, 12, "ln", "Normal branch vector"));
  figures.push_back(beddingTerm(all, 13, "lt", "Tangential branch vector"));
  figures.push_back(omegaVersusPhi(all));
  figures.push_back(omegaVersusStrain(all));
  figures.push_back(roses(all));
  return figures;
}

}  // namespace grainlab::report
