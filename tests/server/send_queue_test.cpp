#include "send_queue.hpp"

#include <gtest/gtest.h>

namespace grainlab::server {
namespace {

Outgoing msg(MessageKind kind, std::string text) { return makeOutgoing(std::move(text), kind); }

std::vector<std::string> drain(SendQueue& q) {
  std::vector<std::string> out;
  while (!q.empty()) {
    out.push_back(*q.front().data);
    q.beginWrite();
    q.pop();
  }
  return out;
}

TEST(SendQueue, DropsTheOldestFramesButNoStatusOrSample) {
  SendQueue q({2, 1 << 20});
  EXPECT_TRUE(q.push(msg(MessageKind::Status, "s1")));
  for (int i = 0; i < 5; ++i) {
    std::string name = "f";
    name += std::to_string(i);  // (gcc 12 warns falsely about "f" + std::to_string(i))
    EXPECT_TRUE(q.push(msg(MessageKind::Frame, name)));
  }
  EXPECT_TRUE(q.push(msg(MessageKind::Sample, "x1")));
  EXPECT_TRUE(q.push(msg(MessageKind::Status, "s2")));
  EXPECT_EQ(drain(q), (std::vector<std::string>{"s1", "f3", "f4", "x1", "s2"}));
  EXPECT_EQ(q.dropped(), 3u);
}

TEST(SendQueue, ANewerHistogramOrProgressTickReplacesAQueuedOne) {
  SendQueue q;
  q.push(msg(MessageKind::Histogram, "h1"));
  q.push(msg(MessageKind::Progress, "p1"));
  q.push(msg(MessageKind::Sample, "x1"));
  q.push(msg(MessageKind::Histogram, "h2"));
  q.push(msg(MessageKind::Progress, "p2"));
  EXPECT_EQ(drain(q), (std::vector<std::string>{"x1", "h2", "p2"}));
}

TEST(SendQueue, NeverDropsTheMessageBeingWritten) {
  SendQueue q({1, 1 << 20});
  q.push(msg(MessageKind::Frame, "f0"));
  q.beginWrite();  // f0 is on the wire
  q.push(msg(MessageKind::Frame, "f1"));
  q.push(msg(MessageKind::Frame, "f2"));
  EXPECT_EQ(*q.front().data, "f0");
  q.pop();
  EXPECT_EQ(drain(q), (std::vector<std::string>{"f2"}));
}

TEST(SendQueue, OverBudgetShedsDroppablesThenGivesUpOnTheClient) {
  SendQueue q({4, 100});
  EXPECT_TRUE(q.push(msg(MessageKind::Frame, std::string(60, 'f'))));
  // The sample fits once the frame is shed.
  EXPECT_TRUE(q.push(msg(MessageKind::Sample, std::string(60, 's'))));
  EXPECT_EQ(q.size(), 1u);
  EXPECT_FALSE(q.push(msg(MessageKind::Status, std::string(60, 't'))));
}

}  // namespace
}  // namespace grainlab::server
