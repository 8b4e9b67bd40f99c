#include "application.hpp"

#include "access_policy.hpp"
#include "repository.hpp"
#include "router.hpp"
#include "run_service.hpp"
#include "static_files.hpp"
#include "stream_hub.hpp"

namespace grainlab::server {

Application::Application(const ServeOptions& options, const AccessTokens& tokens)
    : options_(options),
      repo_(std::make_unique<Repository>(options.db)),
      hub_(std::make_unique<StreamHub>()),
      service_(std::make_unique<RunService>(*repo_, *hub_, options_)),
      router_(std::make_unique<Router>(*service_, StaticFiles(options.webRoot))),
      access_(std::make_unique<AccessPolicy>(AccessSettings{options.host, tokens.full, tokens.readOnly,
                                                             options.allowedHosts, options.allowedOrigins})) {}

Application::~Application() { shutdown(); }

void Application::shutdown() { service_->shutdown(); }

}  // namespace grainlab::server
