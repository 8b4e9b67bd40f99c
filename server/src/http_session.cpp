#include "http_session.hpp"

#include <chrono>

#include "access_policy.hpp"
#include "application.hpp"
#include "router.hpp"
#include "run_service.hpp"
#include "websocket_session.hpp"

namespace grainlab::server {
namespace {

constexpr auto kRequestTimeout = std::chrono::seconds(30);
constexpr std::uint32_t kHeaderLimit = 16 * 1024;
constexpr std::uint64_t kMaxDrainBytes = 64ull << 20;

}  // namespace

HttpSession::HttpSession(tcp::socket&& socket, Application& app) : stream_(std::move(socket)), app_(app) {}

void HttpSession::run() {
  net::dispatch(stream_.get_executor(), beast::bind_front_handler(&HttpSession::doRead, shared_from_this()));
}

void HttpSession::doRead() {
  // A fresh parser per request: body_limit applies to one message.
  parser_.emplace();
  parser_->body_limit(app_.options().maxBodyBytes);
  parser_->header_limit(kHeaderLimit);
  stream_.expires_after(kRequestTimeout);
  // The header first: a body past the limit is refused before the client sends it.
  http::async_read_header(stream_, buffer_, *parser_,
                          beast::bind_front_handler(&HttpSession::onHeader, shared_from_this()));
}

void HttpSession::onHeader(beast::error_code ec, std::size_t) {
  if (refused(ec)) return;
  const auto& request = parser_->get();
  // Who may ask, decided on the headers alone, before any body is read.
  beast::error_code peerError;
  const auto peer = stream_.socket().remote_endpoint(peerError).address().to_string();
  AccessRequest access{request.method_string(), request.target(), request[http::field::host],
                       request[http::field::origin], request[http::field::content_type],
                       request[http::field::authorization], request[http::field::cookie], peer,
                       websocket::is_upgrade(request), !parser_->is_done()};
  if (auto answer = app_.access().check(access)) {
    answer->headOnly = request.method() == http::verb::head;
    // A body we will not read: answer, then swallow it and close.
    drainAfterWrite_ = !parser_->is_done();
    send(*answer, request.version(), request.keep_alive() && parser_->is_done());
    return;
  }
  if (!parser_->is_done() && beast::iequals(request[http::field::expect], "100-continue")) {
    // curl waits a second for this before sending a large body.
    auto res = std::make_shared<http::response<http::empty_body>>(http::status::continue_, request.version());
    response_ = res;
    http::async_write(stream_, *res, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->response_.reset();
      if (ec) return self->doClose();
      self->readBody();
    });
    return;
  }
  readBody();
}

void HttpSession::readBody() {
  http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&HttpSession::onRead, shared_from_this()));
}

bool HttpSession::refused(beast::error_code ec) {
  if (!ec) return false;
  if (ec == http::error::end_of_stream) {
    doClose();
  } else if (ec == http::error::body_limit) {
    drainAfterWrite_ = true;
    send(errorResponse(413,
                       "the body is larger than this server's limit of " +
                           std::to_string(app_.options().maxBodyBytes) + " bytes",
                       "body"),
         11, false);
  } else if (ec == http::error::header_limit) {
    drainAfterWrite_ = true;
    send(errorResponse(431, "the request headers are too large"), 11, false);
  } else if (ec == beast::error::timeout || ec == net::error::operation_aborted || ec == net::error::eof ||
             ec == net::error::connection_reset) {
    doClose();
  } else {
    drainAfterWrite_ = true;
    send(errorResponse(400, "malformed HTTP request: " + ec.message()), 11, false);
  }
  return true;
}

void HttpSession::onRead(beast::error_code ec, std::size_t) {
  if (refused(ec)) return;

  auto request = parser_->release();
  if (websocket::is_upgrade(request)) {
    if (auto id = Router::streamTarget(request.target()); id && app_.runs().exists(*id)) {
      // The WebSocket session takes the socket over; this session ends here.
      stream_.expires_never();
      std::make_shared<WebsocketSession>(stream_.release_socket(), app_, *id)->run(std::move(request));
      return;
    }
  }
  ApiRequest api;
  api.method = std::string(request.method_string());
  api.target = std::string(request.target());
  api.body = std::move(request.body());
  send(app_.router().handle(api), request.version(), request.keep_alive());
}

void HttpSession::send(const ApiResponse& r, unsigned version, bool keepAlive) {
  auto res = std::make_shared<http::response<http::string_body>>(static_cast<http::status>(r.status), version);
  res->set(http::field::server, "grainlab");
  if (!(r.status == 204 || r.status == 304)) res->set(http::field::content_type, r.contentType);
  for (const auto& [name, value] : r.headers) res->set(name, value);
  res->keep_alive(keepAlive);
  if (r.headOnly) {
    res->content_length(r.body.size());
  } else {
    res->body() = r.body;
    res->prepare_payload();
  }
  response_ = res;
  http::async_write(stream_, *res, beast::bind_front_handler(&HttpSession::onWrite, shared_from_this(), keepAlive));
}

void HttpSession::onWrite(bool keepAlive, beast::error_code ec, std::size_t) {
  response_.reset();
  if (ec) return doClose();
  if (drainAfterWrite_) return drain();
  if (!keepAlive) return doClose();
  doRead();
}

void HttpSession::drain() {
  beast::error_code ignored;
  stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
  stream_.expires_after(std::chrono::seconds(5));
  stream_.async_read_some(net::buffer(scratch_), beast::bind_front_handler(&HttpSession::onDrain, shared_from_this()));
}

void HttpSession::onDrain(beast::error_code ec, std::size_t bytes) {
  drained_ += bytes;
  if (ec || drained_ > kMaxDrainBytes) return doClose();
  stream_.async_read_some(net::buffer(scratch_), beast::bind_front_handler(&HttpSession::onDrain, shared_from_this()));
}

void HttpSession::doClose() {
  beast::error_code ignored;
  stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
  stream_.socket().close(ignored);
}

}  // namespace grainlab::server
