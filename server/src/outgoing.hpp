#pragma once
// One stream message, built once and shared by every session that sends it.
#include <memory>
#include <string>

namespace grainlab::server {

/// What a message is decides what a slow client may lose.
enum class MessageKind {
  Status,     ///< run state changes: never dropped
  Progress,   ///< a status message that only moves progress on: a newer one replaces it
  Shapes,     ///< never dropped
  Sample,     ///< never dropped
  Histogram,  ///< a newer one replaces it
  Frame,      ///< binary; the oldest queued frames are dropped first
};

struct Outgoing {
  std::shared_ptr<const std::string> data;
  MessageKind kind = MessageKind::Status;
  bool binary() const { return kind == MessageKind::Frame; }
};

inline Outgoing makeOutgoing(std::string text, MessageKind kind) {
  return {std::make_shared<const std::string>(std::move(text)), kind};
}

}  // namespace grainlab::server
