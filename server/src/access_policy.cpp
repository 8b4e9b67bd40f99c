#include "access_policy.hpp"

#include <arpa/inet.h>

#include <algorithm>
#include <cctype>

#include "static_files.hpp"

namespace grainlab::server {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool contains(const std::vector<std::string>& list, std::string_view value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

bool isIpLiteral(const std::string& host) {
  unsigned char buffer[16];
  return inet_pton(AF_INET, host.c_str(), buffer) == 1 || inet_pton(AF_INET6, host.c_str(), buffer) == 1;
}

bool isReading(std::string_view method) { return method == "GET" || method == "HEAD" || method == "OPTIONS"; }

// "http://Example.org:80" -> "example.org"; "https://x:8443" -> "x:8443"; default ports dropped.
std::string authority(std::string_view scheme, std::string_view hostAndPort) {
  std::string out = lower(hostAndPort);
  if (!out.empty() && out.back() == '/') out.pop_back();
  if (scheme == "http" && out.ends_with(":80")) out.resize(out.size() - 3);
  if (scheme == "https" && out.ends_with(":443")) out.resize(out.size() - 4);
  return out;
}

std::string normalOrigin(std::string_view origin) {
  const auto colon = origin.find("://");
  if (colon == std::string_view::npos) return lower(origin);
  const std::string scheme = lower(origin.substr(0, colon));
  return scheme + "://" + authority(scheme, origin.substr(colon + 3));
}

ApiResponse refusal(int status, const std::string& message) { return errorResponse(status, message); }

}  // namespace

bool isLoopbackAddress(std::string_view address) {
  const std::string text(address);
  unsigned char v4[4];
  if (inet_pton(AF_INET, text.c_str(), v4) == 1) return v4[0] == 127;
  unsigned char v6[16];
  if (inet_pton(AF_INET6, text.c_str(), v6) != 1) return false;
  static constexpr unsigned char loopback[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  if (std::equal(v6, v6 + 16, loopback)) return true;
  static constexpr unsigned char mapped[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff};
  return std::equal(v6, v6 + 12, mapped) && v6[12] == 127;
}

bool isUnspecifiedAddress(std::string_view address) {
  const std::string text(address);
  unsigned char buffer[16] = {};
  if (inet_pton(AF_INET, text.c_str(), buffer) == 1) return std::all_of(buffer, buffer + 4, [](auto b) { return b == 0; });
  if (inet_pton(AF_INET6, text.c_str(), buffer) == 1) return std::all_of(buffer, buffer + 16, [](auto b) { return b == 0; });
  return false;
}

std::string hostName(std::string_view header) {
  header = trim(header);
  std::string_view name = header;
  if (header.starts_with('[')) {
    const auto close = header.find(']');
    name = close == std::string_view::npos ? header.substr(1) : header.substr(1, close - 1);
  } else if (const auto colon = header.rfind(':');
             colon != std::string_view::npos && header.find(':') == colon) {  // not a bare IPv6 address
    name = header.substr(0, colon);
  }
  std::string out = lower(name);
  if (!out.empty() && out.back() == '.') out.pop_back();  // "localhost." is localhost
  return out;
}

bool sameSecret(std::string_view a, std::string_view b) {
  // Length is not secret (every token the server makes has the same); the bytes are.
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

AccessPolicy::AccessPolicy(AccessSettings settings, FailureLimiter::Limits limits)
    : settings_(std::move(settings)), failures_(limits) {
  for (auto& host : settings_.allowedHosts) host = hostName(host);
  for (auto& origin : settings_.allowedOrigins) origin = normalOrigin(origin);
}

bool AccessPolicy::hostAllowed(std::string_view header) const {
  // A client that sends no Host (HTTP/1.0, a script) is no browser, so no rebinding victim.
  if (trim(header).empty()) return true;
  const std::string name = hostName(header);
  if (contains(settings_.allowedHosts, "*") || contains(settings_.allowedHosts, name)) return true;
  // Names that always mean this machine: no DNS answer can point them elsewhere.
  if (name == "localhost" || name.ends_with(".localhost") || isLoopbackAddress(name)) return true;
  if (name == hostName(settings_.bindHost)) return true;
  // Listening on every address: any address of the machine is a fair name for it, and an
  // address (unlike a name) cannot be rebound.
  return isUnspecifiedAddress(settings_.bindHost) && isIpLiteral(name);
}

bool AccessPolicy::originAllowed(std::string_view origin, std::string_view host) const {
  const std::string normal = normalOrigin(trim(origin));
  if (contains(settings_.allowedOrigins, "*") || contains(settings_.allowedOrigins, normal)) return true;
  // The server's own pages: the Origin names the host the request was sent to.
  const auto colon = normal.find("://");
  if (colon == std::string::npos || trim(host).empty()) return false;  // "null", garbage
  const std::string scheme = normal.substr(0, colon);
  if (scheme != "http" && scheme != "https") return false;
  return normal.substr(colon + 3) == authority(scheme, trim(host));
}

std::string AccessPolicy::presentedToken(const AccessRequest& request) const {
  const std::string_view auth = trim(request.authorization);
  if (auth.size() > 7 && lower(auth.substr(0, 7)) == "bearer ") return std::string(trim(auth.substr(7)));
  const std::string name = cookieName();
  std::string_view cookies = request.cookie;
  while (!cookies.empty()) {
    const auto semi = cookies.find(';');
    const std::string_view pair = trim(cookies.substr(0, semi));
    const auto eq = pair.find('=');
    if (eq != std::string_view::npos && pair.substr(0, eq) == name) return std::string(pair.substr(eq + 1));
    if (semi == std::string_view::npos) break;
    cookies.remove_prefix(semi + 1);
  }
  return {};
}

std::optional<ApiResponse> AccessPolicy::check(const AccessRequest& request) {
  if (!hostAllowed(request.host))
    return refusal(421, "this server does not answer to the host name in the request; start it with --allowed-hosts");
  const bool changes = !isReading(request.method);
  if ((changes || request.upgrade) && !trim(request.origin).empty() && !originAllowed(request.origin, request.host))
    return refusal(403, "requests from another site's page are refused; start the server with --allowed-origins");

  // The path as the router will see it: "/%61pi/runs" is /api/runs too.
  const std::string_view rawPath = request.target.substr(0, request.target.find('?'));
  // A path that does not decode is held to the API's rules (the router then refuses it).
  const std::string path = percentDecode(rawPath).value_or("/api/");
  const bool api = path == "/api" || path.starts_with("/api/");
  if (!api) return std::nullopt;  // the dashboard's files: nothing secret, and the login page
  if (path == "/api/health") return std::nullopt;  // a liveness probe needs no secret

  const bool session = path == "/api/session";
  if (tokenRequired()) {
    const auto now = FailureLimiter::Clock::now();
    if (const long wait = failures_.blockedFor(request.peer, now); wait > 0) {
      auto r = refusal(429, "too many wrong tokens from this address; try again later");
      r.headers.emplace_back("Retry-After", std::to_string(wait));
      return r;
    }
    const std::string token = presentedToken(request);
    const bool full = sameSecret(token, settings_.token);
    const bool readOnly = !full && !settings_.readOnlyToken.empty() && sameSecret(token, settings_.readOnlyToken);
    if (!full && !readOnly) {
      if (!token.empty()) failures_.recordFailure(request.peer, now);
      auto r = refusal(401, "a token is required");
      r.headers.emplace_back("WWW-Authenticate", "Bearer");
      return r;
    }
    if (readOnly && changes && !session)
      return refusal(403, "this token may read runs and watch them, not start, stop or delete them");
  }

  if (session) {
    ApiResponse r;
    r.status = 204;
    if (request.method == "POST") {
      // The token itself, out of reach of scripts (HttpOnly) and of other sites' requests
      // (SameSite=Strict); a session cookie, gone when the browser closes.
      if (tokenRequired())
        r.headers.emplace_back("Set-Cookie", cookieName() + "=" + presentedToken(request) +
                                                 "; Path=/; HttpOnly; SameSite=Strict");
    } else if (request.method == "DELETE") {
      r.headers.emplace_back("Set-Cookie", cookieName() + "=; Path=/; HttpOnly; SameSite=Strict; Max-Age=0");
    } else {
      auto refused = refusal(405, "use POST to log in, DELETE to log out");
      refused.headers.emplace_back("Allow", "POST, DELETE");
      return refused;
    }
    return r;
  }

  if (changes) {
    const std::string_view type = trim(request.contentType.substr(0, request.contentType.find(';')));
    if (type.empty() ? request.hasBody : lower(type) != "application/json")
      return refusal(415, "send the body as JSON, with Content-Type: application/json");
  }
  return std::nullopt;
}

}  // namespace grainlab::server
