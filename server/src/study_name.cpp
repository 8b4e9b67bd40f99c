#include "study_name.hpp"

#include <cctype>

#include "api_types.hpp"

namespace grainlab::server {

namespace {
constexpr std::size_t kMaxNameLength = 64;
}

std::string studyName(const nlohmann::ordered_json& spec, const std::optional<std::string>& fallback) {
  if (!spec.contains("name")) {
    if (fallback) return *fallback;
    throw ApiError(400, "a study launched on the server needs a name (letters, digits, '.', '-', '_')", "name");
  }
  if (!spec["name"].is_string()) throw ApiError(400, "must be a string", "name");
  const std::string name = spec["name"].get<std::string>();
  bool ok = !name.empty() && name.size() <= kMaxNameLength && std::isalnum(static_cast<unsigned char>(name[0]));
  for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_');
  if (!ok)
    throw ApiError(400,
                   "must be 1 to " + std::to_string(kMaxNameLength) +
                       " letters, digits, '.', '-' or '_', starting with a letter or digit (got \"" + name + "\")",
                   "name");
  return name;
}

}  // namespace grainlab::server
