// The neighbour list carries each persisting pair's contact state across a rebuild whole,
// clears it for a pair that left the list, and keeps it in checkpoints.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "grainlab/state_archive.hpp"
#include "neighbor_list.hpp"

namespace grainlab {
namespace {

// Every slot of a contact's state set to a distinct non-zero value.
void fillContactState(PairState& p, double base) {
  p.history.tangential = base + 1;
  p.history.rolling = base + 2;
  p.fn = base + 3;
  p.ft = base + 4;
  p.overlap = base + 5;
}

bool sameContactState(const PairState& a, const PairState& b) {
  return std::memcmp(&a.history, &b.history, sizeof(ContactHistory)) == 0 && a.fn == b.fn && a.ft == b.ft &&
         a.overlap == b.overlap;
}

struct Scene {
  std::vector<Vec2> positions{{0, 0}, {0.0039, 0}, {1, 0}};  // 0 and 1 touch; 2 is far away
  std::vector<double> radii{0.002, 0.002, 0.002};
  std::vector<Motion> motions{Motion::Dynamic, Motion::Dynamic, Motion::Dynamic};
  std::vector<Wall> walls{Wall{Vec2(0, -0.0019), Vec2(0, 1)}};  // particle 0 rests on it
  double skin = 0.001;

  bool update(NeighborList& list, bool moved) { return list.update(positions, radii, motions, walls, skin, moved); }
};

const PairState* find(const NeighborList& list, int i, int j) {
  for (const PairState& p : list.pairs()) {
    if (p.i == i && p.j == j) return &p;
  }
  return nullptr;
}

TEST(NeighborList, APersistingPairKeepsItsWholeContactStateOverARebuild) {
  Scene s;
  NeighborList list;
  ASSERT_TRUE(s.update(list, false));
  std::vector<PairState> before;
  for (PairState& p : list.pairs()) {
    fillContactState(p, 10.0 * (&p - list.pairs().data()));
    before.push_back(p);
  }
  ASSERT_NE(find(list, 0, 1), nullptr);
  ASSERT_NE(find(list, 0, -1), nullptr);
  // Particle 1 moves by more than half the skin, still within reach of 0: a rebuild.
  s.positions[1].x() += 0.0006;
  ASSERT_TRUE(list.outdated(s.positions, 0, 3));
  ASSERT_TRUE(s.update(list, true));
  for (const PairState& b : before) {
    const PairState* after = find(list, b.i, b.j);
    ASSERT_NE(after, nullptr) << b.i << "," << b.j;
    EXPECT_TRUE(sameContactState(*after, b)) << "pair (" << b.i << ", " << b.j << "): rolling " << after->history.rolling
                                             << " (was " << b.history.rolling << "), tangential "
                                             << after->history.tangential << " (was " << b.history.tangential << ")";
  }
}

TEST(NeighborList, APairThatLeftTheListComesBackWithNoState) {
  Scene s;
  NeighborList list;
  s.update(list, false);
  for (PairState& p : list.pairs()) fillContactState(p, 1);
  s.positions[1].x() += 0.01;  // out of reach: the pair (0, 1) is dropped
  ASSERT_TRUE(s.update(list, true));
  ASSERT_EQ(find(list, 0, 1), nullptr);
  s.positions[1].x() -= 0.01;
  ASSERT_TRUE(s.update(list, true));
  const PairState* back = find(list, 0, 1);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(back->history.tangential, 0);
  EXPECT_EQ(back->history.rolling, 0);
  EXPECT_EQ(back->fn, 0);
  EXPECT_EQ(back->overlap, 0);
}

TEST(NeighborList, ACheckpointKeepsTheHistoryBlock) {
  Scene s;
  NeighborList list;
  s.update(list, false);
  for (PairState& p : list.pairs()) fillContactState(p, 100.0 * (&p - list.pairs().data()));
  StateArchive out;
  list.persist(out, 3, 1);
  NeighborList loaded;
  StateArchive in(out.bytes());
  loaded.persist(in, 3, 1);
  in.expectEnd();
  ASSERT_EQ(loaded.pairs().size(), list.pairs().size());
  for (size_t k = 0; k < list.pairs().size(); ++k) EXPECT_TRUE(sameContactState(loaded.pairs()[k], list.pairs()[k]));
  // And the loaded list carries it over its next rebuild as the original would.
  s.positions[1].x() += 0.0006;
  ASSERT_TRUE(s.update(loaded, true));
  const PairState* p = find(loaded, 0, 1);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->history.rolling, find(list, 0, 1)->history.rolling);
}

}  // namespace
}  // namespace grainlab
