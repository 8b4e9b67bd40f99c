#pragma once
// The one folder POST /api/sweeps/import may read under (--import-root). A path is resolved
// (symbolic links and ".." followed) before it is compared, and every path outside gets the
// same refusal, existing or not, so the endpoint cannot be used to map the machine's files.
#include <filesystem>
#include <optional>
#include <string>

namespace grainlab::server {

/// `requested` (relative paths are taken under the root) if, resolved, it lies under the
/// resolved `root`; nothing otherwise, or if the root is empty.
std::optional<std::filesystem::path> underImportRoot(const std::string& root, const std::string& requested);

}  // namespace grainlab::server
