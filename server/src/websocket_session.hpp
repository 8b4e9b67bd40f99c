#pragma once
// One client watching one run over a WebSocket. Messages arrive from the hub on any thread and
// are posted to this session's strand; one write is in flight at a time and the rest wait in
// a bounded SendQueue, so a slow client loses stale frames and never holds up the run or the
// other clients. Binary messages are particle frames; text messages are JSON.
#include <cstdint>
#include <memory>

#include "beast.hpp"
#include "send_queue.hpp"
#include "stream_hub.hpp"

namespace grainlab::server {

class Application;

class WebsocketSession : public StreamSink, public std::enable_shared_from_this<WebsocketSession> {
 public:
  WebsocketSession(tcp::socket&& socket, Application& app, std::int64_t runId);
  /// Accepts the upgrade request, then subscribes to the run.
  void run(http::request<http::string_body> request);

  /// Any thread: queues the message on this session's strand.
  void deliver(const Outgoing& message) override;
  /// Any thread: close once everything queued has been written.
  void finish() override;

 private:
  void onAccept(beast::error_code ec);
  void doRead();
  void onRead(beast::error_code ec, std::size_t bytes);
  void onDeliver(Outgoing message);
  void onFinish();
  void writeNext();
  void onWrite(beast::error_code ec, std::size_t bytes);
  void onClose(beast::error_code ec);
  /// The connection is gone or hopeless: drop it without a handshake.
  void abort();

  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  Application& app_;
  const std::int64_t runId_;
  SendQueue queue_;
  bool open_ = false;       // handshake done, not yet closing
  bool finishing_ = false;  // close after the queue drains
  bool closing_ = false;
};

}  // namespace grainlab::server
