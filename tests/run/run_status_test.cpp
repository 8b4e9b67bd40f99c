// The run statuses' one spelling: what summary.json, the HTTP API and the database say
// (docs/http-api.md), read back to the same status; anything else is no status at all.
#include <gtest/gtest.h>

#include "grainlab/run_status.hpp"

namespace grainlab {
namespace {

TEST(RunStatus, EachStatusHasTheApiSpellingAndReadsBack) {
  const std::pair<RunStatus, const char*> api[] = {
      {RunStatus::Queued, "queued"},       {RunStatus::Running, "running"},
      {RunStatus::Completed, "completed"}, {RunStatus::Failed, "failed"},
      {RunStatus::Cancelled, "cancelled"}, {RunStatus::Interrupted, "interrupted"},
  };
  for (const auto& [status, text] : api) {
    EXPECT_EQ(toString(status), text);
    EXPECT_EQ(parseRunStatus(text), status) << text;
  }
}

TEST(RunStatus, OtherStringsAreNoStatus) {
  for (const char* text : {"", "Completed", "complete", "done", "completed ", "unknown"})
    EXPECT_FALSE(parseRunStatus(text).has_value()) << '"' << text << '"';
}

TEST(RunStatus, OnlyQueuedAndRunningHaveNotEnded) {
  EXPECT_FALSE(hasEnded(RunStatus::Queued));
  EXPECT_FALSE(hasEnded(RunStatus::Running));
  for (RunStatus s : {RunStatus::Completed, RunStatus::Failed, RunStatus::Cancelled, RunStatus::Interrupted})
    EXPECT_TRUE(hasEnded(s)) << s;
}

}  // namespace
}  // namespace grainlab
