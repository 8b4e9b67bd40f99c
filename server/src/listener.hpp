#pragma once
// Accepts TCP connections and hands each to an HttpSession on its own strand.
#include <boost/asio/steady_timer.hpp>
#include <cstdint>
#include <memory>

#include "beast.hpp"

namespace grainlab::server {

class Application;

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  /// Binds and listens; throws boost::system::system_error if the address is unusable.
  Listener(net::io_context& ioc, const tcp::endpoint& endpoint, Application& app);
  /// Starts accepting.
  void run();
  /// Stops accepting (open sessions go on until the io_context stops).
  void stop();
  /// The bound port (the real one when asked for port 0).
  unsigned short port() const { return port_; }

 private:
  void doAccept();
  void onAccept(beast::error_code ec, tcp::socket socket);

  net::io_context& ioc_;
  tcp::acceptor acceptor_;
  /// After a failed accept (out of file descriptors: every connection held open, say), the
  /// next waits on this rather than failing again at once: a loop on the error would take a
  /// core and fill the log while the held connections time out.
  net::steady_timer retry_;
  std::uint64_t failedAccepts_ = 0;  ///< in a row, since the last accept that worked
  Application& app_;
  unsigned short port_ = 0;
};

}  // namespace grainlab::server
