// A study's time left (study_summary.hpp addTimeLeft) from its sums, against the arithmetic
// it promises: the unfinished runs' estimated seconds × (wall ÷ estimate of the completed
// ones) ÷ the runs that go at once.
#include <gtest/gtest.h>

#include "study_summary.hpp"

namespace grainlab::server {
namespace {

TEST(StudyTimeLeft, IsTheEstimatesAtTheMeasuredPaceOverTheRunsGoingAtOnce) {
  StudyPace pace;
  pace.finished = 2;
  pace.finishedEstimated = 10;  // two runs estimated at 5 s each...
  pace.finishedWall = 30;       // ...took 15 s each: the pace is 3
  pace.unfinished = 3;
  pace.unfinishedEstimated = 12;  // e.g. 5 + 5 queued and a running one 60 % done
  nlohmann::json study;
  addTimeLeft(study, pace, 2);
  EXPECT_DOUBLE_EQ(study["seconds_left"].get<double>(), 3.0 * 12 / 2);
  EXPECT_EQ(study["seconds_left_basis"], "measured");
  EXPECT_DOUBLE_EQ(study["pace"]["wall_over_estimate"].get<double>(), 3.0);
  // More slots than runs left: the runs left go at once, no faster.
  addTimeLeft(study, pace, 8);
  EXPECT_DOUBLE_EQ(study["seconds_left"].get<double>(), 3.0 * 12 / 3);
}

TEST(StudyTimeLeft, RestsOnTheEstimatesUntilARunHasCompleted) {
  StudyPace pace;
  pace.unfinished = 4;
  pace.unfinishedEstimated = 20;
  nlohmann::json study;
  addTimeLeft(study, pace, 1);
  EXPECT_DOUBLE_EQ(study["seconds_left"].get<double>(), 20.0);
  EXPECT_EQ(study["seconds_left_basis"], "estimate");
}

TEST(StudyTimeLeft, IsZeroWhenNothingIsLeftAndUnknownWithoutAnEstimate) {
  nlohmann::json study;
  addTimeLeft(study, StudyPace{}, 2);
  EXPECT_EQ(study["seconds_left"].get<double>(), 0.0);
  EXPECT_EQ(study["seconds_left_basis"], "done");
  StudyPace pace;
  pace.unfinished = 2;
  pace.unestimated = 1;
  addTimeLeft(study, pace, 2);
  EXPECT_TRUE(study["seconds_left"].is_null());
  EXPECT_EQ(study["seconds_left_basis"], "unknown");
}

}  // namespace
}  // namespace grainlab::server
