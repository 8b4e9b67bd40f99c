// A batch's idle cores go to the running run expected to finish last, one per progress report,
// and come back when that run ends.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core_lending.hpp"

namespace grainlab::studies {
namespace {

// Two runs started together, so their elapsed times are alike and their fractions decide.
void startTwo(CoreLending& lending) {
  lending.started("a");
  lending.started("b");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
}

TEST(CoreLending, NothingIsLentWhileNoCoreIsIdle) {
  CoreLending lending;
  startTwo(lending);
  lending.advanced("a", 0.5);
  lending.advanced("b", 0.1);
  EXPECT_EQ(lending.threadsLent("a"), 0);
  EXPECT_EQ(lending.threadsLent("b"), 0);
}

TEST(CoreLending, AnIdleCoreGoesToTheRunWithTheMostTimeLeft) {
  CoreLending lending;
  startTwo(lending);
  lending.advanced("a", 0.9);  // about a ninth of its time left
  lending.advanced("b", 0.1);  // nine times its time so far left
  lending.release(1);
  lending.advanced("a", 0.9);  // not the neediest: it does not take the core
  EXPECT_EQ(lending.threadsLent("a"), 0);
  EXPECT_EQ(lending.idleCores(), 1);
  lending.advanced("b", 0.1);
  EXPECT_EQ(lending.threadsLent("b"), 1);
  EXPECT_EQ(lending.idleCores(), 0);
}

TEST(CoreLending, ARunThatHasNotReportedIsTheNeediest) {
  CoreLending lending;
  startTwo(lending);
  lending.advanced("a", 0.01);
  lending.release(1);
  lending.advanced("a", 0.01);
  EXPECT_EQ(lending.threadsLent("a"), 0) << "b has all its work ahead of it";
  lending.advanced("b", 0.5);
  EXPECT_EQ(lending.threadsLent("b"), 0) << "once b reports, a (at 1 %) has the more time left";
  lending.advanced("a", 0.01);
  EXPECT_EQ(lending.threadsLent("a"), 1);
}

TEST(CoreLending, ARunsBorrowedCoresGoBackWhenItEnds) {
  CoreLending lending;
  startTwo(lending);
  lending.release(2);
  lending.advanced("b", 0.9);  // a has not reported yet: it is the neediest
  lending.advanced("a", 0.2);
  lending.advanced("a", 0.2);  // with one core lent, a's time left is still the longer
  EXPECT_EQ(lending.threadsLent("a"), 2);
  EXPECT_EQ(lending.finished("a"), 2);
  EXPECT_EQ(lending.idleCores(), 2);
  EXPECT_EQ(lending.threadsLent("a"), 0) << "a has ended";
  lending.advanced("b", 0.95);
  lending.advanced("b", 0.95);
  EXPECT_EQ(lending.threadsLent("b"), 2);
  EXPECT_EQ(lending.finished("b"), 2);
  EXPECT_EQ(lending.idleCores(), 2);
}

TEST(CoreLending, ACoreReleasedWithNoRunGoingWaits) {
  CoreLending lending;
  lending.release(1);
  lending.release(-3);  // nothing to take back
  EXPECT_EQ(lending.idleCores(), 1);
  EXPECT_EQ(lending.finished("never started"), 0);
}

}  // namespace
}  // namespace grainlab::studies
