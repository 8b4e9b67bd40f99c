#pragma once
// The dashboard's files under the web root. Paths are percent-decoded first and refused if
// any segment is "..", so neither "/../x" nor "/%2e%2e/x" leaves the root.
#include <optional>
#include <string>
#include <string_view>

#include "api_types.hpp"

namespace grainlab::server {

class StaticFiles {
 public:
  explicit StaticFiles(std::string root) : root_(std::move(root)) {}
  /// GET or HEAD of a decoded path ("/", "/app.js"); "/" and directories serve index.html.
  ApiResponse get(const std::string& path, bool head) const;

 private:
  std::string root_;
};

/// The Content-Type for a file name, by extension ("application/octet-stream" if unknown).
std::string_view mimeType(std::string_view path);
/// Decodes %XX escapes ("+" stays "+": this is a path). Empty optional for a bad escape or a NUL.
std::optional<std::string> percentDecode(std::string_view text);

}  // namespace grainlab::server
