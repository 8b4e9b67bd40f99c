#include "application.hpp"

#include "repository.hpp"
#include "router.hpp"
#include "run_service.hpp"
#include "static_files.hpp"
#include "stream_hub.hpp"

namespace grainlab::server {

Application::Application(const ServeOptions& options)
    : options_(options),
      repo_(std::make_unique<Repository>(options.db)),
      hub_(std::make_unique<StreamHub>()),
      service_(std::make_unique<RunService>(*repo_, *hub_, options_)),
      router_(std::make_unique<Router>(*service_, StaticFiles(options.webRoot))) {}

Application::~Application() { shutdown(); }

void Application::shutdown() { service_->shutdown(); }

}  // namespace grainlab::server
