#include "api_types.hpp"

#include <nlohmann/json.hpp>

namespace grainlab::server {

ApiResponse jsonResponse(int status, const nlohmann::json& body) {
  ApiResponse r;
  r.status = status;
  // Replace invalid UTF-8 (a scene name, an echoed path) rather than fail the response.
  r.body = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return r;
}

ApiResponse errorResponse(int status, const std::string& message, const std::string& field) {
  nlohmann::json body = {{"error", message}};
  if (!field.empty()) body["field"] = field;
  return jsonResponse(status, body);
}

}  // namespace grainlab::server
