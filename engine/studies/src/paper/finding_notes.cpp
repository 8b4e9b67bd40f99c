// The notes beside the findings: where a claim does not hold or cannot be told, the likely
// reasons, with the numbers of these runs (sizes, noise floors, servo error) filled in.
#include <algorithm>
#include <cmath>

#include "grainlab/studies/paper/findings.hpp"
#include "grainlab/studies/paper/number_text.hpp"
#include "grainlab/studies/paper/series_stats.hpp"

namespace grainlab::report {
namespace {

struct RunFacts {
  bool quick = false;
  int minParticles = 0, maxParticles = 0;  // including the membrane's ring
  double minContacts = 0, maxFloor = 0;    // at the start of shearing
  double servoError = 0;                   // max |σ11 − 300 kPa| / 300 kPa over the shearing
  double minVoidRatio = NAN, maxVoidRatio = NAN;  // after consolidation
};

RunFacts factsOf(std::span<const AssemblyResult> runs) {
  RunFacts f;
  bool first = true;
  for (const AssemblyResult& a : runs) {
    if (a.shearing.size() == 0) continue;
    f.quick = f.quick || a.quick;
    const double contacts = a.shearing.at("contacts", 0);
    f.minParticles = first ? a.summary.particles : std::min(f.minParticles, a.summary.particles);
    f.maxParticles = first ? a.summary.particles : std::max(f.maxParticles, a.summary.particles);
    f.minContacts = first ? contacts : std::min(f.minContacts, contacts);
    f.maxFloor = std::max(f.maxFloor, noiseFloor(contacts));
    first = false;
    const double e = a.summary.voidRatioAfterConsolidation;
    if (e >= 0) {
      f.minVoidRatio = std::isnan(f.minVoidRatio) ? e : std::min(f.minVoidRatio, e);
      f.maxVoidRatio = std::isnan(f.maxVoidRatio) ? e : std::max(f.maxVoidRatio, e);
    }
    for (double s : a.shearing.column("sigma11")) {
      if (std::isfinite(s)) f.servoError = std::max(f.servoError, std::abs(s - 300e3) / 300e3);
    }
  }
  return f;
}

std::string sizeSentence(const RunFacts& f) {
  std::string range = std::to_string(f.minParticles);
  if (f.maxParticles != f.minParticles) range += '-' + std::to_string(f.maxParticles);
  std::string s = "These specimens hold " + range + " particles (ring included) and about " + fixed(f.minContacts, 0) +
                  " contacts at the start of shearing, so a_k below " + fixed(2 * f.maxFloor, 3) +
                  " (twice the noise floor 1.25·√(2/N_c)) is noise. ";
  if (f.quick) {
    s += "They are the -quick presets (60 mm across): small and noisy, meant to exercise the pipeline, not to settle "
         "the paper's claims; run `grainlab paper` without --quick for the 160 mm specimens. ";
  } else {
    // Discs of r = 2 mm filling a 160 mm circle at the paper's void ratio 0.282: (R/r)²/(1 + e).
    const double discs = (0.080 * 0.080) / (0.002 * 0.002) / (1 + 0.282);
    s += "The paper reports 2000-2500 particles per specimen, but a 160 mm specimen of r = 2 mm discs at e = 0.282 "
         "holds only about " + fixed(discs, 0) + ", so the paper's circular specimen cannot have been both; ours "
         "follows the stated sizes and is noisier for it. ";
  }
  return s;
}

std::string servoSentence(const RunFacts& f) {
  return "During shearing σ11 strays up to " + fixed(f.servoError * 100, 1) +
         " % from the 300 kPa the servo should hold; every swing of the lateral stress turns the principal axes. ";
}

std::string reasons(const Finding& finding, const RunFacts& facts) {
  switch (finding.number) {
    case 1:
      return "σ12 − σ21 measures how far particles are from moment equilibrium when sampled: sizeable values point to "
             "inertia (a shearing that is not quasi-static enough; see inertial_number in series.csv) rather than to "
             "the formula. " + servoSentence(facts);
    case 2:
      return "Discs are soft here: each contact point sits δ/2 inside the disc, so l_n = r − δ/2 varies with the "
             "normal force and a_ln ≈ (δ/2r)·a_n, of order 1e-3 at 300 kPa. The paper's circular specimen starts "
             "near 120°, a trace of how it was prepared; an isotropically consolidated random packing starts with a_c "
             "near the noise floor, where its direction is chance. " + sizeSentence(facts);
    case 3:
      return "a_ln and a_lt come from the particles' elongation meeting the contact normals; random orientation "
             "cancels it only on average, so small specimens keep a residual branch anisotropy. " +
             sizeSentence(facts);
    case 4:
      return "The starting fabric depends on how the bedding survives compaction and consolidation: our specimens "
             "are placed with their long axes at α and then compacted without friction, which can rotate "
             "particles; and for α = 90° the paper itself reports a_c falling to near zero, where θ_c means nothing. "
             "The grading (count fractions solved for Cu = 1.35 and Cc = 1.2) and six-vertex polygons inscribed in "
             "the ellipse are our interpretation of the paper's particles. " + sizeSentence(facts);
    case 5:
      return "Once the stress has turned to the loading axis, ω is a small angle between two nearly coaxial "
             "directions and easily moved by noise (compare how soon it halves with the paper, where it falls over "
             "the whole test). " + servoSentence(facts) + sizeSentence(facts);
    case 6:
      return "Eq. (7) drops third-order products of the a_k, a fraction of a degree for realistic states; Eq. (10) "
             "is the unweighted mean of θ_c, θ_n, θ_t and is right only when a_c ≈ a_n ≈ a_t. Eq. (11)'s error is "
             "first order in a_ln and a_lt, but only the part of A_ln + A_lt at an angle to the other terms turns "
             "θσ: for α = 0° and 90° the branch vectors lie along the loading axes (θ_ln, θ_lt ≈ α), so dropping "
             "them changes the size of the sum, not its direction, and Eq. (11) cannot fail there by symmetry; "
             "only α = 30° and 60° can show the paper's effect. " + sizeSentence(facts);
    case 7:
      return "Solid fractions 1/(1 + e): ours " + fixed(1 / (1 + facts.maxVoidRatio), 3) + "-" +
             fixed(1 / (1 + facts.minVoidRatio), 3) + ", the paper's 0.780-0.792. Our compaction stage runs "
             "without friction up to 3 kPa, which already brings the particles to a random close packing "
             "before friction is switched on for consolidation; the paper's specimens ended looser, so its "
             "initial compaction likely stopped earlier. Our void ratio is the membrane's enclosed area less "
             "the particles' area, which if anything counts extra void along the membrane; our grading "
             "interpretation and six-vertex polygons also set how densely the particles pack. " +
             sizeSentence(facts);
    case 8:
      return "ω has the sign of the sum of the pushes a_k sin 2(θ_k − 90°) over the five terms (Eq. 7); the rows "
             "marked 'measured' give each at ε22 = 0 and at the onset, and ω by Eq. (7) and by Eq. (11), which drops "
             "the branch-vector terms ln and lt. The fabric A_c pushes θσ toward θ_c ≈ 90° + α; the branch-vector "
             "terms, whose directions lie near α for bedded elongated particles, push it the other way. Where they "
             "outweigh the fabric, ω starts negative, while Eq. (11) (the fabric and force terms alone) gives the "
             "positive ω of the natural reading. The angle conventions are not the cause: "
             "tests/analysis/stress_sign_convention_test.cpp shows grainlab gives ω > 0 for a disc fabric at 90° + α "
             "compressed along the 2-axis. " + sizeSentence(facts);
    default: return "";
  }
}

}  // namespace

std::vector<Finding> evaluateFindings(std::span<const AssemblyResult> runs) {
  // One list of findings per seed, from that seed's run of each assembly, then merged.
  std::vector<int> seeds;
  for (const AssemblyResult& a : runs) {
    if (std::find(seeds.begin(), seeds.end(), a.seed) == seeds.end()) seeds.push_back(a.seed);
  }
  std::sort(seeds.begin(), seeds.end());
  std::vector<std::vector<Finding>> perSeed;
  for (int seed : seeds) {
    std::vector<AssemblyResult> ofSeed;
    for (const AssemblyResult& a : runs) {
      if (a.seed == seed) ofSeed.push_back(a);
    }
    perSeed.push_back(evaluateSeedFindings(ofSeed));
  }
  if (perSeed.empty()) perSeed.push_back(evaluateSeedFindings(runs));
  std::vector<Finding> all = mergeSeedFindings(perSeed);
  const RunFacts facts = factsOf(runs);
  for (Finding& f : all) {
    if (f.verdict != Verdict::Holds) f.note = reasons(f, facts);
  }
  return all;
}

}  // namespace grainlab::report
