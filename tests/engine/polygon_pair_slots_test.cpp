// The wide path's kept polygon pair slots (polygon_pair_slots.hpp, polygon_hold_kernel.hpp):
// the hold kernel must answer as the first pass's scalar tests do, bit for bit, and a polygon
// run whose pairs keep their slots from step to step must give every bit of one whose pairs are
// all decided again at every step: each on every instruction set this build compiled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "grainlab/bench_scenes.hpp"
#include "grainlab/world.hpp"
#include "polygon_collider.hpp"
#include "polygon_hold_kernel.hpp"
#include "wide_path_support.hpp"
#include "world_helpers.hpp"

namespace grainlab {
namespace {

// Slots of random hexagon pairs whose features were found at one pose, the bodies then moved
// by amounts spread over four decades around each slot's slack, so both answers are common.
// Some slots are set exactly at the edge of each test (motion equal to the slack, centres
// exactly a reach apart), where < and <= differ, and one body's centre is NaN. The kernel
// does the scalar tests' operations in their order without fused products, so its answers and
// the poses it writes must equal the scalar ones exactly. Two ranges of odd lengths, the
// second starting past slot 0, cover the part-vectors at their ends.
TEST(PolygonHoldKernel, AnswersAsTheFirstPassDoes) {
  if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  PolygonCollider collider(1.0 / 0.0025);
  const int shapes[] = {collider.add(test::ellipseHexagon(0.005)), collider.add(test::ellipseHexagon(0.0045))};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int slots = 1001, split = 499, particles = 2 * slots;
  std::vector<double> position(2 * particles), cosAngle(particles), sinAngle(particles);
  std::vector<std::int64_t> is(slots), js(slots);
  std::vector<double> sign(slots), offsetX(slots), offsetY(slots), lever(slots), ca(slots), sa(slots), cb(slots),
      sb(slots), slack(slots), reach(slots);
  std::vector<bool> expectedFail(slots);
  std::vector<double> expectedPose(8 * static_cast<size_t>(slots));
  int slot = 0;
  while (slot < slots) {
    const int a = shapes[rng() % 2], b = shapes[rng() % 2];
    const double r = collider.polygon(a).circumradius + collider.polygon(b).circumradius;
    const double dir = 2 * kPi * unit(rng), angleA = 2 * kPi * unit(rng), angleB = 2 * kPi * unit(rng);
    const Pose pa{Vec2(0.01 * unit(rng), 0.01 * unit(rng)), std::cos(angleA), std::sin(angleA)};
    const Pose pb{pa.x + (0.5 + 0.5 * unit(rng)) * r * Vec2(std::cos(dir), std::sin(dir)), std::cos(angleB),
                  std::sin(angleB)};
    CachedContact c;
    if (!collider.keepPolygonFeatures(a, pa, b, pb, c)) continue;
    // Moved: a shift and a turn of about 10^(−2..2) times the slack.
    const double scale = c.slack * std::pow(10.0, 4 * unit(rng) - 2);
    const double turnA = scale / c.lever * (2 * unit(rng) - 1), turnB = scale / c.lever * (2 * unit(rng) - 1);
    Pose qa{pa.x + scale * Vec2(2 * unit(rng) - 1, 2 * unit(rng) - 1), std::cos(angleA + turnA),
            std::sin(angleA + turnA)};
    Pose qb{pb.x, std::cos(angleB + turnB), std::sin(angleB + turnB)};
    if (slot % 97 == 7) qa.x.x() = std::numeric_limits<double>::quiet_NaN();
    const auto s = static_cast<size_t>(slot);
    const bool iIsA = rng() % 2 == 0;  // the pair's i is the face's body or the other
    const Pose& pi = iIsA ? qa : qb;
    const Pose& pj = iIsA ? qb : qa;
    is[s] = 2 * slot + (iIsA ? 0 : 1);
    js[s] = 2 * slot + (iIsA ? 1 : 0);
    for (const auto& [index, pose] : {std::pair{is[s], pi}, std::pair{js[s], pj}}) {
      position[2 * static_cast<size_t>(index)] = pose.x.x();
      position[2 * static_cast<size_t>(index) + 1] = pose.x.y();
      cosAngle[static_cast<size_t>(index)] = pose.c;
      sinAngle[static_cast<size_t>(index)] = pose.s;
    }
    // The cache as the pair (i, j) would hold it: anchored at i's and j's poses.
    CachedContact held = c;
    if (!iIsA) {
      held.offset = -c.offset;
      std::swap(held.ca, held.cb);
      std::swap(held.sa, held.sb);
    }
    if (slot % 97 == 3) held.slack = relativeMotion(held, pi, pj);  // motion exactly the slack: fails
    // Centres about a reach apart (the square of the root may round either way).
    const double rr = slot % 97 == 5 ? std::sqrt((pj.x - pi.x).squaredNorm()) : r;
    sign[s] = iIsA ? 1.0 : -1.0;
    offsetX[s] = held.offset.x();
    offsetY[s] = held.offset.y();
    lever[s] = held.lever;
    ca[s] = held.ca;
    sa[s] = held.sa;
    cb[s] = held.cb;
    sb[s] = held.sb;
    slack[s] = held.slack;
    reach[s] = rr;
    // The first pass's tests (ContactSolver::decideWidePair, PolygonCollider::keepPolygonFeatures).
    const bool apart = (pj.x - pi.x).squaredNorm() >= rr * rr;
    expectedFail[s] = apart || !(relativeMotion(held, pi, pj) < held.slack);
    const Pose& ref = iIsA ? pi : pj;
    const Pose& inc = iIsA ? pj : pi;
    const double pose[8] = {ref.x.x(), ref.x.y(), ref.c, ref.s, inc.x.x(), inc.x.y(), inc.c, inc.s};
    std::memcpy(&expectedPose[8 * s], pose, sizeof pose);
    ++slot;
  }
  int fails = 0;
  for (bool f : expectedFail) fails += f;
  // Both answers are exercised.
  ASSERT_GT(fails, slots / 5);
  ASSERT_LT(fails, slots - slots / 5);
  test::onEveryWideTarget([&](const std::string& target) {
    std::vector<double> out(8 * static_cast<size_t>(slots), -7.0);
    std::vector<std::int32_t> failed(slots, -1);
    std::vector<bool> gotFail(slots);
    std::vector<bool> gotFailWithoutPoses(slots);
    for (const auto& [begin, count] : {std::pair{0, split}, std::pair{split, slots - split}}) {
      const auto b = static_cast<size_t>(begin);
      PolygonHoldInput in{};
      in.i = is.data() + b;
      in.j = js.data() + b;
      in.offsetX = offsetX.data() + b;
      in.offsetY = offsetY.data() + b;
      in.lever = lever.data() + b;
      in.ca = ca.data() + b;
      in.sa = sa.data() + b;
      in.cb = cb.data() + b;
      in.sb = sb.data() + b;
      in.slack = slack.data() + b;
      in.reach = reach.data() + b;
      in.particles = {position.data(), cosAngle.data(), sinAngle.data()};
      // Apart slots: no poses.
      int n = holdPolygonSlots(in, count, failed.data() + b);
      for (int f = 0; f < n; ++f) {
        gotFailWithoutPoses[b + static_cast<size_t>(failed[b + static_cast<size_t>(f)])] = true;
      }
      // Face slots: their poses written too.
      in.normalSign = sign.data() + b;
      double* columns[8];
      for (int c = 0; c < 8; ++c) columns[c] = out.data() + static_cast<size_t>(c) * slots + b;
      in.refX = columns[0], in.refY = columns[1], in.refC = columns[2], in.refS = columns[3];
      in.incX = columns[4], in.incY = columns[5], in.incC = columns[6], in.incS = columns[7];
      n = holdPolygonSlots(in, count, failed.data() + b);
      for (int f = 0; f < n; ++f) {
        if (f > 0) {
          EXPECT_LT(failed[b + static_cast<size_t>(f) - 1], failed[b + static_cast<size_t>(f)]) << target;
        }
        gotFail[b + static_cast<size_t>(failed[b + static_cast<size_t>(f)])] = true;
      }
    }
    EXPECT_EQ(gotFail, gotFailWithoutPoses) << target;
    int wrongAnswers = 0, wrongPoses = 0;
    for (int s = 0; s < slots; ++s) {
      wrongAnswers += gotFail[static_cast<size_t>(s)] != expectedFail[static_cast<size_t>(s)];
      for (int c = 0; c < 8; ++c) {
        const double got = out[static_cast<size_t>(c) * slots + static_cast<size_t>(s)];
        const double want = expectedPose[8 * static_cast<size_t>(s) + static_cast<size_t>(c)];
        wrongPoses += std::memcmp(&got, &want, sizeof got) != 0;
      }
    }
    EXPECT_EQ(wrongAnswers, 0) << target;
    EXPECT_EQ(wrongPoses, 0) << target;
  });
}

// A shuffled polygon pile released 8 % closer than its lattice under 50 g: it springs apart
// and settles, so pairs come into and out of face contact, features are searched again and the
// neighbour list is rebuilt. One world keeps its face and apart slots; in the other every pair is decided again
// at every step (a change of thread count lays the slots out afresh, and the thread count
// itself changes no bit: ThreadChange.BetweenStepsKeepsEveryBit). Every bit must agree.
TEST(PolygonPairSlots, KeptSlotsGiveTheBitsOfDecidingEveryPairEveryStep) {
  if (!test::wideSimdBuilt()) GTEST_SKIP() << "this build has no wide path (GRAINLAB_SIMD=OFF)";
  Scene scene = pileScene(12, 12, true);
  std::mt19937_64 rng(3);
  std::shuffle(scene.particles.begin(), scene.particles.end(), rng);
  for (ParticleSpec& p : scene.particles) p.position *= 0.92;
  scene.gravity *= 50;
  test::onEveryWideTarget([&](const std::string& target) {
    const std::unique_ptr<World> kept = test::worldOf(scene, {}), decided = test::worldOf(scene, {});
    for (int k = 0; k < 12000; ++k) {
      decided->setThreads(k % 2 + 1);
      kept->step();
      decided->step();
    }
    const auto bits = [](const World& w) {
      std::vector<double> v;
      for (int p = 0; p < w.size(); ++p) {
        v.insert(v.end(), {w.positions()[p].x(), w.positions()[p].y(), w.angles()[p], w.velocities()[p].x(),
                           w.velocities()[p].y(), w.spins()[p], w.forces()[p].x(), w.forces()[p].y(),
                           w.torques()[p]});
      }
      return v;
    };
    EXPECT_TRUE(test::sameBits(bits(*kept), bits(*decided))) << target;
    EXPECT_EQ(kept->profile().featureSearches, decided->profile().featureSearches) << target;
    // The comparison means something only if slots failed and the list was rebuilt.
    EXPECT_GT(kept->profile().featureSearches, 1000) << target;
    EXPECT_GT(kept->profile().rebuilds, 2) << target;
    std::vector<ContactRecord> contacts;
    kept->contacts(contacts);
    EXPECT_GT(contacts.size(), 100u) << target;
  });
}

}  // namespace
}  // namespace grainlab
