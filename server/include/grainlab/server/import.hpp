#pragma once
// `grainlab import DIR`: a sweep folder's finished runs into the server's database, beside a
// server that may be running on it (POST /api/sweeps/import does the same through the server).
#include <string>

namespace grainlab::server {

struct ImportReport {
  int imported = 0;      ///< runs added
  int alreadyThere = 0;  ///< found in the database already (same name and scene)
  int notFinished = 0;   ///< not run to an end yet: run the sweep again first
};

/// Throws std::invalid_argument if `dir` is not a sweep folder, std::runtime_error if the
/// database cannot be opened.
ImportReport importSweepFolder(const std::string& dir, const std::string& db);

}  // namespace grainlab::server
