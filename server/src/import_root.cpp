#include "import_root.hpp"

#include <algorithm>

namespace grainlab::server {

std::optional<std::filesystem::path> underImportRoot(const std::string& root, const std::string& requested) {
  namespace fs = std::filesystem;
  if (root.empty() || requested.empty() || requested.find('\0') != std::string::npos) return std::nullopt;
  std::error_code ec;
  const fs::path base = fs::weakly_canonical(fs::absolute(root, ec), ec);
  if (ec) return std::nullopt;
  const fs::path asked = fs::path(requested).is_absolute() ? fs::path(requested) : base / requested;
  // Any failure to resolve (a folder we may not list, say) is "outside": the same answer.
  const fs::path resolved = fs::weakly_canonical(asked, ec);
  if (ec) return std::nullopt;
  // Component by component: /data/root2 is not under /data/root.
  auto b = base.begin(), r = resolved.begin();
  for (; b != base.end(); ++b, ++r) {
    if (b->empty() && std::next(b) == base.end()) break;  // a trailing separator
    if (r == resolved.end() || *b != *r) return std::nullopt;
  }
  return resolved;
}

}  // namespace grainlab::server
