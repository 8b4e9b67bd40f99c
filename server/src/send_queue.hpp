#pragma once
// A WebSocket session's outgoing queue: one message in flight and a bounded backlog behind
// it. A client that reads slowly loses stale frames, histograms and progress ticks, never a
// state change or a sample; a client so far behind that even those exceed the byte budget is
// told to go (the caller closes it) instead of growing the server's memory.
#include <cstddef>
#include <deque>

#include "outgoing.hpp"

namespace grainlab::server {

class SendQueue {
 public:
  struct Limits {
    std::size_t maxFrames = 2;           ///< queued binary frames behind the one in flight
    std::size_t maxBytes = 16u << 20;    ///< all queued messages together
  };

  SendQueue() = default;
  explicit SendQueue(Limits limits) : limits_(limits) {}

  /// Queues a message, dropping what it supersedes. False: over budget, close the client.
  bool push(Outgoing message);
  bool empty() const { return queue_.empty(); }
  /// The next message to write; it stays queued (and undroppable) until pop().
  const Outgoing& front() const { return queue_.front(); }
  /// Marks front() as being written.
  void beginWrite() { inFlight_ = true; }
  /// Removes the written front().
  void pop();
  bool writing() const { return inFlight_; }
  std::size_t size() const { return queue_.size(); }
  std::size_t bytes() const { return bytes_; }
  /// Messages lost to newer ones so far (frames, histograms, progress ticks).
  std::size_t dropped() const { return dropped_; }

 private:
  void erase(std::deque<Outgoing>::iterator it);

  Limits limits_;
  std::deque<Outgoing> queue_;
  std::size_t bytes_ = 0;
  std::size_t dropped_ = 0;
  bool inFlight_ = false;
};

}  // namespace grainlab::server
