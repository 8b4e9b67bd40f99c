#pragma once
// Which runs a list asks for (GET /api/runs?...): filters, an order and a page. Parsed from
// the query string with every bad parameter refused by name; the repository turns it into one
// SQL statement that an index serves (Repository::listRuns).
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "run_record.hpp"

namespace grainlab::server {

/// The orders a list can have. Each is backed by an index on (key, created_at, id): ties go
/// by creation, then id, in the same direction.
enum class RunSortKey { CreatedAt, Name, Status, Preset, WallSeconds, PeakPhiMobDeg };

struct RunQuery {
  std::vector<RunStatus> statuses;   ///< any of these; empty: any status
  std::string preset;                ///< exact; empty: any
  std::string study;                 ///< exact; empty: any
  std::string nameContains;          ///< case-insensitive (ASCII) substring of the name; empty: any
  RunSortKey sort = RunSortKey::CreatedAt;
  bool descending = true;
  std::optional<std::int64_t> limit; ///< none: every matching run (the list before paging)
  std::int64_t offset = 0;

  static constexpr std::int64_t kMaxLimit = 1000;
};

using QueryParameters = std::map<std::string, std::string, std::less<>>;

/// GET /api/runs's parameters: limit, offset, status (comma-separated), preset, study, q,
/// sort, order. Throws ApiError 400 naming the parameter and why for an unknown parameter or
/// a bad value. An empty filter (`q=`) filters nothing, as an empty form box means.
RunQuery parseRunQuery(const QueryParameters& parameters);

/// The query string (without '?') that asks for the same runs in the same order from
/// `offset` on: the `next` link of a page.
std::string runQueryString(const RunQuery& query, std::int64_t offset);

/// The name a sort key has in the API ("created_at", "name", ...).
std::string_view sortKeyName(RunSortKey key);

}  // namespace grainlab::server
