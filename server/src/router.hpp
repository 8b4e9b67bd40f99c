#pragma once
// The routes: one plain request -> response function over the service and the static files
// (Beast's advanced server keeps its handler so; it is what the fuzzer calls). Every refusal
// is a JSON {"error", "field"?} with its status: 400 bad input, 404 unknown route or id,
// 405 wrong method (with Allow), 409 a run that has already ended, 413 too big (from the
// session), 426 a stream without the upgrade, 429 queue full, 503 past the particle limit.
#include <cstdint>
#include <optional>
#include <string_view>

#include "api_types.hpp"
#include "static_files.hpp"

namespace grainlab::server {

class RunService;

class Router {
 public:
  Router(RunService& service, StaticFiles files);

  /// Never throws: an unexpected failure is a 500 with its message.
  ApiResponse handle(const ApiRequest& request) noexcept;

  /// The run id if the target is /api/runs/{id}/stream (query ignored).
  static std::optional<std::int64_t> streamTarget(std::string_view target);

 private:
  ApiResponse route(const ApiRequest& request);

  RunService& service_;
  StaticFiles files_;
};

}  // namespace grainlab::server
