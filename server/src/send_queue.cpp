#include "send_queue.hpp"

#include <algorithm>

namespace grainlab::server {

void SendQueue::erase(std::deque<Outgoing>::iterator it) {
  bytes_ -= it->data->size();
  queue_.erase(it);
  ++dropped_;
}

bool SendQueue::push(Outgoing message) {
  // The message in flight (front, while writing) is never touched: Beast is reading it.
  const auto first = queue_.begin() + (inFlight_ && !queue_.empty() ? 1 : 0);
  if (message.kind == MessageKind::Histogram || message.kind == MessageKind::Progress) {
    const auto kind = message.kind;
    auto it = std::find_if(first, queue_.end(), [kind](const Outgoing& o) { return o.kind == kind; });
    if (it != queue_.end()) erase(it);
  } else if (message.kind == MessageKind::Frame) {
    const auto frames = static_cast<std::size_t>(std::count_if(
        first, queue_.end(), [](const Outgoing& o) { return o.kind == MessageKind::Frame; }));
    if (frames >= limits_.maxFrames) {
      auto begin = queue_.begin() + (inFlight_ && !queue_.empty() ? 1 : 0);
      auto oldest = std::find_if(begin, queue_.end(),
                                 [](const Outgoing& o) { return o.kind == MessageKind::Frame; });
      if (oldest != queue_.end()) erase(oldest);
    }
  }
  bytes_ += message.data->size();
  queue_.push_back(std::move(message));
  if (bytes_ <= limits_.maxBytes) return true;
  // Over budget: shed every droppable message still waiting before giving up on the client.
  for (auto it = queue_.begin() + (inFlight_ ? 1 : 0); it != queue_.end();) {
    const bool droppable = it->kind == MessageKind::Frame || it->kind == MessageKind::Histogram ||
                           it->kind == MessageKind::Progress;
    if (droppable && bytes_ > limits_.maxBytes) {
      bytes_ -= it->data->size();
      ++dropped_;
      it = queue_.erase(it);
    } else {
      ++it;
    }
  }
  return bytes_ <= limits_.maxBytes;
}

void SendQueue::pop() {
  if (queue_.empty()) return;
  bytes_ -= queue_.front().data->size();
  queue_.pop_front();
  inFlight_ = false;
}

}  // namespace grainlab::server
