// On a DEM packing at rest: the contact stress is symmetric and equals the stress the
// boundary ring applies (computed here independently, from the ring's forces alone).
#include <gtest/gtest.h>

#include <cmath>

#include "grainlab/presets.hpp"
#include "grainlab/run.hpp"
#include "grainlab/stress.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

class EquilibriumProbe : public RunObserver {
 public:
  void onFinish(const RunSummary&, const World& world) override {
    std::vector<ContactRecord> contacts;
    world.contacts(contacts);
    std::vector<unsigned char> inside(world.size());
    Vec2 centre = Vec2::Zero();
    int ring = 0;
    for (int k = 0; k < world.size(); ++k) {
      inside[k] = world.boundaryFlags()[k] ? 0 : 1;
      if (!inside[k]) centre += world.positions()[k], ++ring;
    }
    centre /= ring;
    const double area = 1.0;  // both sides are divided by the same area: compare the sums
    contact = contactStress(contacts, world.positions(), inside, area);
    // −Σ F ⊗ (x − c) over the forces F the ring exerts on the specimen at points x.
    for (const ContactRecord& c : contacts) {
      if (c.isWall() || inside[c.i] == inside[c.j]) continue;
      const Vec2 onJ = c.fn * c.normal + c.ft * perp(c.normal);
      const Vec2 f = inside[c.j] ? onJ : Vec2(-onJ);
      const Vec2 x = c.point - centre;
      boundary.s11 -= f.x() * x.x();
      boundary.s12 -= f.x() * x.y();
      boundary.s21 -= f.y() * x.x();
      boundary.s22 -= f.y() * x.y();
    }
    kinetic = world.kineticEnergy();
  }
  StressTensor contact, boundary;
  double kinetic = 0;
};

TEST(PackingEquilibrium, ContactStressIsSymmetricAndEqualsBoundaryStress) {
  // Consolidate the quick circular specimen to 300 kPa, then let it come to rest with the
  // ring held still and strong local damping.
  nlohmann::json j = presetScene("circular-quick");
  j["stages"].erase(2);  // no shearing
  j["stages"].push_back({{"type", "free"}, {"name", "rest"}, {"duration", 0.02}});
  j["material"]["local_damping"] = 0.7;
  EquilibriumProbe probe;
  ASSERT_EQ(runScene(parseScene(j), probe).status, RunStatus::Completed);
  const StressTensor& c = probe.contact;
  const StressTensor& b = probe.boundary;
  const double p = c.p();
  ASSERT_GT(p, 0);
  // Moment equilibrium of every particle makes Σ f ⊗ l symmetric; what remains is the
  // residual out-of-balance torque of a packing at rest.
  EXPECT_LT(std::abs(c.s12 - c.s21), 1e-3 * p);
  // Force equilibrium of every particle turns the sum over internal contacts into the sum
  // over the boundary: equal within 1% of p.
  EXPECT_NEAR(c.s11, b.s11, 0.01 * p);
  EXPECT_NEAR(c.s22, b.s22, 0.01 * p);
  EXPECT_NEAR(c.s12, b.s12, 0.01 * p);
  EXPECT_NEAR(c.s21, b.s21, 0.01 * p);
}

}  // namespace
}  // namespace grainlab
