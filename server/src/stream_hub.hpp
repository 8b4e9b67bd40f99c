#pragma once
// Fan-out of live runs to their watchers (Beast's chat-multi shared_state, per run). The
// simulation thread publishes each message once; the hub remembers what a late joiner needs
// (shapes, latest status, the samples so far, latest histogram, latest frame) and hands the
// same immutable buffer to every subscriber. Subscribers only queue, so publish never waits
// on a network.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "outgoing.hpp"

namespace grainlab::server {

/// Something that sends stream messages to one client (a WebSocket session).
class StreamSink {
 public:
  virtual ~StreamSink() = default;
  /// Queues a message; must return at once (called with the hub's lock held).
  virtual void deliver(const Outgoing& message) = 0;
  /// No more messages will come: close once the queue has drained.
  virtual void finish() = 0;
};

class StreamHub {
 public:
  /// Runs a fan-out job somewhere, in the order given. The default runs it at once on the
  /// publishing thread; the server posts it to one strand of its I/O threads, so the
  /// simulation thread pays one post per message however many clients watch.
  using Dispatcher = std::function<void(std::function<void()>)>;
  void setDispatcher(Dispatcher dispatcher);

  /// Starts a channel for a run that will produce messages.
  void open(std::int64_t runId);
  /// Records the message for late joiners and delivers it to the run's subscribers.
  void publish(std::int64_t runId, const Outgoing& message);
  /// Delivers the current state to the sink, then everything published after. False if the
  /// run has no open channel (it has ended or never existed).
  bool subscribe(std::int64_t runId, const std::shared_ptr<StreamSink>& sink);
  void unsubscribe(std::int64_t runId, const StreamSink* sink);
  /// Ends the channel: subscribers get finish().
  void close(std::int64_t runId);
  /// Watchers of one run, for tests and /api/health.
  std::size_t subscribers(std::int64_t runId) const;
  std::size_t subscribers() const;

 private:
  struct Channel {
    std::vector<std::weak_ptr<StreamSink>> sinks;
    Outgoing shapes, status, histogram, frame;
    std::vector<Outgoing> samples;
  };

  mutable std::mutex mutex_;
  std::map<std::int64_t, Channel> channels_;
  Dispatcher dispatch_ = [](std::function<void()> job) { job(); };
};

}  // namespace grainlab::server
