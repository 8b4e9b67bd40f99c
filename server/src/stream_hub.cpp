#include "stream_hub.hpp"

#include <algorithm>

namespace grainlab::server {

void StreamHub::setDispatcher(Dispatcher dispatcher) {
  std::lock_guard lock(mutex_);
  dispatch_ = std::move(dispatcher);
}

void StreamHub::open(std::int64_t runId) {
  std::lock_guard lock(mutex_);
  channels_.try_emplace(runId);
}

void StreamHub::publish(std::int64_t runId, const Outgoing& message) {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(runId);
  if (it == channels_.end()) return;
  Channel& ch = it->second;
  switch (message.kind) {
    case MessageKind::Shapes: ch.shapes = message; break;
    case MessageKind::Status:
    case MessageKind::Progress: ch.status = message; break;
    case MessageKind::Sample: ch.samples.push_back(message); break;
    case MessageKind::Histogram: ch.histogram = message; break;
    case MessageKind::Frame: ch.frame = message; break;
  }
  std::erase_if(ch.sinks, [](const std::weak_ptr<StreamSink>& weak) { return weak.expired(); });
  if (ch.sinks.empty()) return;
  // Dispatched under the lock with the watchers of this moment: every sink sees messages in
  // publish order, and one that subscribes later has this message in its snapshot instead.
  dispatch_([sinks = ch.sinks, message] {
    for (const auto& weak : sinks)
      if (auto sink = weak.lock()) sink->deliver(message);
  });
}

bool StreamHub::subscribe(std::int64_t runId, const std::shared_ptr<StreamSink>& sink) {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(runId);
  if (it == channels_.end()) return false;
  Channel& ch = it->second;
  // A late joiner starts from the current state.
  if (ch.shapes.data) sink->deliver(ch.shapes);
  if (ch.status.data) sink->deliver(ch.status);
  for (const auto& sample : ch.samples) sink->deliver(sample);
  if (ch.histogram.data) sink->deliver(ch.histogram);
  if (ch.frame.data) sink->deliver(ch.frame);
  ch.sinks.push_back(sink);
  return true;
}

void StreamHub::unsubscribe(std::int64_t runId, const StreamSink* sink) {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(runId);
  if (it == channels_.end()) return;
  std::erase_if(it->second.sinks, [sink](const std::weak_ptr<StreamSink>& weak) {
    auto s = weak.lock();
    return !s || s.get() == sink;
  });
}

void StreamHub::close(std::int64_t runId) {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(runId);
  if (it == channels_.end()) return;
  // After the fan-out of everything published before: finish() comes after the last status.
  dispatch_([sinks = std::move(it->second.sinks)] {
    for (const auto& weak : sinks)
      if (auto sink = weak.lock()) sink->finish();
  });
  channels_.erase(it);
}

std::size_t StreamHub::subscribers(std::int64_t runId) const {
  std::lock_guard lock(mutex_);
  auto it = channels_.find(runId);
  return it == channels_.end() ? 0 : it->second.sinks.size();
}

std::size_t StreamHub::subscribers() const {
  std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const auto& [id, ch] : channels_) n += ch.sinks.size();
  return n;
}

}  // namespace grainlab::server
