#include "grainlab/report/findings.hpp"

#include <algorithm>
#include <cmath>

#include "grainlab/analysis/angles.hpp"
#include "grainlab/report/markup.hpp"
#include "grainlab/report/series_stats.hpp"

namespace grainlab::report {
namespace {

using namespace criteria;

bool usable(const AssemblyResult& a) { return a.summary.status == "completed" && a.shearing.size() >= 2; }

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
  for (const Check& c : f.checks) parts.push_back(c.verdict);
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

std::string verdictText(Verdict v) {
  switch (v) {
    case Verdict::Holds: return "holds";
    case Verdict::DoesNotHold: return "does not hold";
    case Verdict::Inconclusive: return "inconclusive";
  }
  return "inconclusive";
}

Verdict combine(const std::vector<Verdict>& parts) {
  if (parts.empty()) return Verdict::Inconclusive;
  if (std::count(parts.begin(), parts.end(), Verdict::DoesNotHold)) return Verdict::DoesNotHold;
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
    const Verdict v = !std::isfinite(worst) ? Verdict::Inconclusive
                      : worst < kAsymmetryOverP ? Verdict::Holds : Verdict::DoesNotHold;
    f.checks.push_back({a->label(), "max |σ12 − σ21|/p = " + general(worst, 2), v});
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
    f.checks.push_back({a->label() + ": a_ln, a_lt",
                        "max a_ln = " + general(ln, 2) + ", max a_lt = " + general(lt, 2),
                        !std::isfinite(worst) ? Verdict::Inconclusive
                        : worst <= kDiscBranchAnisotropy ? Verdict::Holds : Verdict::DoesNotHold});

    const auto c = meaningfulDirections(*a, "c"), n = meaningfulDirections(*a, "n"), t = meaningfulDirections(*a, "t");
    std::vector<double> spread;
    for (size_t r = 0; r < c.size(); ++r) {
      if (!std::isfinite(c[r]) || !std::isfinite(n[r]) || !std::isfinite(t[r])) continue;
      spread.push_back(std::max({axialDistanceDeg(c[r], n[r]), axialDistanceDeg(c[r], t[r]), axialDistanceDeg(n[r], t[r])}));
    }
    const double median = finiteMedian(spread);
    f.checks.push_back({a->label() + ": θ_c, θ_n, θ_t coincide",
                        std::isfinite(median) ? "median spread " + deg(median) + " over " + std::to_string(spread.size()) +
                                                    " of " + std::to_string(c.size()) + " samples"
                                              : "no sample with all three a_k above twice the noise floor",
                        !std::isfinite(median) ? Verdict::Inconclusive
                        : median <= kCoincideDeg ? Verdict::Holds : Verdict::DoesNotHold});

    const double start = startDirection(*a, "c"), end = endDirection(*a, "c");
    Check turn{a->label() + ": θ_c turns to 90°", "", Verdict::Inconclusive};
    if (!std::isfinite(start)) {
      turn.measured = "a_c = " + general(a->shearing.at("a_c", 0), 2) + " at ε22 = 0 is below twice the noise floor (" +
                      general(kDirectionNoiseFactor * floorAt(*a, 0), 2) + "): the starting direction means nothing";
    } else if (!std::isfinite(end)) {
      turn.measured = "θ_c(0) = " + deg(start) + "; a_c over the last quarter is below twice the noise floor";
    } else {
      const double d0 = axialDistanceDeg(start, 90), d1 = axialDistanceDeg(end, 90);
      turn.measured = "θ_c(0) = " + deg(start) + ", last quarter " + deg(end);
      turn.verdict = d0 > kAwayFromAxisDeg && d1 <= kAwayFromAxisDeg && d1 < d0 ? Verdict::Holds : Verdict::DoesNotHold;
    }
    f.checks.push_back(turn);
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
    f.checks.push_back({a->label() + ": small",
                        "median a_ln = " + fixed(mln, 3) + ", a_lt = " + fixed(mlt, 3) + " (a_n: " + fixed(mn, 3) + ")",
                        !std::isfinite(mln) || !std::isfinite(mlt) ? Verdict::Inconclusive
                        : std::max(mln, mlt) <= kSmallBranchAnisotropy ? Verdict::Holds : Verdict::DoesNotHold});
    int greater = 0, counted = 0;
    for (size_t r = 0; r < ln.size(); ++r) {
      if (!std::isfinite(ln[r]) || !std::isfinite(lt[r])) continue;
      ++counted;
      greater += lt[r] > ln[r];
    }
    const double share = counted ? static_cast<double>(greater) / counted : std::nan("");
    f.checks.push_back({a->label() + ": a_lt > a_ln",
                        "in " + std::to_string(greater) + " of " + std::to_string(counted) + " samples",
                        !counted ? Verdict::Inconclusive : share >= kMostRows ? Verdict::Holds : Verdict::DoesNotHold});
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
    Check s{a->label() + ": θ_c(0) ≈ 90° + α", "", Verdict::Inconclusive};
    if (std::isfinite(start)) {
      const double d = axialDistanceDeg(start, 90 + alpha);
      s.measured = "θ_c(0) = " + deg(start) + " (90° + α = " + deg(analysis::axialDeg(90 + alpha)) + ")";
      s.verdict = d <= kNearDirectionDeg ? Verdict::Holds : Verdict::DoesNotHold;
    } else {
      s.measured = "a_c(0) = " + general(a->shearing.at("a_c", 0), 2) + " is below twice the noise floor";
    }
    f.checks.push_back(s);

    Check turn{a->label() + ": θ_c → 90°", "", Verdict::Inconclusive};
    if (std::isfinite(start) && std::isfinite(end)) {
      const double d0 = axialDistanceDeg(start, 90), d1 = axialDistanceDeg(end, 90);
      turn.measured = "|θ_c − 90°|: " + deg(d0) + " at the start, " + deg(d1) + " over the last quarter";
      turn.verdict = d1 <= kAwayFromAxisDeg || d1 < d0 - 5.0 ? Verdict::Holds : Verdict::DoesNotHold;
    } else {
      turn.measured = std::isfinite(start) ? "a_c over the last quarter is below twice the noise floor"
                                           : "no meaningful starting direction";
    }
    f.checks.push_back(turn);

    for (const std::string term : {"ln", "lt"}) {
      const auto dirs = meaningfulDirections(*a, term);
      std::vector<double> dist;
      for (double d : dirs) {
        if (std::isfinite(d)) dist.push_back(axialDistanceDeg(d, alpha));
      }
      const double median = finiteMedian(dist);
      f.checks.push_back({a->label() + ": θ_" + term + " ≈ α",
                          std::isfinite(median) ? "median |θ_" + term + " − α| = " + deg(median) + " (mean direction " +
                                                      deg(axialMeanDeg(dirs)) + ")"
                                                : "a_" + term + " below twice the noise floor throughout",
                          !std::isfinite(median) ? Verdict::Inconclusive
                          : median <= kNearDirectionDeg ? Verdict::Holds : Verdict::DoesNotHold});
    }
    startCoef.push_back(a->shearing.at("a_c", 0));
    floors.push_back(floorAt(*a, 0));
  }
  Check same{"all bedding angles: a_c(0) alike", "", Verdict::Inconclusive};
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
    same.verdict = !std::isfinite(spread) ? Verdict::Inconclusive
                   : spread <= allowed ? Verdict::Holds : Verdict::DoesNotHold;
  } else {
    same.measured = "fewer than two bedding assemblies ran";
  }
  f.checks.push_back(same);
  return finish(std::move(f));
}

Finding findOmegaDecay(std::span<const AssemblyResult> runs) {
  Finding f;
  f.number = 5;
  f.claim = "The non-coaxiality ω decreases toward zero as shearing goes on, for every assembly, also after the "
            "peak of φ_mob (Fig. 14).";
  f.criterion = "mean |ω_macro| over the last quarter of the shearing below that at its onset (the first " +
                fixed(kOnsetFraction * 100, 0) + " % of the final strain), and |ω| not rising after the peak of "
                "φ_mob (least-squares slope from the peak on less than " + fixed(kTrendSigmas, 0) +
                " standard errors above zero, judged when at least " + std::to_string(kMinSamplesAfterPeak) +
                " samples follow the peak); samples with φ_mob < " + deg(kMinPhiMobDeg) +
                " left out; inconclusive when |ω| stays below " + deg(kOmegaSignalDeg) +
                " at both onset and end, and an end more than " + deg(kOmegaSignalDeg) +
                " above the onset does not hold";
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
    Check c{a->label(), "", Verdict::Inconclusive};
    c.measured = "|ω| at onset " + deg(onset) + ", last quarter " + deg(late) +
                 (std::isfinite(halfStrain) ? ", half the onset value by ε22 = " + fixed(halfStrain * 100, 1) + " %" : "") +
                 "; φ_mob peaks at " + fixed(phi[peak], 1) + "° at ε22 = " + fixed(strain[peak] * 100, 1) + " %" +
                 (testable ? ", |ω| after it trends " + fixed(trend.slope, 2) + " ± " + fixed(trend.standardError, 2) +
                                 "° per % strain"
                           : ", too near the end to judge after it");
    if (std::isfinite(onset) && std::isfinite(late)) {
      const bool signal = onset >= kOmegaSignalDeg || late >= kOmegaSignalDeg;
      const bool grows = late > onset + kOmegaSignalDeg;
      const bool decreases = late < onset;
      const bool afterPeak = !testable || !trend.risesBeyond(kTrendSigmas);
      if (grows) c.verdict = Verdict::DoesNotHold;
      else if (signal) c.verdict = decreases && afterPeak ? Verdict::Holds : Verdict::DoesNotHold;
    }
    f.checks.push_back(c);
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
  auto follows = [](double e) {
    return !std::isfinite(e) ? Verdict::Inconclusive : e <= kEquationDeg ? Verdict::Holds : Verdict::DoesNotHold;
  };
  for (const AssemblyResult* a : chosen) {
    const double e7 = medianEquationError(*a, "omega_micro_deg");
    f.checks.push_back({a->label() + ": Eq. (7) follows", "median error " + deg(e7), follows(e7)});
    if (isIsotropicFabric(*a)) {
      const double e10 = medianEquationError(*a, "omega_eq10_deg");
      f.checks.push_back({a->label() + ": Eq. (10) follows", "median error " + deg(e10), follows(e10)});
    }
    if (isBedding(*a)) {
      const double e11 = medianEquationError(*a, "omega_eq11_deg");
      const Verdict v = !std::isfinite(e11) || !std::isfinite(e7) ? Verdict::Inconclusive
                        : e11 > kEquationDeg && e11 > 2 * e7  ? Verdict::Holds
                                                              : Verdict::DoesNotHold;
      f.checks.push_back({a->label() + ": Eq. (11) fails", "median error " + deg(e11) + " (Eq. 7: " + deg(e7) + ")", v});
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
    if (a.summary.status != "completed" || !(e >= 0)) continue;
    any = true;
    f.checks.push_back({a.label(), "e = " + fixed(e, 3) + " (paper " + fixed(paperVoidRatio(a), 3) + ")",
                        e >= kVoidRatioLow && e < kVoidRatioHigh ? Verdict::Holds : Verdict::DoesNotHold});
  }
  if (!any) return noneRan(std::move(f), "all");
  return finish(std::move(f));
}

}  // namespace grainlab::report
