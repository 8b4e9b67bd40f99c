// Issue 4, test 4: polar histograms of contact ends, folded into [0°, 180°), and the fitted
// c0 + c1 cos 2θ + c2 sin 2θ curves with the sinΔ/Δ binning correction.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numeric>
#include <vector>

#include "analysis/synthetic_contacts.hpp"
#include "grainlab/analysis/angles.hpp"
#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/histogram.hpp"

namespace grainlab::analysis {
namespace {

// Contacts between fresh pairs of particles with the given normal angles (degrees) and
// forces; branch vectors l = R n from each end (a disc of radius 1 mm).
struct Set {
  std::vector<ContactRecord> contacts;
  std::vector<Vec2> centroids;
  std::vector<unsigned char> inside;
  void add(double thetaDeg, double fn, double ft) {
    const double r = 1e-3;
    ContactRecord c;
    c.i = static_cast<int>(centroids.size());
    c.j = c.i + 1;
    c.normal = Vec2(std::cos(radians(thetaDeg)), std::sin(radians(thetaDeg)));
    c.point = Vec2::Zero();
    c.fn = fn;
    c.ft = ft;
    centroids.push_back(-r * c.normal);
    centroids.push_back(r * c.normal);
    inside.push_back(1);
    inside.push_back(1);
    contacts.push_back(c);
  }
};

PolarHistograms histograms(const Set& s, int bins) {
  PolarHistograms h;
  h.bins = bins;
  measureHistograms(s.contacts, s.centroids, s.inside, h);
  return h;
}

TEST(PolarHistograms, CountsSumToEndsAndBothEndsShareABin) {
  Set s;
  testing::Rng rng(3);
  for (int k = 0; k < 1000; ++k) s.add(360 * rng.uniform(), 1 + rng.uniform(), 0);
  const PolarHistograms h = histograms(s, 18);
  ASSERT_EQ(h.count.size(), 18u);
  EXPECT_EQ(std::accumulate(h.count.begin(), h.count.end(), std::int64_t{0}), 2000);
  EXPECT_EQ(h.ends, 2000);
  EXPECT_EQ(h.contacts, 1000);
  // Both ends of a contact (θ and θ + 180°) land in the same bin, so every count is even.
  for (std::int64_t c : h.count) EXPECT_EQ(c % 2, 0);
}

TEST(PolarHistograms, FoldsDirectionsIntoHalfCircle) {
  PolarHistograms h;
  h.bins = 36;  // 5° bins
  for (double th = -720; th < 720; th += 0.37) {
    EXPECT_EQ(h.binOf(th), h.binOf(th + 180));
    EXPECT_EQ(h.binOf(th), h.binOf(axialDeg(th)));
  }
  EXPECT_EQ(h.binOf(0.0), 0);
  EXPECT_EQ(h.binOf(4.999), 0);
  EXPECT_EQ(h.binOf(5.0), 1);
  EXPECT_EQ(h.binOf(179.999), 35);
  EXPECT_EQ(h.binOf(180.0), 0);
  EXPECT_EQ(h.binOf(-0.001), 35);
  EXPECT_NEAR(h.binCentreDeg(0), 2.5, 1e-12);

  // A contact whose normal points at 202° has ends at 202° and 22°: both in the [20°, 25°) bin.
  Set s;
  s.add(202.0, 5.0, 0.0);
  const PolarHistograms one = histograms(s, 36);
  EXPECT_EQ(one.count[4], 2);
  EXPECT_DOUBLE_EQ(one.fn[4], 5.0);
  EXPECT_NEAR(one.ln[4], 1e-3, 1e-15);
}

// Ends spread exactly (stratified, not random) along f_n = f0[1 + a cos 2(θ − θ_n)]: the bin
// means are the curve averaged over each bin, whose cos 2θ amplitude shrinks by sinΔ/Δ. The
// fit sees the shrunk amplitude; anisotropy() divides it out.
TEST(PolarHistograms, FittedAmplitudeOfCos2ThetaCurveWithBinCorrection) {
  for (int bins : {18, 36}) {
    SCOPED_TRACE(bins);
    Set s;
    const int per = 200 * bins;  // uniform in θ over [0, 180): isotropic contacts
    const double a = 0.4, thn = 65, f0 = 80, at = 0.25, tht = 150;
    for (int k = 0; k < per; ++k) {
      const double th = 180.0 * (k + 0.5) / per, x = radians(th);
      s.add(th, f0 * (1 + a * std::cos(2 * (x - radians(thn)))),
            f0 * (-at * std::sin(2 * (x - radians(tht)))));
    }
    const PolarHistograms h = histograms(s, bins);
    const double delta = kPi / bins, shrink = std::sin(delta) / delta;
    EXPECT_NEAR(h.smoothing(), shrink, 1e-15);
    // 200 evenly spaced points per bin average the curve as the integral does to ~1e-5.
    EXPECT_NEAR(h.fnFit.c0, f0, 1e-9 * f0);
    EXPECT_NEAR(h.fnFit.amplitude(), a * f0 * shrink, 1e-4 * f0);
    EXPECT_NEAR(wrapAxialDeg(h.fnFit.cosDirectionDeg() - thn), 0.0, 1e-6);
    EXPECT_NEAR(h.ftFit.amplitude(), at * f0 * shrink, 1e-4 * f0);
    EXPECT_NEAR(wrapAxialDeg(h.ftFit.sinDirectionDeg() - tht), 0.0, 1e-6);
    const FabricState f = h.anisotropy();
    EXPECT_NEAR(f.f0, f0, 1e-9 * f0);
    EXPECT_NEAR(f.a_n, a, 1e-4);
    EXPECT_NEAR(wrapAxialDeg(f.theta_n_deg - thn), 0.0, 1e-6);
    EXPECT_NEAR(f.a_t, at, 1e-4);
    EXPECT_NEAR(wrapAxialDeg(f.theta_t_deg - tht), 0.0, 1e-6);
    EXPECT_NEAR(f.a_c, 0.0, 1e-9);
    // Uncorrected, the amplitude would be low by (1 − sinΔ/Δ)·a: 0.002 with 18 bins, far
    // beyond the 1e-4 above.
    EXPECT_GT(a * (1 - shrink), 4e-4);
  }
}

// Contact normals drawn exactly from E(θ) ∝ 1 + a_c cos 2(θ − θ_c) by inverting its
// cumulative distribution at evenly spaced quantiles: the relative density of each bin is
// 1 + a_c (sinΔ/Δ) cos 2(θ_b − θ_c) up to ±½ contact per bin.
TEST(PolarHistograms, FittedDensityOfCos2ThetaDistribution) {
  const double ac = 0.5, thc = 110;
  const int n = 90000;
  auto cdf = [&](double x) {  // ∫₀ˣ (1 + a_c cos 2(θ − θ_c)) dθ / π, x in radians
    const double c = radians(thc);
    return (x + 0.5 * ac * (std::sin(2 * (x - c)) - std::sin(-2 * c))) / kPi;
  };
  Set s;
  for (int k = 0; k < n; ++k) {
    const double q = (k + 0.5) / n;
    double lo = 0, hi = kPi;  // the CDF is increasing for a_c < 1: bisect
    for (int it = 0; it < 60; ++it) (cdf(0.5 * (lo + hi)) < q ? lo : hi) = 0.5 * (lo + hi);
    s.add(degrees(0.5 * (lo + hi)), 1.0, 0.0);
  }
  const PolarHistograms h = histograms(s, 18);
  const double shrink = h.smoothing();
  EXPECT_NEAR(h.density.c0, 1.0, 1e-9);
  // ±½ contact in 5,000 per bin moves the amplitude by ~1e-4 at most.
  EXPECT_NEAR(h.density.amplitude(), ac * shrink, 2e-4);
  const FabricState f = h.anisotropy();
  EXPECT_NEAR(f.a_c, ac, 2e-4);
  EXPECT_NEAR(wrapAxialDeg(f.theta_c_deg - thc), 0.0, 0.05);
  // The G0/G2 estimator sees the same contacts without binning.
  const FabricState g = measureFabric(s.contacts, s.centroids, s.inside);
  EXPECT_NEAR(g.a_c, ac, 1e-4);
}

// On a random sample both readings of the anisotropy estimate the same parameters; their
// difference is smaller than either's sampling error, 4·√(2/N) bounds it.
TEST(PolarHistograms, RegressionAgreesWithEstimators) {
  testing::FabricParams p{.a_c = 0.35, .theta_c = 115, .a_n = 0.55, .theta_n = 95, .a_t = 0.3,
                          .theta_t = 80, .a_ln = 0.25, .theta_ln = 30, .a_lt = 0.35,
                          .theta_lt = 40};
  p.a_w = testing::equilibriumAw(p);
  const int n = 20000;
  const auto s = testing::sampleContacts(p, n, 9);
  PolarHistograms h;
  h.bins = 36;
  measureHistograms(s.contacts, s.centroids, s.inside, h);
  const FabricState fromBins = h.anisotropy();
  const FabricState direct = measureFabric(s.contacts, s.centroids, s.inside);
  const double tol = 4 * std::sqrt(2.0 / n);
  for (Term k : {Term::c, Term::n, Term::t, Term::ln, Term::lt}) {
    EXPECT_NEAR(fromBins.a(k), direct.a(k), tol);
    EXPECT_NEAR(wrapAxialDeg(fromBins.thetaDeg(k) - direct.thetaDeg(k)), 0.0,
                degrees(tol / (2 * direct.a(k))));
  }
  EXPECT_NEAR(fromBins.f0, direct.f0, tol * direct.f0);
  EXPECT_NEAR(fromBins.l0, direct.l0, tol * direct.l0);
}

TEST(PolarHistograms, ReusesBuffersAndRejectsCoarseBinning) {
  Set s;
  for (int k = 0; k < 100; ++k) s.add(1.8 * k, 1.0, 0.0);
  PolarHistograms h;
  h.bins = 18;
  measureHistograms(s.contacts, s.centroids, s.inside, h);
  const void* before = h.fn.data();
  measureHistograms(s.contacts, s.centroids, s.inside, h);
  EXPECT_EQ(static_cast<const void*>(h.fn.data()), before);
  EXPECT_EQ(h.ends, 200);  // not accumulated across calls
  h.bins = 12;
  EXPECT_THROW(measureHistograms(s.contacts, s.centroids, s.inside, h), std::invalid_argument);
}

TEST(PolarHistograms, JsonRoundTripWithEmptyBins) {
  Set s;
  s.add(12.0, 3.0, 0.5);
  s.add(95.0, 7.0, -1.0);
  s.add(140.0, 2.0, 0.25);
  const PolarHistograms h = histograms(s, 18);
  const nlohmann::json j = h;
  EXPECT_EQ(j.at("bins").get<int>(), 18);
  EXPECT_TRUE(j.at("fn")[0].is_null());  // an empty bin has no mean
  EXPECT_DOUBLE_EQ(j.at("fn")[1].get<double>(), 3.0);
  EXPECT_EQ(j.at("centres_deg").size(), 18u);
  const PolarHistograms back = j.get<PolarHistograms>();
  EXPECT_EQ(back.bins, h.bins);
  EXPECT_EQ(back.ends, h.ends);
  EXPECT_EQ(back.contacts, h.contacts);
  EXPECT_EQ(back.count, h.count);
  EXPECT_EQ(back.fn, h.fn);
  EXPECT_EQ(back.ft, h.ft);
  EXPECT_EQ(back.ln, h.ln);
  EXPECT_EQ(back.lt, h.lt);
  EXPECT_DOUBLE_EQ(back.fnFit.c1, h.fnFit.c1);
  EXPECT_DOUBLE_EQ(back.density.c2, h.density.c2);
  nlohmann::json bad = j;
  bad["count"].erase(0);
  EXPECT_THROW(bad.get<PolarHistograms>(), std::invalid_argument);
}

}  // namespace
}  // namespace grainlab::analysis
