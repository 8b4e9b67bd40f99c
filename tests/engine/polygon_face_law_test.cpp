// The wide path's force law at polygon face-against-edge contacts (polygon_face_kernel.hpp,
// measurePolygonFaceForces): each lane must give what ContactSolver's scalar law gives at the
// contact measurePolygons finds (the force on j, both torques, the pair's fn, ft, overlap and
// tangential spring), bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "contact_law.hpp"
#include "grainlab/simd_path.hpp"
#include "polygon_collider.hpp"
#include "polygon_face_batch.hpp"
#include "wide_path_support.hpp"

namespace grainlab {
namespace {

// ContactSolver::contactForce (engine/src/contact_solver.cpp) for a pair of polygons outside a
// periodic cell, written out from the same building blocks: the scalar reference.
template <class Tangential>
void scalarLaw(PairState& p, const ContactGeometry& g, const Vec2& xi, const Vec2& vi, double wi, const Vec2& xj,
               const Vec2& vj, double wj, const LinearSpringDashpot& normal, const Tangential& tangential, double dt,
               Vec2& F, double& ti, double& tj) {
  const Vec2& n = g.normal;
  const Vec2 t = perp(n);
  const Vec2 ri = g.point - xi;
  Vec2 dv = -(vi + cross(wi, ri));
  const Vec2 rj = g.point - xj;
  dv += vj + cross(wj, rj);
  const ContactMotion m{g.overlap, dv.dot(n), dv.dot(t)};
  p.fn = normal.force(m, p.dampN);
  p.ft = tangential.force(p.fn, m, p.dampT, dt, p.history.tangential);
  p.overlap = m.overlap;
  F = p.fn * n + p.ft * t;
  ti = cross(ri, F);
  tj = cross(rj, F);
}

struct Outcome {
  int pairs = 0, touching = 0, sliding = 0, differing = 0;
  double worstForce = 0;  // N
};

// Random pairs of four shapes (as polygon_face_kernel_test), their features found at one pose
// and measured at another a little moved; random velocities and spins (up to 0.5 m/s and
// 50 rad/s: a fast shear's), random damping and a random tangential spring, so that some
// lanes stick and some slide. The kernel performs the scalar law's operations in its order,
// without fused products (the build contracts none) and with IEEE division, so the bound is
// zero: every output of every lane must have the scalar bits. Two ranges of odd lengths cover
// the part-vectors at their ends.
Outcome compareLaws(bool frictional) {
  PolygonCollider collider(1.0 / 0.0025);
  const int shapes[] = {collider.add(test::ellipseHexagon(0.005)), collider.add(test::ellipseHexagon(0.0045)),
                        collider.add(test::regularPolygon(3, 0.0025)), collider.add(test::regularPolygon(8, 0.002))};
  std::mt19937_64 rng(frictional ? 17 : 19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto signedUnit = [&] { return 2 * unit(rng) - 1; };
  const int pairs = 2003, split = 997;
  const double kn = 1e8, kt = 0.75e8, mu = 0.5, dt = 2e-7;  // N/m, N/m, −, s
  const LinearSpringDashpot normal{kn};
  // Particles: pair k is particles 2k (i) and 2k + 1 (j).
  std::vector<Vec2> x(2 * pairs), v(2 * pairs);
  std::vector<double> w(2 * pairs);
  std::vector<PairState> state(pairs), expected(pairs);
  std::vector<Vec2> force(pairs);
  std::vector<double> torqueI(pairs), torqueJ(pairs);
  std::vector<bool> touches(pairs);
  PolygonFaceBatch batch;
  batch.resize(pairs);
  Outcome o;
  o.pairs = pairs;
  int slot = 0;
  while (slot < pairs) {
    const int a = shapes[rng() % 4], b = shapes[rng() % 4];
    const double reach = collider.polygon(a).circumradius + collider.polygon(b).circumradius;
    const double dir = 2 * kPi * unit(rng);
    const double angleA = 2 * kPi * unit(rng), angleB = 2 * kPi * unit(rng);
    const Pose ra{Vec2(0.01 * unit(rng), 0.01 * unit(rng)), std::cos(angleA), std::sin(angleA)};
    const Pose rb{ra.x + (0.4 + 0.6 * unit(rng)) * reach * Vec2(std::cos(dir), std::sin(dir)), std::cos(angleB), std::sin(angleB)};
    CachedContact kept;
    if (!collider.keepPolygonFeatures(a, ra, b, rb, kept)) continue;
    const double turn = 0.3 * signedUnit();
    const Pose moved{rb.x + 0.15 * reach * Vec2(signedUnit(), signedUnit()), std::cos(angleB + turn), std::sin(angleB + turn)};
    const int k = slot, i = 2 * k, j = 2 * k + 1;
    x[i] = ra.x;
    x[j] = moved.x;
    v[i] = 0.5 * Vec2(signedUnit(), signedUnit());
    v[j] = 0.5 * Vec2(signedUnit(), signedUnit());
    w[i] = 50 * signedUnit();
    w[j] = 50 * signedUnit();
    PairState& p = state[k];
    p.i = i;
    p.j = j;
    p.dampN = 20 * unit(rng);
    p.dampT = 20 * unit(rng);
    // A spring of up to 2 mm at 0.75e8 N/m: often beyond μ f_n of a 0.01-1 mm overlap.
    p.history.tangential = 2e-3 * signedUnit() * unit(rng) * unit(rng);
    expected[k] = p;
    CachedContact held = kept;
    held.slack = std::numeric_limits<double>::infinity();  // measured as kept, not searched again
    const ContactGeometry g = collider.collidePolygons(a, ra, b, moved, &held);
    touches[k] = g.overlap > 0;
    if (touches[k]) {
      ++o.touching;
      if (frictional) {
        scalarLaw(expected[k], g, x[i], v[i], w[i], x[j], v[j], w[j], normal, CundallStrack{kt, mu}, dt, force[k],
                  torqueI[k], torqueJ[k]);
        o.sliding += std::abs(expected[k].ft) == mu * expected[k].fn;
      } else {
        scalarLaw(expected[k], g, x[i], v[i], w[i], x[j], v[j], w[j], normal, Frictionless{}, dt, force[k],
                  torqueI[k], torqueJ[k]);
      }
    }
    batch.setParticles(slot, i, j);
    batch.add(slot, k, kept, a, ra, b, moved, collider);
    ++slot;
  }
  const PolygonFaceLaw law{kn, kt, mu, dt, frictional};
  batch.measureForces(collider, law, v.data()->data(), w.data(), state.data(), 0, split);
  batch.measureForces(collider, law, v.data()->data(), w.data(), state.data(), split, pairs - split);
  auto bits = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (int k = 0; k < pairs; ++k) {
    EXPECT_EQ(batch.pairOf(k), k);
    if (batch.touches(k) != touches[k]) {
      ++o.differing;
      continue;
    }
    if (!touches[k]) continue;
    const PairState& got = state[k];
    const PairState& want = expected[k];
    const bool same = bits(batch.force(k).x(), force[k].x()) && bits(batch.force(k).y(), force[k].y()) &&
                      bits(batch.torqueI(k), torqueI[k]) && bits(batch.torqueJ(k), torqueJ[k]) &&
                      bits(got.fn, want.fn) && bits(got.ft, want.ft) && bits(got.overlap, want.overlap) &&
                      bits(got.history.tangential, want.history.tangential);
    o.differing += !same;
    o.worstForce = std::max(o.worstForce, (batch.force(k) - force[k]).norm());
  }
  return o;
}

// Each test on every instruction set this build compiled (vectors of 1 to 8 doubles, each
// forced in turn): every one must give the scalar law's bits.
TEST(PolygonFaceLaw, FrictionalLanesHaveTheScalarLawsBits) {
  if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  test::onEveryWideTarget([&](const std::string& target) {
    const Outcome o = compareLaws(true);
    EXPECT_EQ(o.differing, 0) << target << ": largest force difference " << o.worstForce << " N";
    // Touching and apart lanes, sticking and sliding ones are all exercised.
    EXPECT_GT(o.touching, o.pairs / 4) << target;
    EXPECT_LT(o.touching, o.pairs - o.pairs / 10) << target;
    EXPECT_GT(o.sliding, o.touching / 10) << target;
    EXPECT_LT(o.sliding, o.touching - o.touching / 10) << target;
  });
}

TEST(PolygonFaceLaw, FrictionlessLanesHaveTheScalarLawsBits) {
  if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  test::onEveryWideTarget([&](const std::string& target) {
    const Outcome o = compareLaws(false);
    EXPECT_EQ(o.differing, 0) << target << ": largest force difference " << o.worstForce << " N";
    EXPECT_GT(o.touching, o.pairs / 4) << target;
  });
}

}  // namespace
}  // namespace grainlab
