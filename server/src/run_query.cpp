#include "run_query.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <utility>

#include "api_types.hpp"

namespace grainlab::server {
namespace {

constexpr std::array<std::pair<RunSortKey, std::string_view>, 6> kSortKeys = {{
    {RunSortKey::CreatedAt, "created_at"},
    {RunSortKey::Name, "name"},
    {RunSortKey::Status, "status"},
    {RunSortKey::Preset, "preset"},
    {RunSortKey::WallSeconds, "wall_seconds"},
    {RunSortKey::PeakPhiMobDeg, "peak_phi_mob_deg"},
}};

constexpr std::string_view kKnown = "limit, offset, status, preset, study, q, sort, order";
// Longer filters than this are no one's run name; refused rather than scanned for.
constexpr std::size_t kMaxFilterLength = 256;

std::int64_t integer(const std::string& key, const std::string& text, std::int64_t low, std::int64_t high,
                     const std::string& range) {
  std::int64_t value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || value < low ||
      value > high)
    throw ApiError(400, "must be " + range + " (got '" + text.substr(0, 32) + "')", key);
  return value;
}

std::string filter(const std::string& key, const std::string& value) {
  if (value.size() > kMaxFilterLength)
    throw ApiError(400, "must be at most " + std::to_string(kMaxFilterLength) + " characters", key);
  return value;
}

std::string percentEncode(std::string_view text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == ',') {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

}  // namespace

std::string_view sortKeyName(RunSortKey key) {
  for (const auto& [k, name] : kSortKeys)
    if (k == key) return name;
  return "created_at";
}

RunQuery parseRunQuery(const QueryParameters& parameters) {
  RunQuery q;
  bool orderGiven = false;
  for (const auto& [key, value] : parameters) {
    if (key == "limit") {
      q.limit = integer(key, value, 1, RunQuery::kMaxLimit,
                        "an integer from 1 to " + std::to_string(RunQuery::kMaxLimit));
    } else if (key == "offset") {
      q.offset = integer(key, value, 0, std::int64_t{1} << 53, "a non-negative integer");
    } else if (key == "status") {
      const std::string list = filter(key, value);
      for (std::size_t start = 0; !list.empty();) {
        const auto comma = list.find(',', start);
        const auto name = list.substr(start, comma == std::string::npos ? comma : comma - start);
        const auto status = parseRunStatus(name);
        if (!status)
          throw ApiError(400, "'" + std::string(name) +
                                  "' is not a status (queued, running, completed, failed, cancelled, interrupted)",
                         key);
        q.statuses.push_back(*status);
        if (comma == std::string_view::npos) break;
        start = comma + 1;
      }
    } else if (key == "preset") {
      q.preset = filter(key, value);
    } else if (key == "study") {
      q.study = filter(key, value);
    } else if (key == "q") {
      q.nameContains = filter(key, value);
    } else if (key == "sort") {
      bool found = false;
      for (const auto& [k, name] : kSortKeys)
        if (value == name) q.sort = k, found = true;
      if (!found)
        throw ApiError(400, "must be one of created_at, name, status, preset, wall_seconds, peak_phi_mob_deg", key);
    } else if (key == "order") {
      if (value != "asc" && value != "desc") throw ApiError(400, "must be asc or desc", key);
      q.descending = value == "desc";
      orderGiven = true;
    } else {
      throw ApiError(400, "unknown parameter; GET /api/runs takes " + std::string(kKnown), key);
    }
  }
  // Newest first by default; the other keys read naturally upwards (a to z, short to long).
  if (!orderGiven) q.descending = q.sort == RunSortKey::CreatedAt;
  return q;
}

std::string runQueryString(const RunQuery& q, std::int64_t offset) {
  std::string out;
  auto add = [&](std::string_view key, std::string_view value) {
    if (!out.empty()) out += '&';
    out += key;
    out += '=';
    out += percentEncode(value);
  };
  if (q.limit) add("limit", std::to_string(*q.limit));
  if (offset > 0) add("offset", std::to_string(offset));
  if (!q.statuses.empty()) {
    std::string statuses;
    for (RunStatus s : q.statuses) statuses += (statuses.empty() ? "" : ",") + std::string(toString(s));
    add("status", statuses);
  }
  if (!q.preset.empty()) add("preset", q.preset);
  if (!q.study.empty()) add("study", q.study);
  if (!q.nameContains.empty()) add("q", q.nameContains);
  if (q.sort != RunSortKey::CreatedAt) add("sort", sortKeyName(q.sort));
  add("order", q.descending ? "desc" : "asc");
  return out;
}

}  // namespace grainlab::server
