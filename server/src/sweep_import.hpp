#pragma once
// A sweep folder (`grainlab sweep`'s DIR) into the runs database: each finished run with its
// scene, how it ended and its whole series, so the dashboard lists and compares them; and the
// sweep as a study, its spec and each run's values in a studies row (source "imported"), so its
// bands group by value as a launched study's do.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace grainlab::server {

class Repository;

struct SweepImport {
  std::vector<std::int64_t> ids;  ///< the runs added, in the sweep's order
  int alreadyThere = 0;           ///< finished runs found in the database already (not added again)
  int notFinished = 0;            ///< runs of the sweep that have not run to an end yet
};

/// Throws std::invalid_argument (saying why) if `dir` is not a sweep folder, or if a study of
/// its name was launched on the server (nothing imported). A run already
/// imported (same name and scene) is not added twice.
SweepImport importSweep(Repository& repo, const std::filesystem::path& dir);

}  // namespace grainlab::server
