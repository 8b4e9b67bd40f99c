#pragma once
// Accepts TCP connections and hands each to an HttpSession on its own strand.
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
  Application& app_;
  unsigned short port_ = 0;
};

}  // namespace grainlab::server
