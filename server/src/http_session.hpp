#pragma once
// One HTTP connection: reads a request (with body and header limits and a timeout), answers
// it through the Router, and keeps the connection alive; an upgrade to /api/runs/{id}/stream
// becomes a WebsocketSession.
#include <cstdint>
#include <memory>
#include <optional>

#include "api_types.hpp"
#include "beast.hpp"

namespace grainlab::server {

class Application;

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, Application& app);
  void run();

 private:
  void doRead();
  void onHeader(beast::error_code ec, std::size_t bytes);
  void readBody();
  void onRead(beast::error_code ec, std::size_t bytes);
  /// Answers a failed read (413, 431, 400) or closes; false if there was no error.
  bool refused(beast::error_code ec);
  void send(const ApiResponse& response, unsigned version, bool keepAlive);
  void onWrite(bool keepAlive, beast::error_code ec, std::size_t bytes);
  /// After refusing a request mid-body: stop sending, swallow what the client still sends
  /// (so closing does not reset the connection under the response), then close.
  void drain();
  void onDrain(beast::error_code ec, std::size_t bytes);
  void doClose();

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  Application& app_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<void> response_;  // keeps the response alive while it is written
  bool drainAfterWrite_ = false;
  std::uint64_t drained_ = 0;
  char scratch_[16384];
};

}  // namespace grainlab::server
