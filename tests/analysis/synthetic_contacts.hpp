#pragma once
// Synthetic contact sets drawn from the paper's Fourier distributions (docs/micromechanics.md):
// contact normals from E(θ), per-contact forces and branch vectors scattered about the mean
// curves f_n(θ), f_t(θ), l_n(θ), l_t(θ). Shared by the analysis tests.
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/math.hpp"

namespace grainlab::testing {

/// The parameters a sample is drawn from. Angles in degrees, forces N/m, lengths m.
struct FabricParams {
  double a_c = 0, theta_c = 0;
  double a_n = 0, theta_n = 0;
  double a_t = 0, theta_t = 0;
  double a_w = 0;  ///< set by equilibriumAw() for a state in moment equilibrium
  double a_ln = 0, theta_ln = 0;
  double a_lt = 0, theta_lt = 0;
  double f0 = 100.0;
  double l0 = 1e-3;

  // The mean curves of paper Eqs. (2)-(4), θ in radians.
  double density(double th) const {  // E(θ) · 2π
    return 1 + a_c * std::cos(2 * (th - radians(theta_c)));
  }
  double fn(double th) const { return f0 * (1 + a_n * std::cos(2 * (th - radians(theta_n)))); }
  double ft(double th) const { return f0 * (a_w - a_t * std::sin(2 * (th - radians(theta_t)))); }
  double ln(double th) const { return l0 * (1 + a_ln * std::cos(2 * (th - radians(theta_ln)))); }
  double lt(double th) const { return -l0 * a_lt * std::sin(2 * (th - radians(theta_lt))); }
};

/// Eq. (1) integrated numerically (midpoint rule, exact for these trigonometric polynomials
/// once the points outnumber their highest harmonic): σ/m_v as [s11, s12, s21, s22]. Independent
/// of the closed forms in the library, so it can check them.
inline std::array<double, 4> integrateEq1(const FabricParams& p, int points = 720) {
  std::array<double, 4> s{0, 0, 0, 0};
  for (int k = 0; k < points; ++k) {
    const double th = 2 * kPi * (k + 0.5) / points;
    const Vec2 n(std::cos(th), std::sin(th)), t = perp(n);
    const Vec2 f = p.fn(th) * n + p.ft(th) * t, l = p.ln(th) * n + p.lt(th) * t;
    const double w = p.density(th) / points;  // E(θ) dθ
    s[0] += w * f.x() * l.x();
    s[1] += w * f.x() * l.y();
    s[2] += w * f.y() * l.x();
    s[3] += w * f.y() * l.y();
  }
  return s;
}

/// The a_w that makes σ12 = σ21 for the other parameters of p, found from Eq. (1) itself:
/// σ12 − σ21 is linear in a_w.
inline double equilibriumAw(FabricParams p) {
  p.a_w = 0;
  const auto s0 = integrateEq1(p);
  p.a_w = 1;
  const auto s1 = integrateEq1(p);
  const double m0 = s0[1] - s0[2], m1 = s1[1] - s1[2];
  return -m0 / (m1 - m0);
}

/// Scatter about the mean curves: f_n = f̄_n·ξ with ξ ~ Gamma(4)/4 (mean 1, CV 0.5, like the
/// broad force distributions of a granular packing); f_t = f̄_t + f0·ftSd·z; l_n, l_t = mean +
/// l0·u with u uniform on ±branchHalfWidth (bounded, so l_n stays positive). All zero-mean about
/// the curves, as the estimators assume.
struct Scatter {
  double ftSd = 0.3;
  double branchHalfWidth = 0.15;
};

/// A deterministic generator: std::mt19937_64's output is specified by the standard, and the
/// conversions below are ours, so a seed gives the same sample on every platform.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double normal() {  // Box-Muller, one value per call
    const double u1 = 1.0 - uniform(), u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * kPi * u2);
  }
  double gamma4() {  // Gamma(4, 1/4): the mean of four unit exponentials
    double s = 0;
    for (int k = 0; k < 4; ++k) s -= std::log(1.0 - uniform());
    return 0.25 * s;
  }

 private:
  std::mt19937_64 engine_;
};

/// A contact set: every contact joins its own two particles, both inside, so there are two
/// ends per contact, each with its own branch vector l = l_n n_end + l_t t_end drawn at that
/// end's outward normal (θ for end i, θ + 180° for end j).
struct SyntheticSet {
  std::vector<ContactRecord> contacts;
  std::vector<Vec2> centroids;
  std::vector<unsigned char> inside;
};

inline SyntheticSet sampleContacts(const FabricParams& p, int count, std::uint64_t seed,
                                   Scatter scatter = {}) {
  Rng rng(seed);
  SyntheticSet s;
  s.contacts.reserve(static_cast<size_t>(count));
  s.centroids.reserve(2 * static_cast<size_t>(count));
  const double peak = 1 + std::abs(p.a_c);
  for (int k = 0; k < count; ++k) {
    double th = 0;
    do th = 2 * kPi * rng.uniform();  // rejection sampling of E(θ)
    while (rng.uniform() * peak > p.density(th));
    const Vec2 n(std::cos(th), std::sin(th)), t = perp(n);
    ContactRecord c;
    c.i = 2 * k;
    c.j = 2 * k + 1;
    c.normal = n;
    c.point = Vec2(0.1 * rng.uniform(), 0.1 * rng.uniform());
    c.fn = p.fn(th) * rng.gamma4();
    c.ft = p.ft(th) + p.f0 * scatter.ftSd * rng.normal();
    c.overlap = 0;
    auto branch = [&](double angle) {
      const double w = scatter.branchHalfWidth * p.l0;
      const double ln = p.ln(angle) + w * (2 * rng.uniform() - 1);
      const double lt = p.lt(angle) + w * (2 * rng.uniform() - 1);
      return std::pair{ln, lt};
    };
    const auto [lni, lti] = branch(th);
    const auto [lnj, ltj] = branch(th + kPi);
    // l runs from the centroid to the contact point; end j's frame is (−n, −t).
    s.centroids.push_back(c.point - (lni * n + lti * t));
    s.centroids.push_back(c.point + (lnj * n + ltj * t));
    s.contacts.push_back(c);
  }
  s.inside.assign(s.centroids.size(), 1);
  return s;
}

}  // namespace grainlab::testing
