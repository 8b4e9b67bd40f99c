#pragma once
// The handler's view of HTTP: plain structs, so the routes can be called (and fuzzed) without
// sockets or Beast, plus the shared error helpers every route answers with.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace grainlab::server {

struct ApiRequest {
  std::string method;   ///< "GET", "POST"...
  std::string target;   ///< path and query as sent, e.g. "/api/runs/3/series?format=csv"
  std::string body;
};

struct ApiResponse {
  int status = 200;
  std::string contentType = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  ///< extra: Allow, Retry-After...
  /// HEAD: send the headers (and the body's length) without the body.
  bool headOnly = false;
};

/// A request the server refuses: the status, a message for a person and, for bad input, the
/// field at fault (a JSON path such as "material.friction").
class ApiError : public std::runtime_error {
 public:
  ApiError(int status, const std::string& message, std::string field = {})
      : std::runtime_error(message), status_(status), field_(std::move(field)) {}
  int status() const { return status_; }
  const std::string& field() const { return field_; }

 private:
  int status_;
  std::string field_;
};

/// 2xx/4xx with a JSON body.
ApiResponse jsonResponse(int status, const nlohmann::json& body);
/// {"error": message[, "field": field]} with the status.
ApiResponse errorResponse(int status, const std::string& message, const std::string& field = {});

}  // namespace grainlab::server
