#pragma once
// Everything the server is, minus the sockets: storage, the stream hub, the run service and
// the routes, built from ServeOptions. serve() puts Beast in front of it; the tests and the
// fuzzer call its router directly.
#include <memory>

#include "access_tokens.hpp"
#include "grainlab/server/serve.hpp"

namespace grainlab::server {

class Repository;
class StreamHub;
class RunService;
class Router;
class AccessPolicy;

class Application {
 public:
  /// Opens the database (creating it), marking runs left unfinished as interrupted.
  /// `tokens`: none on loopback, as the tests and the fuzzer run it by default.
  explicit Application(const ServeOptions& options, const AccessTokens& tokens = {});
  /// Stops the runs and flushes the database.
  ~Application();
  Application(const Application&) = delete;
  Application& operator=(const Application&) = delete;

  const ServeOptions& options() const { return options_; }
  Repository& repository() { return *repo_; }
  StreamHub& hub() { return *hub_; }
  RunService& runs() { return *service_; }
  Router& router() { return *router_; }
  /// Host, Origin, token and content-type checks before the routes (access_policy.hpp).
  AccessPolicy& access() { return *access_; }
  /// Stops the runs (they end `interrupted`) and waits for their records; idempotent.
  void shutdown();

 private:
  ServeOptions options_;
  std::unique_ptr<Repository> repo_;
  std::unique_ptr<StreamHub> hub_;
  std::unique_ptr<RunService> service_;
  std::unique_ptr<Router> router_;
  std::unique_ptr<AccessPolicy> access_;
};

}  // namespace grainlab::server
