// Rolling resistance (engine/src/rolling_resistance.hpp) against its closed forms: a disc on
// a flat under gravity tilted by θ stays put below tan θ_c = μ_r and rolls above it with the
// predicted acceleration; a disc rolling on a flat stops in the predicted distance; the
// couple is equal and opposite on a pair (angular momentum is conserved).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/world_helpers.hpp"

namespace grainlab {
namespace {

using test::disc;

constexpr double kR = 0.002;   // m
constexpr double kG = 9.81;    // m/s²
constexpr double kMuR = 0.1;   // rolling friction: θ_c = atan(0.1) = 5.71°

Material rollingMaterial(double rollingDamping = 0.3) {
  Material m = test::material(1e8, 0.5, 0.5);  // μ = 0.5: no sliding below 26°
  m.rollingFriction = kMuR;
  m.rollingDamping = rollingDamping;
  return m;
}

// A disc resting on the floor y = 0 (at its static overlap), gravity tilted by `angle` over
// the first `ramp` seconds (slowly against the rolling spring's period, 0.2 ms, so the couple
// follows the load without overshoot), then held.
struct Incline {
  World world;
  explicit Incline(const Material& m, double v0 = 0, double spin0 = 0) : world(m) {
    world.addWall(Wall{Vec2(0, 0), Vec2(0, 1)});
    const double mass = m.density * kPi * kR * kR;
    world.addParticle(disc(kR, {0, kR - mass * kG / m.normalStiffness}, {v0, 0}, spin0));
    world.setGravity({0, -kG});
    world.initialize();
  }
  void tilt(double angle, double ramp) {
    const int steps = static_cast<int>(ramp / world.timestep());
    for (int k = 1; k <= steps; ++k) {
      const double a = angle * k / steps;
      world.setGravity({kG * std::sin(a), -kG * std::cos(a)});
      world.step();
    }
  }
  void run(double duration) {
    const int steps = static_cast<int>(duration / world.timestep());
    for (int k = 0; k < steps; ++k) world.step();
  }
  double x() const { return world.positions()[0].x(); }
  double v() const { return world.velocities()[0].x(); }
};

// The elastic travel of the disc's centre when both springs hold the largest load they can
// before rolling sets in: the rolling spring's rotation at the cap (μ_r R f_n / k_r) at the
// lever R, and the tangential spring's stretch under the force that balances the slope.
double elasticTravel(const Material& m, double angle) {
  const double mass = m.density * kPi * kR * kR;
  const double fn = mass * kG * std::cos(angle);
  const double kr = m.rollingStiffnessRatio * m.tangentialStiffness * kR * kR;
  return kR * kMuR * kR * fn / kr + mass * kG * std::sin(angle) / m.tangentialStiffness;
}

TEST(RollingResistance, ADiscStaysPutBelowTheCriticalSlope) {
  const double critical = std::atan(kMuR);
  const Material m = rollingMaterial();
  for (double fraction : {0.5, 0.9}) {
    Incline incline(m);
    incline.tilt(fraction * critical, 0.02);
    const double x0 = incline.x();
    incline.run(0.05);
    // Rolling at even a tenth of the above-critical acceleration would move it 1e-5 m.
    EXPECT_LT(std::abs(incline.x() - x0), 2 * elasticTravel(m, critical)) << fraction << " of the critical slope";
    EXPECT_LT(std::abs(incline.x()), 2 * elasticTravel(m, critical)) << "during the tilt";
  }
}

TEST(RollingResistance, ADiscRollsAboveTheCriticalSlopeWithThePredictedAcceleration) {
  const double critical = std::atan(kMuR);
  const Material m = rollingMaterial();
  for (double fraction : {1.2, 2.0}) {
    const double angle = fraction * critical;
    Incline incline(m);
    incline.tilt(angle, 0.02);
    const double t = 0.05, v0 = incline.v();
    incline.run(t);
    // Rolling without slip against the plastic couple μ_r R m g cos θ: m a = m g sin θ − F_t,
    // (I/R) a = F_t R − μ_r R m g cos θ, I = m R²/2, so a = (2/3) g (sin θ − μ_r cos θ).
    const double predicted = 2.0 / 3.0 * kG * (std::sin(angle) - kMuR * std::cos(angle));
    const double measured = (incline.v() - v0) / t;
    // The lever is R − δ rather than R (δ/R ~ 1e-6) and the normal force settles from the
    // tilt within microseconds: 0.1% covers both with margin.
    EXPECT_NEAR(measured, predicted, 1e-3 * predicted) << fraction << " of the critical slope";
  }
}

TEST(RollingResistance, ARollingDiscStopsInThePredictedDistance) {
  const Material m = rollingMaterial();
  const double v0 = 0.1;  // m/s, rolling without slip: ω = −v/R
  Incline floor(m, v0, -v0 / kR);
  // The couple μ_r R m g decelerates the rolling disc at a = (2/3) μ_r g (as above with θ = 0):
  // it stops after v0/a and d = v0² / (2a) = 3 v0² / (4 μ_r g).
  const double a = 2.0 / 3.0 * kMuR * kG, stopTime = v0 / a, distance = v0 * v0 / (2 * a);
  floor.run(0.9 * stopTime);
  EXPECT_GT(floor.v(), 0.05 * v0) << "stopped too early";
  floor.run(0.2 * stopTime);
  const double x = floor.x();
  EXPECT_LT(std::abs(floor.v()), 1e-3 * v0) << "still rolling";
  floor.run(0.1 * stopTime);
  // After it stops the springs hold it; the position is the closed form's within a few
  // timesteps' travel at the start speed and the springs' elastic travel.
  const double tolerance = 4 * v0 * floor.world.timestep() + 2 * elasticTravel(m, 0);
  EXPECT_NEAR(x, distance, tolerance);
  EXPECT_NEAR(floor.x(), x, 2 * elasticTravel(m, 0)) << "crept on after stopping";
}

TEST(RollingResistance, ThePlasticCoupleDissipatesTheKineticEnergyItsWorkPredicts) {
  // Without damping anywhere (e = 1, no rolling damper) the energy a rolling disc loses until
  // it stops is the couple's work μ_r R m g φ over its rotation φ = d/R.
  Material m = rollingMaterial(0);
  m.restitution = 1;
  const double v0 = 0.05;
  Incline floor(m, v0, -v0 / kR);
  const double mass = floor.world.masses()[0], inertia = floor.world.inertias()[0];
  const double kinetic0 = 0.5 * mass * v0 * v0 + 0.5 * inertia * (v0 / kR) * (v0 / kR);
  const double x0 = floor.x();
  const double a = 2.0 / 3.0 * kMuR * kG;
  floor.run(1.2 * v0 / a);
  const double work = kMuR * kR * mass * kG * (floor.x() - x0) / kR;
  EXPECT_NEAR(work, kinetic0, 1e-3 * kinetic0);
}

TEST(RollingResistance, TheCoupleIsEqualAndOppositeAngularMomentumIsConserved) {
  // Two spinning discs collide obliquely in free space: contact forces and the rolling
  // couple are internal, so the total angular momentum about the origin is conserved.
  Material m = rollingMaterial();
  m.rollingFriction = 0.5;  // a large couple, so a wrong sign would show
  auto angularMomentum = [](const World& w) {
    double l = 0;
    for (int k = 0; k < w.size(); ++k) {
      const Vec2 x = w.positions()[k], v = w.velocities()[k];
      l += w.inertias()[k] * w.spins()[k] + w.masses()[k] * (x.x() * v.y() - x.y() * v.x());
    }
    return l;
  };
  auto collide = [&](const Material& material, double& spinChange) {
    World w(material);
    w.addParticle(disc(kR, {-kR - 1e-5, 0}, {0.2, 0}, 40.0));
    w.addParticle(disc(1.5 * kR, {2.5 * kR, 0.8 * kR}, {-0.2, 0}, -10.0));
    w.initialize();
    const double l0 = angularMomentum(w), spin0 = w.spins()[0];
    for (int k = 0; k < 20000; ++k) w.step();
    spinChange = w.spins()[0] - spin0;
    return std::abs(angularMomentum(w) - l0) / (std::abs(l0) + 1e-30);
  };
  double withRolling, without;
  const double drift = collide(m, withRolling);
  Material plain = m;
  plain.rollingFriction = 0;
  collide(plain, without);
  EXPECT_LT(drift, 1e-12);
  // The couple did act: disc 0's spin changed differently from the plain collision's.
  EXPECT_GT(std::abs(withRolling - without), 0.01 * std::abs(without));
}

TEST(RollingResistance, TheTimestepBoundCountsTheRollingSpring) {
  // The tangential and rolling springs on a disc (u = Rφ, masses m and m/2, stiffness
  // k_t [[1, 1], [1, 1 + β]]): the highest eigenvalue of M⁻¹K is (5 + √17)/2 · k_t/m for β = 1
  // against 3 k_t/m without rolling resistance.
  Material m = rollingMaterial();
  m.normalStiffness = 1e6;  // the tangential bound decides
  m.tangentialStiffness = 1e7;
  World rolling(m);
  rolling.addParticle(disc(kR, {0, 0}));
  Material plain = m;
  plain.rollingFriction = 0;
  World without(plain);
  without.addParticle(disc(kR, {0, 0}));
  const double ratio = without.criticalTimestep() / rolling.criticalTimestep();
  EXPECT_NEAR(ratio, std::sqrt((5 + std::sqrt(17.0)) / 2 / 3), 1e-12);
}

}  // namespace
}  // namespace grainlab
