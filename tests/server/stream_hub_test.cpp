#include "stream_hub.hpp"

#include <gtest/gtest.h>

namespace grainlab::server {
namespace {

struct RecordingSink : StreamSink {
  void deliver(const Outgoing& m) override { got.push_back(*m.data); }
  void finish() override { finished = true; }
  std::vector<std::string> got;
  bool finished = false;
};

Outgoing msg(MessageKind kind, std::string text) { return makeOutgoing(std::move(text), kind); }

TEST(StreamHub, ALateJoinerGetsTheCurrentStateThenLiveMessages) {
  StreamHub hub;
  hub.open(7);
  hub.publish(7, msg(MessageKind::Status, "queued"));
  hub.publish(7, msg(MessageKind::Shapes, "shapes"));
  hub.publish(7, msg(MessageKind::Status, "running"));
  hub.publish(7, msg(MessageKind::Frame, "f1"));
  hub.publish(7, msg(MessageKind::Sample, "x0"));
  hub.publish(7, msg(MessageKind::Histogram, "h0"));
  hub.publish(7, msg(MessageKind::Sample, "x1"));
  hub.publish(7, msg(MessageKind::Histogram, "h1"));
  hub.publish(7, msg(MessageKind::Frame, "f2"));
  hub.publish(7, msg(MessageKind::Progress, "progress"));

  auto sink = std::make_shared<RecordingSink>();
  ASSERT_TRUE(hub.subscribe(7, sink));
  EXPECT_EQ(sink->got, (std::vector<std::string>{"shapes", "progress", "x0", "x1", "h1", "f2"}));
  hub.publish(7, msg(MessageKind::Frame, "f3"));
  hub.publish(7, msg(MessageKind::Status, "completed"));
  hub.close(7);
  EXPECT_EQ(sink->got.back(), "completed");
  EXPECT_TRUE(sink->finished);
  EXPECT_FALSE(hub.subscribe(7, sink));
}

TEST(StreamHub, EveryWatcherGetsTheSameBuffer) {
  StreamHub hub;
  hub.open(1);
  struct PointerSink : StreamSink {
    void deliver(const Outgoing& m) override { last = m.data.get(); }
    void finish() override {}
    const std::string* last = nullptr;
  };
  auto a = std::make_shared<PointerSink>(), b = std::make_shared<PointerSink>();
  hub.subscribe(1, a);
  hub.subscribe(1, b);
  EXPECT_EQ(hub.subscribers(1), 2u);
  hub.publish(1, msg(MessageKind::Frame, "frame"));
  EXPECT_EQ(a->last, b->last);
}

TEST(StreamHub, ThePublisherPaysOneDispatchPerMessageHoweverManyWatch) {
  // The server dispatches to its I/O strand; here the jobs are only collected, so anything a
  // sink did on the publishing thread would show before they run.
  StreamHub hub;
  std::vector<std::function<void()>> jobs;
  hub.setDispatcher([&](std::function<void()> job) { jobs.push_back(std::move(job)); });
  hub.open(1);
  std::vector<std::shared_ptr<RecordingSink>> sinks;
  for (int k = 0; k < 50; ++k) {
    sinks.push_back(std::make_shared<RecordingSink>());
    ASSERT_TRUE(hub.subscribe(1, sinks.back()));
  }
  for (int m = 0; m < 3; ++m) hub.publish(1, msg(MessageKind::Frame, "f" + std::to_string(m)));
  EXPECT_EQ(jobs.size(), 3u);
  for (const auto& sink : sinks) EXPECT_TRUE(sink->got.empty());
  for (auto& job : jobs) job();
  for (const auto& sink : sinks) EXPECT_EQ(sink->got, (std::vector<std::string>{"f0", "f1", "f2"}));
}

TEST(StreamHub, ForgetsWatchersThatAreGone) {
  StreamHub hub;
  hub.open(1);
  auto a = std::make_shared<RecordingSink>();
  auto b = std::make_shared<RecordingSink>();
  hub.subscribe(1, a);
  hub.subscribe(1, b);
  a.reset();
  hub.publish(1, msg(MessageKind::Sample, "x"));
  EXPECT_EQ(hub.subscribers(1), 1u);
  hub.unsubscribe(1, b.get());
  EXPECT_EQ(hub.subscribers(1), 0u);
}

}  // namespace
}  // namespace grainlab::server
