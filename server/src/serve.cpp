#include "grainlab/server/serve.hpp"

#include <sys/resource.h>

#include <boost/asio/signal_set.hpp>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <thread>
#include <vector>

#include "access_policy.hpp"
#include "access_tokens.hpp"
#include "application.hpp"
#include "listener.hpp"
#include "stream_hub.hpp"

namespace grainlab::server {

int serve(const ServeOptions& options) {
  beast::error_code ec;
  const auto address = net::ip::make_address(options.host, ec);
  if (ec) {
    std::cerr << "grainlab serve: --host " << options.host << " is not an IP address\n";
    return 2;
  }
  AccessTokens tokens;
  try {
    tokens = loadAccessTokens(options, [](const char* name) { return std::getenv(name); });
  } catch (const std::exception& e) {
    std::cerr << "grainlab serve: " << e.what() << "\n";
    return 2;
  }
  std::unique_ptr<Application> app;
  try {
    app = std::make_unique<Application>(options, tokens);
  } catch (const std::exception& e) {
    std::cerr << "grainlab serve: cannot open the database " << options.db << ": " << e.what() << "\n";
    return 1;
  }

  // Every connection holds a file descriptor. The soft limit is often 1,024, which 1,000 idle
  // connections nearly exhaust (new ones then wait until idle ones time out); the hard limit
  // is usually far higher, and raising the soft one to it needs no privilege.
  if (rlimit files{}; getrlimit(RLIMIT_NOFILE, &files) == 0 && files.rlim_cur < files.rlim_max) {
    files.rlim_cur = files.rlim_max;
    setrlimit(RLIMIT_NOFILE, &files);
  }

  const int threads = std::max(1, options.ioThreads);
  // Declared after the application, so destroyed first: its pending handlers hold sessions
  // that refer to the application.
  net::io_context ioc(threads);
  std::shared_ptr<Listener> listener;
  try {
    listener = std::make_shared<Listener>(ioc, tcp::endpoint(address, options.port), *app);
  } catch (const boost::system::system_error& e) {
    std::cerr << "grainlab serve: cannot listen on " << options.host << ":" << options.port << ": "
              << e.code().message() << "\n";
    return 1;
  }
  app->access().setPort(listener->port());
  listener->run();
  // Stream fan-out runs on the I/O threads, in order (one strand), not on the simulation's.
  app->hub().setDispatcher([fanout = net::make_strand(ioc)](std::function<void()> job) {
    net::post(fanout, std::move(job));
  });

  net::signal_set signals(ioc, SIGINT, SIGTERM);
  signals.async_wait([&](const beast::error_code& error, int signal) {
    if (error) return;
    std::cerr << "grainlab serve: " << (signal == SIGINT ? "SIGINT" : "SIGTERM") << ", stopping\n";
    listener->stop();
    ioc.stop();
  });

  std::cerr << "grainlab serve: listening on http://" << options.host << ":" << listener->port()
            << " (database " << options.db << ", web root " << options.webRoot << ")" << std::endl;
  if (app->access().tokenRequired()) {
    // The one place the token is written, for the person who started the server (as Jupyter
    // does); 0.0.0.0 is no address to browse to, so the URL names loopback then.
    std::string host = isUnspecifiedAddress(options.host) ? (address.is_v6() ? "::1" : "127.0.0.1") : options.host;
    if (host.find(':') != std::string::npos) host = "[" + host + "]";
    std::cerr << "grainlab serve: login URL: http://" << host << ":" << listener->port() << "/?token=" << tokens.full
              << std::endl;
  }

  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back([&ioc] { ioc.run(); });
  ioc.run();
  for (auto& t : pool) t.join();

  // Runs still going end `interrupted`; the database gets everything before we return.
  app->shutdown();
  std::cerr << "grainlab serve: stopped" << std::endl;
  return 0;
}

}  // namespace grainlab::server
