#pragma once
// Everything the server is, minus the sockets: storage, the stream hub, the run service and
// the routes, built from ServeOptions. serve() puts Beast in front of it; the tests and the
// fuzzer call its router directly.
#include <memory>

#include "grainlab/server/serve.hpp"

namespace grainlab::server {

class Repository;
class StreamHub;
class RunService;
class Router;

class Application {
 public:
  /// Opens the database (creating it), marking runs left unfinished as interrupted.
  explicit Application(const ServeOptions& options);
  /// Stops the runs and flushes the database.
  ~Application();
  Application(const Application&) = delete;
  Application& operator=(const Application&) = delete;

  const ServeOptions& options() const { return options_; }
  Repository& repository() { return *repo_; }
  StreamHub& hub() { return *hub_; }
  RunService& runs() { return *service_; }
  Router& router() { return *router_; }
  /// Stops the runs (they end `interrupted`) and waits for their records; idempotent.
  void shutdown();

 private:
  ServeOptions options_;
  std::unique_ptr<Repository> repo_;
  std::unique_ptr<StreamHub> hub_;
  std::unique_ptr<RunService> service_;
  std::unique_ptr<Router> router_;
};

}  // namespace grainlab::server
