#include "websocket_session.hpp"

#include "application.hpp"
#include "run_service.hpp"

namespace grainlab::server {

WebsocketSession::WebsocketSession(tcp::socket&& socket, Application& app, std::int64_t runId)
    : ws_(std::move(socket)), app_(app), runId_(runId) {}

void WebsocketSession::run(http::request<http::string_body> request) {
  auto timeouts = websocket::stream_base::timeout::suggested(beast::role_type::server);
  // Pings keep a quiet but healthy watcher connected through long stages; a peer that stops
  // answering them is dropped.
  timeouts.keep_alive_pings = true;
  ws_.set_option(timeouts);
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& res) { res.set(http::field::server, "grainlab"); }));
  // Accept on this session's strand (the socket's executor).
  net::dispatch(ws_.get_executor(), [self = shared_from_this(), request = std::move(request)]() mutable {
    self->ws_.async_accept(request, beast::bind_front_handler(&WebsocketSession::onAccept, self));
  });
}

void WebsocketSession::onAccept(beast::error_code ec) {
  if (ec) return;
  open_ = true;
  doRead();
  // After the handshake: what the run has so far, then everything it publishes.
  if (!app_.runs().watch(runId_, shared_from_this())) {
    ws_.async_close(websocket::close_reason(websocket::close_code::going_away, "run deleted"),
                    beast::bind_front_handler(&WebsocketSession::onClose, shared_from_this()));
    closing_ = true;
  }
}

void WebsocketSession::doRead() {
  ws_.async_read(buffer_, beast::bind_front_handler(&WebsocketSession::onRead, shared_from_this()));
}

void WebsocketSession::onRead(beast::error_code ec, std::size_t) {
  if (ec) {
    // Closed by the client, the server or a timeout: stop watching. (Not in the destructor:
    // the hub may be destroying the last reference while it holds its lock.)
    open_ = false;
    app_.hub().unsubscribe(runId_, this);
    return;
  }
  // Clients have nothing to say yet; what they send is read and ignored.
  buffer_.consume(buffer_.size());
  doRead();
}

void WebsocketSession::deliver(const Outgoing& message) {
  net::post(ws_.get_executor(), beast::bind_front_handler(&WebsocketSession::onDeliver, shared_from_this(), message));
}

void WebsocketSession::finish() {
  net::post(ws_.get_executor(), beast::bind_front_handler(&WebsocketSession::onFinish, shared_from_this()));
}

void WebsocketSession::onDeliver(Outgoing message) {
  if (closing_) return;
  if (!queue_.push(std::move(message))) return abort();  // too far behind even without frames
  if (open_ && !queue_.writing()) writeNext();
}

void WebsocketSession::onFinish() {
  finishing_ = true;
  if (open_ && !queue_.writing() && queue_.empty() && !closing_) {
    closing_ = true;
    ws_.async_close(websocket::close_code::normal,
                    beast::bind_front_handler(&WebsocketSession::onClose, shared_from_this()));
  }
}

void WebsocketSession::writeNext() {
  const Outgoing& next = queue_.front();
  queue_.beginWrite();
  ws_.binary(next.binary());
  ws_.async_write(net::buffer(*next.data), beast::bind_front_handler(&WebsocketSession::onWrite, shared_from_this()));
}

void WebsocketSession::onWrite(beast::error_code ec, std::size_t) {
  queue_.pop();
  if (ec) return abort();
  if (!queue_.empty()) return writeNext();
  if (finishing_) onFinish();
}

void WebsocketSession::onClose(beast::error_code) {
  // The read loop ends on its own once the close handshake completes.
}

void WebsocketSession::abort() {
  closing_ = true;
  open_ = false;
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
  beast::get_lowest_layer(ws_).close();
}

}  // namespace grainlab::server
