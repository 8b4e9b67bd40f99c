#include "router.hpp"

#include <charconv>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "run_query.hpp"
#include "run_service.hpp"

namespace grainlab::server {
namespace {

using Query = QueryParameters;

std::vector<std::string_view> splitPath(std::string_view path) {
  std::vector<std::string_view> segments;
  std::size_t start = 1;  // after the leading '/'
  while (start <= path.size()) {
    const auto slash = path.find('/', start);
    const auto end = slash == std::string_view::npos ? path.size() : slash;
    segments.push_back(path.substr(start, end - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return segments;
}

Query parseQuery(std::string_view query) {
  Query out;
  while (!query.empty()) {
    const auto amp = query.find('&');
    const auto pair = query.substr(0, amp);
    if (!pair.empty()) {
      const auto eq = pair.find('=');
      auto key = percentDecode(pair.substr(0, eq));
      auto value = percentDecode(eq == std::string_view::npos ? std::string_view() : pair.substr(eq + 1));
      if (!key || !value) throw ApiError(400, "bad percent-encoding in the query", "query");
      // Form encoding writes spaces as '+'.
      for (auto& c : *value)
        if (c == '+') c = ' ';
      out[*key] = *value;
    }
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return out;
}

std::optional<std::int64_t> parseId(std::string_view text) {
  if (text.empty() || text.size() > 18) return std::nullopt;
  std::int64_t id = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), id);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() || id <= 0) return std::nullopt;
  return id;
}

std::int64_t integerParameter(const Query& query, const std::string& key) {
  const auto& text = query.at(key);
  std::int64_t value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || value < 0)
    throw ApiError(400, "must be a non-negative integer", key);
  return value;
}

bool isOneOf(const std::string& method, std::initializer_list<std::string_view> allowed) {
  for (auto m : allowed)
    if (method == m) return true;
  return false;
}

ApiResponse methodNotAllowed(const std::string& method, std::string_view path, std::string allow) {
  auto r = errorResponse(405, method + " is not allowed on " + std::string(path) + "; use " + allow);
  r.headers.emplace_back("Allow", std::move(allow));
  return r;
}

ApiResponse textResponse(int status, std::string contentType, std::string body) {
  ApiResponse r;
  r.status = status;
  r.contentType = std::move(contentType);
  r.body = std::move(body);
  return r;
}

}  // namespace

Router::Router(RunService& service, StaticFiles files) : service_(service), files_(std::move(files)) {}

std::optional<std::int64_t> Router::streamTarget(std::string_view target) {
  target = target.substr(0, target.find('?'));
  constexpr std::string_view prefix = "/api/runs/", suffix = "/stream";
  if (target.size() <= prefix.size() + suffix.size() || !target.starts_with(prefix) || !target.ends_with(suffix))
    return std::nullopt;
  return parseId(target.substr(prefix.size(), target.size() - prefix.size() - suffix.size()));
}

ApiResponse Router::handle(const ApiRequest& request) noexcept {
  try {
    try {
      auto response = route(request);
      if (request.method == "HEAD") response.headOnly = true;
      return response;
    } catch (const ApiError& e) {
      auto r = errorResponse(e.status(), e.what(), e.field());
      if (e.status() == 429) r.headers.emplace_back("Retry-After", "5");
      return r;
    } catch (const std::exception& e) {
      return errorResponse(500, std::string("internal error: ") + e.what());
    }
  } catch (...) {
    // Even building the error failed (out of memory): a bare 500.
    ApiResponse r;
    r.status = 500;
    r.body = R"({"error":"internal error"})";
    return r;
  }
}

ApiResponse Router::route(const ApiRequest& request) {
  const std::string& method = request.method;
  std::string_view target = request.target;
  if (target.empty() || target.front() != '/') throw ApiError(400, "the request target must be a path", "target");
  const auto question = target.find('?');
  const auto rawPath = target.substr(0, question);
  const auto rawQuery = question == std::string_view::npos ? std::string_view() : target.substr(question + 1);
  const auto decoded = percentDecode(rawPath);
  if (!decoded) throw ApiError(400, "bad percent-encoding in the path", "target");
  const std::string& path = *decoded;
  const bool read = isOneOf(method, {"GET", "HEAD"});

  if (path != "/api" && !path.starts_with("/api/")) {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    return files_.get(path, method == "HEAD");
  }

  const auto query = parseQuery(rawQuery);
  const auto seg = splitPath(path);
  const auto noRoute = [&] { return errorResponse(404, "no such endpoint: " + path); };

  if (seg.size() == 2 && seg[1] == "health") {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    return jsonResponse(200, service_.health());
  }
  if (seg.size() == 2 && seg[1] == "presets") {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    return jsonResponse(200, {{"presets", presetNames()}});
  }
  if (seg.size() == 3 && seg[1] == "presets") {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    try {
      return jsonResponse(200, presetScene(std::string(seg[2])));
    } catch (const SceneError&) {
      throw ApiError(404, "no preset '" + std::string(seg[2]) + "'", "preset");
    }
  }
  if (seg.size() == 3 && seg[1] == "sweeps" && seg[2] == "import") {
    if (method != "POST") return methodNotAllowed(method, path, "POST");
    return jsonResponse(200, service_.importSweep(request.body));
  }
  if (seg.size() == 2 && seg[1] == "studies") {
    if (read) return jsonResponse(200, service_.studies());
    if (method != "POST") return methodNotAllowed(method, path, "GET, HEAD, POST");
    const std::string name = service_.launchStudy(request.body);
    auto r = textResponse(201, "application/json", service_.studyText(name));
    r.headers.emplace_back("Location", "/api/studies/" + name);
    return r;
  }
  if (seg.size() == 3 && seg[1] == "studies") {
    if (method == "DELETE") return textResponse(service_.deleteStudy(std::string(seg[2])), "application/json", {});
    if (!read) return methodNotAllowed(method, path, "GET, HEAD, DELETE");
    return textResponse(200, "application/json", service_.studyText(std::string(seg[2])));
  }
  if (seg.size() == 4 && seg[1] == "studies" && seg[3] == "findings") {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    const auto format = query.contains("format") ? query.at("format") : std::string("json");
    if (format != "json" && format != "csv") throw ApiError(400, "must be json or csv", "format");
    std::string body = service_.studyFindings(std::string(seg[2]));
    if (format == "json") return textResponse(200, "application/json", std::move(body));
    return textResponse(200, "text/csv; charset=utf-8", nlohmann::json::parse(body)["csv"].get<std::string>());
  }
  if (seg.size() == 4 && seg[1] == "studies" && seg[3] == "tradeoff") {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    const auto format = query.contains("format") ? query.at("format") : std::string("json");
    if (format != "json" && format != "csv") throw ApiError(400, "must be json or csv", "format");
    std::string body = service_.studyTradeoff(std::string(seg[2]));
    if (format == "json") return textResponse(200, "application/json", std::move(body));
    return textResponse(200, "text/csv; charset=utf-8", nlohmann::json::parse(body)["csv"].get<std::string>());
  }
  if (seg.size() == 4 && seg[1] == "studies" && seg[3] == "bands") {
    if (!read) return methodNotAllowed(method, path, "GET, HEAD");
    return textResponse(200, "application/json", service_.studyBands(std::string(seg[2]), query));
  }
  if (seg.size() == 4 && seg[1] == "studies" && seg[3] == "resume") {
    if (method != "POST") return methodNotAllowed(method, path, "POST");
    auto [status, study] = service_.resumeStudy(std::string(seg[2]));
    return textResponse(status, "application/json", std::move(study));
  }
  if (seg.size() == 4 && seg[1] == "studies" && seg[3] == "cancel") {
    if (method != "POST") return methodNotAllowed(method, path, "POST");
    auto [status, study] = service_.cancelStudy(std::string(seg[2]));
    return textResponse(status, "application/json", std::move(study));
  }
  if (seg.size() < 2 || seg[1] != "runs") return noRoute();

  if (seg.size() == 2) {
    if (read) return jsonResponse(200, service_.list(parseRunQuery(query)));
    if (method != "POST") return methodNotAllowed(method, path, "GET, HEAD, POST");
    const auto id = service_.create(request.body);
    auto r = jsonResponse(201, {{"id", id}});
    r.headers.emplace_back("Location", "/api/runs/" + std::to_string(id));
    return r;
  }

  const auto id = parseId(seg[2]);
  if (seg.size() > 4) return noRoute();
  const std::string_view leaf = seg.size() == 4 ? seg[3] : std::string_view();
  const bool known = seg.size() == 3 || leaf == "series" || leaf == "histograms" || leaf == "frames" ||
                     leaf == "shapes" || leaf == "cancel" || leaf == "resume" || leaf == "stream";
  if (!known) return noRoute();
  if (!id) throw ApiError(404, "no run '" + std::string(seg[2]) + "'");

  if (seg.size() == 3) {
    if (read) return jsonResponse(200, service_.get(*id));
    if (method != "DELETE") return methodNotAllowed(method, path, "GET, HEAD, DELETE");
    service_.remove(*id);
    return textResponse(204, "application/json", {});
  }
  if (leaf == "cancel") {
    if (method != "POST") return methodNotAllowed(method, path, "POST");
    auto [status, run] = service_.cancel(*id);
    return jsonResponse(status, run);
  }
  if (leaf == "resume") {
    if (method != "POST") return methodNotAllowed(method, path, "POST");
    return jsonResponse(202, service_.resume(*id));
  }
  if (!read) return methodNotAllowed(method, path, "GET, HEAD");
  if (leaf == "series") {
    const auto format = query.contains("format") ? query.at("format") : std::string("json");
    if (format == "csv") return textResponse(200, "text/csv; charset=utf-8", service_.seriesCsv(*id));
    if (format != "json") throw ApiError(400, "must be json or csv", "format");
    return jsonResponse(200, service_.series(*id));
  }
  if (leaf == "histograms") {
    const auto latest = query.contains("latest") ? query.at("latest") : std::string("0");
    if (latest != "0" && latest != "1" && latest != "true" && latest != "false")
      throw ApiError(400, "must be 1/true or 0/false", "latest");
    return textResponse(200, "application/json", service_.histograms(*id, latest == "1" || latest == "true"));
  }
  if (leaf == "frames") {
    if (query.contains("index") && query.contains("step"))
      throw ApiError(400, "give index or step, not both", "index");
    if (query.contains("index"))
      return textResponse(200, "application/octet-stream", service_.frame(*id, integerParameter(query, "index"), 0));
    if (query.contains("step"))
      return textResponse(200, "application/octet-stream", service_.frame(*id, -1, integerParameter(query, "step")));
    return jsonResponse(200, service_.frameIndex(*id));
  }
  if (leaf == "shapes") return textResponse(200, "application/json", service_.shapes(*id));
  // leaf == "stream" without an upgrade (the session handles the upgrade before routing).
  if (!service_.exists(*id)) throw ApiError(404, "no run " + std::to_string(*id));
  auto r = errorResponse(426, "this is a WebSocket endpoint: connect with a WebSocket client");
  r.headers.emplace_back("Upgrade", "websocket");
  r.headers.emplace_back("Connection", "Upgrade");
  return r;
}

}  // namespace grainlab::server
