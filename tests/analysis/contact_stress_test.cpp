// contactStress and the contact-end bookkeeping shared by every estimator: force index first,
// each end with its own branch vector, walls for particle i's end only, outside particles
// excluded (docs/micromechanics.md, "Stress from contacts").
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "grainlab/analysis/fabric.hpp"
#include "grainlab/analysis/histogram.hpp"
#include "grainlab/stress.hpp"

namespace grainlab::analysis {
namespace {

// Discs of radius 1 m at (0, 0) and (2, 0) touching at (1, 0), and a wall under particle 0.
struct Pair {
  std::vector<Vec2> centroids{Vec2(0, 0), Vec2(2, 0)};
  std::vector<unsigned char> inside{1, 1};
  std::vector<ContactRecord> contacts;
  Pair() {
    ContactRecord c;
    c.i = 0, c.j = 1, c.point = Vec2(1, 0), c.normal = Vec2(1, 0), c.fn = 10, c.ft = 3;
    contacts.push_back(c);
  }
  void addWall() {
    ContactRecord w;
    w.i = 0, w.j = -1, w.point = Vec2(0, -1), w.normal = Vec2(0, -1), w.fn = 4, w.ft = 0;
    contacts.push_back(w);
  }
};

TEST(ContactStress, ForceIndexFirstBothEnds) {
  const Pair p;
  const StressTensor s = contactStress(p.contacts, p.centroids, p.inside, 2.0);
  // End i: f = (10, 3), l = (1, 0). End j: f = (−10, −3), l = (−1, 0). Σ f_a l_b / A.
  EXPECT_DOUBLE_EQ(s.s11, 10.0);
  EXPECT_DOUBLE_EQ(s.s21, 3.0);
  EXPECT_DOUBLE_EQ(s.s12, 0.0);
  EXPECT_DOUBLE_EQ(s.s22, 0.0);
}

TEST(ContactStress, OutsideParticlesAndWalls) {
  Pair p;
  p.addWall();
  p.inside[1] = 0;  // only particle 0's ends count: its pair end and its wall end
  const StressTensor s = contactStress(p.contacts, p.centroids, p.inside, 1.0);
  EXPECT_DOUBLE_EQ(s.s11, 10.0);
  EXPECT_DOUBLE_EQ(s.s21, 3.0);
  EXPECT_DOUBLE_EQ(s.s22, 4.0);  // wall: f = (0, −4), l = (0, −1)
  EXPECT_DOUBLE_EQ(s.s12, 0.0);
  // The estimators and histograms see exactly the same ends.
  const FabricState f = measureFabric(p.contacts, p.centroids, p.inside);
  EXPECT_EQ(f.ends, 2);
  EXPECT_EQ(f.contacts, 2);
  PolarHistograms h;
  measureHistograms(p.contacts, p.centroids, p.inside, h);
  EXPECT_EQ(h.ends, 2);
  // A wall contact of an outside particle counts for nothing.
  p.inside[0] = 0;
  p.inside[1] = 1;
  const StressTensor t = contactStress(p.contacts, p.centroids, p.inside, 1.0);
  EXPECT_DOUBLE_EQ(t.s11, 10.0);
  EXPECT_DOUBLE_EQ(t.s22, 0.0);
  EXPECT_EQ(measureFabric(p.contacts, p.centroids, p.inside).ends, 1);
}

TEST(ContactStress, RejectsBadInput) {
  Pair p;
  EXPECT_THROW(contactStress(p.contacts, p.centroids, p.inside, 0.0), std::invalid_argument);
  EXPECT_THROW(contactStress(p.contacts, p.centroids, p.inside, -1.0), std::invalid_argument);
  std::vector<unsigned char> shortInside{1};
  EXPECT_THROW(contactStress(p.contacts, p.centroids, shortInside, 1.0), std::invalid_argument);
  EXPECT_THROW(measureFabric(p.contacts, p.centroids, shortInside), std::invalid_argument);
  p.contacts[0].j = 5;
  EXPECT_THROW(contactStress(p.contacts, p.centroids, p.inside, 1.0), std::out_of_range);
  EXPECT_THROW(measureFabric(p.contacts, p.centroids, p.inside), std::out_of_range);
}

TEST(StressTensor, DeviatorFromTheSymmetricPart) {
  StressTensor s;
  s.s11 = 300e3, s.s22 = 900e3;
  EXPECT_DOUBLE_EQ(s.q(), 300e3);
  EXPECT_DOUBLE_EQ(s.p(), 600e3);
  s.s12 = 100e3, s.s21 = -100e3;  // a skew part leaves Mohr's circle alone
  EXPECT_DOUBLE_EQ(s.q(), 300e3);
  s.s12 = s.s21 = 400e3;
  EXPECT_DOUBLE_EQ(s.q(), 500e3);  // √(300² + 400²) kPa
}

TEST(Fabric, EmptyAndForceFreeSetsGiveZeros) {
  const std::vector<ContactRecord> none;
  const std::vector<Vec2> centroids{Vec2(0, 0), Vec2(2, 0)};
  const std::vector<unsigned char> inside{1, 1};
  const FabricState e = measureFabric(none, centroids, inside);
  EXPECT_EQ(e.ends, 0);
  EXPECT_EQ(e.contacts, 0);
  EXPECT_EQ(e.a_c, 0.0);
  EXPECT_EQ(e.f0, 0.0);
  // Touching but unloaded contacts (just after generation): no force terms, no NaN.
  Pair p;
  p.contacts[0].fn = p.contacts[0].ft = 0;
  const FabricState z = measureFabric(p.contacts, p.centroids, p.inside);
  EXPECT_EQ(z.ends, 2);
  EXPECT_EQ(z.f0, 0.0);
  EXPECT_EQ(z.a_n, 0.0);
  EXPECT_EQ(z.a_t, 0.0);
  EXPECT_FALSE(std::isnan(z.a_w));
  EXPECT_DOUBLE_EQ(z.l0, 1.0);
  EXPECT_DOUBLE_EQ(z.a_c, 2.0);  // a single direction: A_c = 2e^{2iθ}
}

}  // namespace
}  // namespace grainlab::analysis
