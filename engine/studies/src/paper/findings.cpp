#include "grainlab/studies/paper/findings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/math.hpp"
#include "grainlab/studies/paper/ensemble_stats.hpp"
#include "grainlab/studies/paper/number_text.hpp"
#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::report {
namespace {

using namespace criteria;

bool usable(const AssemblyResult& a) { return a.summary.status == RunStatus::Completed && a.shearing.size() >= 2; }

std::vector<const AssemblyResult*> select(std::span<const AssemblyResult> runs, bool (*wanted)(const AssemblyResult&)) {
  std::vector<const AssemblyResult*> out;
  for (const AssemblyResult& a : runs) {
    if (usable(a) && wanted(a)) out.push_back(&a);
  }
  return out;
}

bool anyKind(const AssemblyResult&) { return true; }
bool isCircular(const AssemblyResult& a) { return a.kind == AssemblyKind::Circular; }
bool isRandom(const AssemblyResult& a) { return a.kind == AssemblyKind::Random; }
bool isBedding(const AssemblyResult& a) { return a.kind == AssemblyKind::Bedding; }
bool isIsotropicFabric(const AssemblyResult& a) { return isCircular(a) || isRandom(a); }

std::string deg(double v) { return fixed(v, 1) + "°"; }

constexpr double kInf = std::numeric_limits<double>::infinity();
// The largest double below x: "value < x" as the closed range (−∞, below(x)].
double below(double x) { return std::nextafter(x, -kInf); }
double above(double x) { return std::nextafter(x, kInf); }

// A check of one run: `quantity` = value, holding for value in [from, to].
Check measuredCheck(std::string subject, std::string quantity, double value, double from, double to,
                    std::string detail) {
  Check c{std::move(subject), std::move(detail), Verdict::Inconclusive};
  c.quantity = std::move(quantity);
  c.value = value;
  c.holdsFrom = from;
  c.holdsTo = to;
  if (std::isfinite(value)) c.verdict = value >= from && value <= to ? Verdict::Holds : Verdict::DoesNotHold;
  return c;
}

// The values a check's quantity can take, so that its ensemble interval stays inside them.
constexpr ValueRange kNonNegative{0.0, kInf};
constexpr ValueRange kShare{0.0, 1.0};
constexpr ValueRange kAxialDistance{0.0, 90.0};      // |θ − θ'| the shorter way round the 180° period
constexpr ValueRange kSignedAxialAngle{-90.0, 90.0};  // ω: an axial difference
Check within(ValueRange range, Check c) {
  c.range = range;
  return c;
}

// The row's noise floor from its contact count.
double floorAt(const AssemblyResult& a, size_t row) { return noiseFloor(a.shearing.at("contacts", row)); }

// θ_k where a_k clears twice the noise floor, NaN elsewhere: a direction of noise is no direction.
std::vector<double> meaningfulDirections(const AssemblyResult& a, const std::string& term) {
  const auto coef = a.shearing.column("a_" + term), theta = a.shearing.column("theta_" + term + "_deg");
  std::vector<double> out(coef.size(), std::nan(""));
  for (size_t r = 0; r < coef.size(); ++r) {
    if (coef[r] >= kDirectionNoiseFactor * floorAt(a, r)) out[r] = theta[r];
  }
  return out;
}

double finalStrain(const AssemblyResult& a) { return finiteMax(a.shearing.column("axial_strain")); }

// Values of `column` over the rows whose axial strain lies in [lo, hi] × the final strain.
std::vector<double> overStrainFraction(const AssemblyResult& a, const std::vector<double>& column, double lo,
                                       double hi) {
  const auto strain = a.shearing.column("axial_strain");
  const double end = finalStrain(a);
  std::vector<double> out;
  for (size_t r = 0; r < strain.size() && r < column.size(); ++r) {
    if (strain[r] >= lo * end - 1e-12 && strain[r] <= hi * end + 1e-12) out.push_back(column[r]);
  }
  return out;
}

Finding finish(Finding f) {
  std::vector<Verdict> parts;
  for (const Check& c : f.checks) {
    if (!c.diagnostic) parts.push_back(c.verdict);
  }
  f.verdict = combine(parts);
  return f;
}

Finding noneRan(Finding f, const std::string& which) {
  f.checks.push_back({which, "no completed run", Verdict::Inconclusive});
  return finish(std::move(f));
}

// Where θ_c points at the start of shearing, or NaN when a_c there is noise.
double startDirection(const AssemblyResult& a, const std::string& term) {
  const double coef = a.shearing.at("a_" + term, 0);
  return coef >= kDirectionNoiseFactor * floorAt(a, 0) ? a.shearing.at("theta_" + term + "_deg", 0) : std::nan("");
}

// The mean meaningful direction over the last quarter of the shearing.
double endDirection(const AssemblyResult& a, const std::string& term) {
  return axialMeanDeg(overStrainFraction(a, meaningfulDirections(a, term), 0.75, 1.0));
}

// |ω| per row where φ_mob makes the principal direction meaningful, NaN elsewhere.
std::vector<double> meaningfulAbs(const AssemblyResult& a, const std::string& column) {
  const auto phi = a.shearing.column("phi_mob_deg"), v = a.shearing.column(column);
  std::vector<double> out(v.size(), std::nan(""));
  for (size_t r = 0; r < v.size(); ++r) {
    if (phi[r] >= kMinPhiMobDeg) out[r] = std::abs(v[r]);
  }
  return out;
}

// Median |ω_eq − ω_macro| (degrees, axial difference) over the rows where ω means something.
double medianEquationError(const AssemblyResult& a, const std::string& column) {
  const auto phi = a.shearing.column("phi_mob_deg"), macro = a.shearing.column("omega_macro_deg"),
             eq = a.shearing.column(column);
  std::vector<double> errors;
  for (size_t r = 0; r < macro.size(); ++r) {
    if (phi[r] >= kMinPhiMobDeg && std::isfinite(macro[r]) && std::isfinite(eq[r])) {
      errors.push_back(axialDistanceDeg(eq[r], macro[r]));
    }
  }
  return finiteMedian(errors);
}

}  // namespace

std::string verdictText(Verdict v, int seeds) {
  switch (v) {
    case Verdict::Holds: return "holds";
    case Verdict::DoesNotHold: return "does not hold";
    case Verdict::NotResolved: return "not resolved at " + std::to_string(seeds) + " seeds";
    case Verdict::Inconclusive: return "inconclusive";
  }
  return "inconclusive";
}

Verdict combine(const std::vector<Verdict>& parts) {
  if (parts.empty()) return Verdict::Inconclusive;
  if (std::count(parts.begin(), parts.end(), Verdict::DoesNotHold)) return Verdict::DoesNotHold;
  if (std::count(parts.begin(), parts.end(), Verdict::NotResolved)) return Verdict::NotResolved;
  if (std::count(parts.begin(), parts.end(), Verdict::Inconclusive)) return Verdict::Inconclusive;
  return Verdict::Holds;
}

double paperVoidRatio(const AssemblyResult& a) {
  switch (a.kind) {
    case AssemblyKind::Circular: return 0.282;
    case AssemblyKind::Random: return 0.267;
    case AssemblyKind::Bedding: {
      const long alpha = std::lround(a.beddingDeg);
      if (alpha == 0) return 0.264;
      if (alpha == 30) return 0.268;
      if (alpha == 60) return 0.272;
      if (alpha == 90) return 0.263;
      return std::nan("");
    }
  }
  return std::nan("");
}

Finding findStressSymmetry(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 1;
  f.claim = "The stress tensor from the contacts (Eq. 1) is symmetric: σ12 − σ21 stays close to zero (Fig. 6).";
  f.criterion = "max |σ12 − σ21| / p over the shearing below " + fixed(kAsymmetryOverP * 100, 0) + " % for every assembly";
  const auto chosen = select(runs, anyKind);
  if (chosen.empty()) return noneRan(std::move(f), "all");
  for (const AssemblyResult* a : chosen) {
    const auto s12 = a->shearing.column("sigma12"), s21 = a->shearing.column("sigma21"), p = a->shearing.column("p");
    std::vector<double> ratio;
    for (size_t r = 0; r < s12.size(); ++r) {
      if (p[r] > 0) ratio.push_back(std::abs(s12[r] - s21[r]) / p[r]);
    }
    const double worst = finiteMax(ratio);
    f.checks.push_back(within(kNonNegative, measuredCheck(a->label(), "max |σ12 − σ21|/p", worst, -kInf, below(kAsymmetryOverP),
                                     "max |σ12 − σ21|/p = " + general(worst, 2))));
  }
  return finish(std::move(f));
}

Finding findCircularFabric(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 2;
  f.claim = "Circular particles: a_ln = a_lt = 0; θ_c, θ_n, θ_t nearly coincide, starting away from 90° (about "
            "120°) and turning to 90° (Fig. 7).";
  f.criterion = "max a_ln, a_lt ≤ " + general(kDiscBranchAnisotropy) + "; median spread of θ_c, θ_n, θ_t ≤ " +
                deg(kCoincideDeg) + " where all three a_k ≥ 2× noise floor; θ_c at ε22 = 0 more than " +
                deg(kAwayFromAxisDeg) + " from 90° and, over the last quarter, within " + deg(kAwayFromAxisDeg) +
                " of it and closer than at the start";
  const auto chosen = select(runs, isCircular);
  if (chosen.empty()) return noneRan(std::move(f), "circular");
  for (const AssemblyResult* a : chosen) {
    const double ln = finiteMax(a->shearing.column("a_ln")), lt = finiteMax(a->shearing.column("a_lt"));
    const double worst = std::max(ln, lt);
    f.checks.push_back(within(kNonNegative, measuredCheck(a->label() + ": a_ln, a_lt", "max(a_ln, a_lt)", worst, -kInf,
                                     kDiscBranchAnisotropy,
                                     "max a_ln = " + general(ln, 2) + ", max a_lt = " + general(lt, 2))));

    const auto c = meaningfulDirections(*a, "c"), n = meaningfulDirections(*a, "n"), t = meaningfulDirections(*a, "t");
    std::vector<double> spread;
    for (size_t r = 0; r < c.size(); ++r) {
      if (!std::isfinite(c[r]) || !std::isfinite(n[r]) || !std::isfinite(t[r])) continue;
      spread.push_back(std::max({axialDistanceDeg(c[r], n[r]), axialDistanceDeg(c[r], t[r]), axialDistanceDeg(n[r], t[r])}));
    }
    const double median = finiteMedian(spread);
    f.checks.push_back(within(kAxialDistance, measuredCheck(
        a->label() + ": θ_c, θ_n, θ_t coincide", "median spread (°)", median, -kInf, kCoincideDeg,
        std::isfinite(median) ? "median spread " + deg(median) + " over " + std::to_string(spread.size()) + " of " +
                                    std::to_string(c.size()) + " samples"
                              : "no sample with all three a_k above twice the noise floor")));

    // The turn in two parts, each one number: away from 90° at the start, at 90° at the end.
    const double start = startDirection(*a, "c"), end = endDirection(*a, "c");
    const double d0 = axialDistanceDeg(start, 90), d1 = axialDistanceDeg(end, 90);
    f.checks.push_back(within(kAxialDistance, measuredCheck(
        a->label() + ": θ_c(0) away from 90°", "|θ_c(0) − 90°| (°)", d0, above(kAwayFromAxisDeg), kInf,
        std::isfinite(start) ? "θ_c(0) = " + deg(start)
                             : "a_c = " + general(a->shearing.at("a_c", 0), 2) +
                                   " at ε22 = 0 is below twice the noise floor (" +
                                   general(kDirectionNoiseFactor * floorAt(*a, 0), 2) +
                                   "): the starting direction means nothing")));
    f.checks.push_back(within(kAxialDistance, measuredCheck(
        a->label() + ": θ_c turns to 90°", "|θ_c − 90°| over the last quarter (°)", d1, -kInf, kAwayFromAxisDeg,
        std::isfinite(end) ? "θ_c over the last quarter " + deg(end)
                           : "a_c over the last quarter is below twice the noise floor")));
  }
  return finish(std::move(f));
}

Finding findRandomBranchVectors(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 3;
  f.claim = "Randomly oriented elongated particles: a_ln and a_lt are small, with a_lt > a_ln (Fig. 8).";
  f.criterion = "medians of a_ln and a_lt over the shearing ≤ " + general(kSmallBranchAnisotropy) +
                "; a_lt > a_ln in at least " + fixed(kMostRows * 100, 0) + " % of the samples";
  const auto chosen = select(runs, isRandom);
  if (chosen.empty()) return noneRan(std::move(f), "random");
  for (const AssemblyResult* a : chosen) {
    const auto ln = a->shearing.column("a_ln"), lt = a->shearing.column("a_lt");
    const double mln = finiteMedian(ln), mlt = finiteMedian(lt), mn = finiteMedian(a->shearing.column("a_n"));
    f.checks.push_back(within(kNonNegative, measuredCheck(a->label() + ": small", "max(median a_ln, median a_lt)",
                                     std::isfinite(mln) && std::isfinite(mlt) ? std::max(mln, mlt) : std::nan(""),
                                     -kInf, kSmallBranchAnisotropy,
                                     "median a_ln = " + fixed(mln, 3) + ", a_lt = " + fixed(mlt, 3) + " (a_n: " +
                                         fixed(mn, 3) + ")")));
    int greater = 0, counted = 0;
    for (size_t r = 0; r < ln.size(); ++r) {
      if (!std::isfinite(ln[r]) || !std::isfinite(lt[r])) continue;
      ++counted;
      greater += lt[r] > ln[r];
    }
    const double share = counted ? static_cast<double>(greater) / counted : std::nan("");
    f.checks.push_back(within(kShare, measuredCheck(a->label() + ": a_lt > a_ln", "share of samples with a_lt > a_ln", share,
                                     kMostRows, kInf,
                                     "in " + std::to_string(greater) + " of " + std::to_string(counted) + " samples")));
  }
  return finish(std::move(f));
}

Finding findBeddingFabric(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 4;
  f.claim = "Bedding angle α: θ_c starts near 90° + α and rotates toward 90°; θ_ln and θ_lt stay near α; a_c "
            "starts at about the same value for all four (Figs. 9, 12, 13).";
  f.criterion = "θ_c(0) within " + deg(kNearDirectionDeg) + " of 90° + α; over the last quarter θ_c within " +
                deg(kAwayFromAxisDeg) + " of 90° or at least 5° closer than at the start; median |θ_ln − α|, |θ_lt − α| ≤ " +
                deg(kNearDirectionDeg) + "; spread of a_c(0) ≤ " + fixed(kSameStartRelative * 100, 0) +
                " % of its mean (or twice the noise floor). Directions only where a_k ≥ 2× noise floor";
  const auto chosen = select(runs, isBedding);
  if (chosen.empty()) return noneRan(std::move(f), "bedding");
  std::vector<double> startCoef, floors;
  for (const AssemblyResult* a : chosen) {
    const double alpha = a->beddingDeg;
    const double start = startDirection(*a, "c"), end = endDirection(*a, "c");
    f.checks.push_back(within(kAxialDistance, measuredCheck(
        a->label() + ": θ_c(0) ≈ 90° + α", "|θ_c(0) − (90° + α)| (°)", axialDistanceDeg(start, 90 + alpha), -kInf,
        kNearDirectionDeg,
        std::isfinite(start) ? "θ_c(0) = " + deg(start) + " (90° + α = " + deg(analysis::axialDeg(90 + alpha)) + ")"
                             : "a_c(0) = " + general(a->shearing.at("a_c", 0), 2) + " is below twice the noise floor")));

    // Holds when the end is within 10° of 90° or at least 5° closer than the start: one number,
    // the end's distance less the larger of the two allowances.
    const double d0 = axialDistanceDeg(start, 90), d1 = axialDistanceDeg(end, 90);
    f.checks.push_back(measuredCheck(
        a->label() + ": θ_c → 90°", "|θ_c − 90°| at the end − max(10°, |θ_c(0) − 90°| − 5°)",
        std::isfinite(d0) ? d1 - std::max(kAwayFromAxisDeg, d0 - 5.0) : std::nan(""), -kInf, 0.0,
        std::isfinite(start) && std::isfinite(end)
            ? "|θ_c − 90°|: " + deg(d0) + " at the start, " + deg(d1) + " over the last quarter"
            : std::isfinite(start) ? "a_c over the last quarter is below twice the noise floor"
                                   : "no meaningful starting direction"));

    for (const std::string term : {"ln", "lt"}) {
      const auto dirs = meaningfulDirections(*a, term);
      std::vector<double> dist;
      for (double d : dirs) {
        if (std::isfinite(d)) dist.push_back(axialDistanceDeg(d, alpha));
      }
      const double median = finiteMedian(dist);
      f.checks.push_back(within(kAxialDistance, measuredCheck(
          a->label() + ": θ_" + term + " ≈ α", "median |θ_" + term + " − α| (°)", median, -kInf, kNearDirectionDeg,
          std::isfinite(median) ? "median |θ_" + term + " − α| = " + deg(median) + " (mean direction " +
                                      deg(axialMeanDeg(dirs)) + ")"
                                : "a_" + term + " below twice the noise floor throughout")));
    }
    // The one magnitude the paper's text gives for the fabric: a_c for α = 60° "keeping a
    // constant to the end with some fluctuations around a_c = 0.45". Shown beside it, not
    // judged: "around" gives no tolerance.
    if (std::lround(alpha) == 60) {
      const double late = finiteMean(overStrainFraction(*a, a->shearing.column("a_c"), 0.5, 1.0));
      Check magnitude = measuredCheck(a->label() + ": a_c against the paper's 0.45",
                                      "mean a_c over the second half of the shearing", late, -kInf, kInf,
                                      "mean a_c " + fixed(late, 3) + " from ε22 = half the final strain to the end; "
                                      "the paper: fluctuating around 0.45");
      magnitude.diagnostic = true;
      magnitude.range = kNonNegative;
      f.checks.push_back(magnitude);
    }
    startCoef.push_back(a->shearing.at("a_c", 0));
    floors.push_back(floorAt(*a, 0));
  }
  Check same = measuredCheck("all bedding angles: a_c(0) alike", "spread of a_c(0) / allowed spread", std::nan(""),
                             -kInf, 1.0, "");
  if (startCoef.size() >= 2) {
    const auto [lo, hi] = std::minmax_element(startCoef.begin(), startCoef.end());
    const double mean = finiteMean(startCoef), spread = *hi - *lo;
    std::string values;
    for (size_t k = 0; k < chosen.size(); ++k) {
      if (k) values += ", ";
      values += chosen[k]->label() + ": " + fixed(startCoef[k], 3);
    }
    same.measured = values + "; spread " + fixed(spread, 3);
    const double allowed = std::max(kSameStartRelative * mean, kDirectionNoiseFactor * finiteMax(floors));
    same = measuredCheck(same.subject, same.quantity, spread / allowed, -kInf, 1.0,
                         same.measured + " (allowed " + fixed(allowed, 3) + ")");
  } else {
    same.measured = "fewer than two bedding assemblies ran";
  }
  same.range = kNonNegative;
  f.checks.push_back(same);
  return finish(std::move(f));
}

Finding findOmegaDecay(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 5;
  f.claim = "The non-coaxiality ω decreases toward zero as shearing goes on, for every assembly, also after the "
            "peak of φ_mob (Fig. 14).";
  f.criterion = "mean |ω_macro| over the last quarter of the shearing below that at its onset (the first " +
                fixed(kOnsetFraction * 100, 0) + " % of the final strain): last quarter − onset < 0; and |ω| not "
                "rising after the peak of φ_mob: the least-squares slope from the peak on, less " +
                fixed(kTrendSigmas, 0) + " standard errors, ≤ 0 (judged when at least " +
                std::to_string(kMinSamplesAfterPeak) + " samples follow the peak); samples with φ_mob < " +
                deg(kMinPhiMobDeg) + " left out; inconclusive for a run whose |ω| stays below " +
                deg(kOmegaSignalDeg) + " at both onset and end";
  const auto chosen = select(runs, anyKind);
  if (chosen.empty()) return noneRan(std::move(f), "all");
  for (const AssemblyResult* a : chosen) {
    const auto omega = meaningfulAbs(*a, "omega_macro_deg");
    const double onset = finiteMean(overStrainFraction(*a, omega, 0.0, kOnsetFraction));
    const double late = finiteMean(overStrainFraction(*a, omega, 0.75, 1.0));
    const auto phi = a->shearing.column("phi_mob_deg"), strain = a->shearing.column("axial_strain");
    size_t peak = 0;
    for (size_t r = 0; r < phi.size(); ++r) {
      if (std::isfinite(phi[r]) && !(phi[r] <= phi[peak])) peak = r;
    }
    // How soon |ω| first falls to half its onset value: the pace of the decay.
    double halfStrain = std::nan("");
    for (size_t r = 0; r < omega.size() && std::isfinite(onset); ++r) {
      if (std::isfinite(omega[r]) && omega[r] <= onset / 2) {
        halfStrain = strain[r];
        break;
      }
    }
    // After the peak: the trend of |ω| over the samples from the peak on, when there are enough.
    std::vector<double> afterStrain, afterOmega;
    for (size_t r = peak; r < omega.size(); ++r) {
      if (std::isfinite(omega[r])) afterStrain.push_back(strain[r] * 100), afterOmega.push_back(omega[r]);
    }
    const bool testable = afterOmega.size() >= kMinSamplesAfterPeak;
    const LinearTrend trend = testable ? linearTrend(afterStrain, afterOmega) : LinearTrend{std::nan(""), std::nan("")};
    std::string measured = "|ω| at onset " + deg(onset) + ", last quarter " + deg(late) +
                 (std::isfinite(halfStrain) ? ", half the onset value by ε22 = " + fixed(halfStrain * 100, 1) + " %" : "") +
                 "; φ_mob peaks at " + fixed(phi[peak], 1) + "° at ε22 = " + fixed(strain[peak] * 100, 1) + " %" +
                 (testable ? ", |ω| after it trends " + fixed(trend.slope, 2) + " ± " + fixed(trend.standardError, 2) +
                                 "° per % strain"
                           : ", too near the end to judge after it");
    // No signal, no verdict: a run whose |ω| is noise-sized throughout says nothing either way.
    const bool signal = onset >= kOmegaSignalDeg || late >= kOmegaSignalDeg;
    f.checks.push_back(measuredCheck(a->label() + ": |ω| decreases", "|ω| last quarter − onset (°)",
                                     signal ? late - onset : std::nan(""), -kInf, below(0.0), measured));
    f.checks.push_back(measuredCheck(a->label() + ": not rising after the peak",
                                     "slope of |ω| after the peak − " + fixed(kTrendSigmas, 0) + " s.e. (° per %)",
                                     signal && testable ? trend.slope - kTrendSigmas * trend.standardError : std::nan(""),
                                     -kInf, 0.0, measured));
  }
  return finish(std::move(f));
}

Finding findMicroExpressions(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 6;
  f.claim = "Eq. (7) follows the measured θσ for all six assemblies; the simplified Eq. (10) does for circular and "
            "random; the truncated Eq. (11) fails for the bedding assemblies (Fig. 15).";
  f.criterion = "median |ω_eq − ω_macro| over the shearing (φ_mob ≥ " + deg(kMinPhiMobDeg) + ") ≤ " + deg(kEquationDeg) +
                " to follow; Eq. (11) fails where its median error exceeds " + deg(kEquationDeg) +
                " and twice that of Eq. (7)";
  const auto chosen = select(runs, anyKind);
  if (chosen.empty()) return noneRan(std::move(f), "all");
  for (const AssemblyResult* a : chosen) {
    const double e7 = medianEquationError(*a, "omega_micro_deg");
    f.checks.push_back(
        within(kAxialDistance, measuredCheck(a->label() + ": Eq. (7) follows", "median error (°)", e7, -kInf, kEquationDeg, "median error " + deg(e7))));
    if (isIsotropicFabric(*a)) {
      const double e10 = medianEquationError(*a, "omega_eq10_deg");
      f.checks.push_back(within(kAxialDistance, measuredCheck(a->label() + ": Eq. (10) follows", "median error (°)", e10, -kInf, kEquationDeg,
                                       "median error " + deg(e10))));
    }
    if (isBedding(*a)) {
      const double e11 = medianEquationError(*a, "omega_eq11_deg");
      // Fails when its error exceeds both 5° and twice Eq. (7)'s: one number, the margin.
      f.checks.push_back(measuredCheck(a->label() + ": Eq. (11) fails", "Eq. (11) error − max(5°, 2 × Eq. (7) error)",
                                       std::isfinite(e7) ? e11 - std::max(kEquationDeg, 2 * e7) : std::nan(""), above(0.0), kInf,
                                       "median error " + deg(e11) + " (Eq. 7: " + deg(e7) + ")"));
    }
  }
  return finish(std::move(f));
}

Finding findVoidRatios(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 7;
  f.claim = "After consolidation every specimen is dense, with void ratios of 0.26-0.28 (paper: 0.282 circular, 0.267 "
            "random, 0.264/0.268/0.272/0.263 for α = 0/30/60/90°).";
  f.criterion = "void ratio after consolidation in [" + general(kVoidRatioLow) + ", " + general(kVoidRatioHigh) +
                ") (0.26-0.28 at two decimals)";
  bool any = false;
  for (const AssemblyResult& a : runs) {
    const double e = a.summary.voidRatioAfterConsolidation;
    if (a.summary.status != RunStatus::Completed || !(e >= 0)) continue;
    any = true;
    f.checks.push_back(within(kNonNegative, measuredCheck(a.label(), "void ratio after consolidation", e, kVoidRatioLow, below(kVoidRatioHigh),
                                     "e = " + fixed(e, 3) + " (paper " + fixed(paperVoidRatio(a), 3) + ")")));
  }
  if (!any) return noneRan(std::move(f), "all");
  return finish(std::move(f));
}

namespace {

bool isTiltedBedding(const AssemblyResult& a) {
  const long alpha = std::lround(a.beddingDeg);
  return isBedding(a) && alpha % 90 != 0;
}

}  // namespace

Finding findOmegaOnsetSign(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 8;
  f.claim = "For tilted bedding (α = 30°, 60°) ω starts positive, the stress axis tilted from 90° toward the contact "
            "normals near 90° + α, and decreases toward zero (our reading of section 6: the paper's text does not "
            "give the sign).";
  f.criterion = "ω_macro at the onset > 0, the onset being the first sample at or beyond ε22 = " +
                fixed(kOnsetStrain * 100, 1) + " % with φ_mob ≥ " + deg(kMinPhiMobDeg) +
                " (no interpolation toward ε22 = 0, where the stress is isotropic and θσ is chance); and the mean ω "
                "over the last quarter of the shearing below it. Beside them, to explain the sign: each term's push "
                "a_k sin 2(θ_k − 90°) at ε22 = 0 and at the onset (ω has the sign of their sum, Eq. 7), and θ_n at "
                "ε22 = 0";
  const auto chosen = select(runs, isTiltedBedding);
  if (chosen.empty()) return noneRan(std::move(f), "α = 30°, 60°");
  for (const AssemblyResult* a : chosen) {
    const auto strain = a->shearing.column("axial_strain"), phi = a->shearing.column("phi_mob_deg");
    size_t onset = strain.size();
    for (size_t r = 0; r < strain.size(); ++r) {
      if (strain[r] >= kOnsetStrain - 1e-12 && phi[r] >= kMinPhiMobDeg) {
        onset = r;
        break;
      }
    }
    const bool found = onset < strain.size();
    const double omega = found ? a->shearing.at("omega_macro_deg", onset) : std::nan("");
    const double late = finiteMean(overStrainFraction(*a, a->shearing.column("omega_macro_deg"), 0.75, 1.0));
    const std::string at = found ? "ε22 = " + fixed(strain[onset] * 100, 2) + " %" : "no sample";
    f.checks.push_back(within(kSignedAxialAngle, measuredCheck(a->label() + ": ω starts positive", "ω at the onset (°)", omega, above(0.0), kInf,
                                     "ω = " + deg(omega) + " at " + at +
                                         (found ? " (φ_mob " + deg(phi[onset]) + ")" : ""))));
    f.checks.push_back(measuredCheck(a->label() + ": ω decreases from its onset",
                                     "mean ω over the last quarter − ω at the onset (°)", late - omega, -kInf, below(0.0),
                                     "last quarter " + deg(late) + ", onset " + deg(omega)));
    // The same ω from the fabric with and without the branch-vector terms: which terms set the sign.
    for (const auto& [column, name] : {std::pair<const char*, const char*>{"omega_micro_deg", "Eq. (7)"},
                                       std::pair<const char*, const char*>{"omega_eq11_deg", "Eq. (11), no ln, lt"}}) {
      const double v = found ? a->shearing.at(column, onset) : std::nan("");
      Check eq = measuredCheck(a->label() + ": ω by " + name + " at the onset", "ω by " + std::string(name) + " (°)", v,
                               -kInf, kInf, "ω = " + deg(v) + " at " + at);
      eq.diagnostic = true;
      eq.range = kSignedAxialAngle;
      f.checks.push_back(eq);
    }
    for (const bool atOnset : {false, true}) {
      const size_t row = atOnset ? onset : 0;
      for (const std::string term : {"c", "n", "t", "ln", "lt"}) {
        const double coef = a->shearing.at("a_" + term, row);
        const double theta = a->shearing.at("theta_" + term + "_deg", row);
        Check push = measuredCheck(a->label() + ": push of A_" + term + (atOnset ? " at the onset" : " at ε22 = 0"),
                                   "a_" + term + " sin 2(θ_" + term + " − 90°)",
                                   coef * std::sin(2 * radians(theta - 90.0)), -kInf, kInf,
                                   "a_" + term + " = " + fixed(coef, 3) + ", θ_" + term + " = " + deg(theta));
        push.diagnostic = true;
        f.checks.push_back(push);
      }
    }
    Check start = measuredCheck(a->label() + ": θ_n at ε22 = 0", "θ_n(0) (°)", a->shearing.at("theta_n_deg", 0), -kInf,
                                kInf, "θ_n(0) = " + deg(a->shearing.at("theta_n_deg", 0)));
    start.diagnostic = true;
    start.axial = true;
    f.checks.push_back(start);
  }
  return finish(std::move(f));
}

std::vector<Finding> evaluateSeedFindings(std::span<const AssemblyResult> runs) {
  return {findStressSymmetry(runs), findCircularFabric(runs), findRandomBranchVectors(runs), findBeddingFabric(runs),
          findOmegaDecay(runs),     findMicroExpressions(runs), findVoidRatios(runs),        findOmegaOnsetSign(runs)};
}

std::vector<Finding> mergeSeedFindings(const std::vector<std::vector<Finding>>& perSeed) {
  if (perSeed.empty()) return {};
  if (perSeed.size() == 1) return perSeed.front();
  const int runs = static_cast<int>(perSeed.size());
  std::vector<Finding> merged;
  for (size_t k = 0; k < perSeed.front().size(); ++k) {
    Finding f = perSeed.front()[k];
    // The checks of every seed, by subject, in the order they first appear.
    std::vector<Check> checks;
    std::vector<std::vector<double>> values;
    for (const std::vector<Finding>& seed : perSeed) {
      if (k >= seed.size()) continue;
      for (const Check& c : seed[k].checks) {
        auto it = std::find_if(checks.begin(), checks.end(), [&](const Check& m) { return m.subject == c.subject; });
        if (it == checks.end()) {
          checks.push_back(c);
          values.emplace_back();
          it = checks.end() - 1;
        }
        values[static_cast<size_t>(it - checks.begin())].push_back(c.value);
      }
    }
    for (size_t j = 0; j < checks.size(); ++j) {
      Check& c = checks[j];
      if (c.quantity.empty()) continue;  // "no completed run": nothing measured to merge
      const MeanInterval m = c.axial ? axialMeanInterval(values[j]) : meanIntervalInRange(values[j], c.range);
      c.runs = runs;
      c.interval = m.method;
      c.seeds = m.n;
      c.value = m.mean;
      c.ciLow = m.low;
      c.ciHigh = m.high;
      const std::string of = m.n == runs ? "" : " (" + std::to_string(m.n) + " of " + std::to_string(runs) + " seeds measured it)";
      if (m.n == 0) {
        c.verdict = Verdict::Inconclusive;
        c.measured = c.quantity + ": not measured in any of " + std::to_string(runs) + " seeds";
      } else if (!m.hasInterval()) {
        c.verdict = m.mean >= c.holdsFrom && m.mean <= c.holdsTo ? Verdict::Holds : Verdict::DoesNotHold;
        c.measured = c.quantity + " = " + general(m.mean, 3) + ", one seed: no interval" + of;
      } else {
        const bool inside = m.low >= c.holdsFrom && m.high <= c.holdsTo;
        const bool outside = m.high < c.holdsFrom || m.low > c.holdsTo;
        c.verdict = inside ? Verdict::Holds : outside ? Verdict::DoesNotHold : Verdict::NotResolved;
        c.measured = c.quantity + " = " + general(m.mean, 3) + ", 95 % interval " + general(m.low, 3) + " to " +
                     general(m.high, 3) + " over " + std::to_string(m.n) + " seeds" + of;
        if (c.verdict == Verdict::NotResolved && std::isfinite(m.sd)) {
          // The threshold the interval straddles decides which way more seeds would tip it.
          const double threshold = m.low < c.holdsFrom && c.holdsFrom <= m.high ? c.holdsFrom : c.holdsTo;
          c.seedsToResolve = seedsToExclude(m.mean, m.sd, threshold);
          if (c.seedsToResolve > 0) {
            c.measured += "; about " + std::to_string(c.seedsToResolve) + " seeds would resolve it at this spread";
          }
        }
      }
    }
    f.checks = std::move(checks);
    merged.push_back(finish(std::move(f)));
  }
  return merged;
}

}  // namespace grainlab::report
