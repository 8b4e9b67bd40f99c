#pragma once
// Who may ask what (docs/security.md): every request's headers pass here before routing, and
// before its body is read. Plain strings in, an answer or nothing out: no sockets, no Beast,
// so the rules are unit-tested and fuzzed on their own.
//   1. Host: a name the server does not go by is refused (421): a page whose DNS name was
//      rebound to this machine never gets an answer.
//   2. Origin: a POST, PUT, PATCH or DELETE, or a WebSocket upgrade, from another site's page
//      is refused (403).
//   3. Token: when the server has one, every /api/ request but GET /api/health must carry it
//      (Authorization: Bearer, or the dashboard's cookie); 401 otherwise. The read-only token
//      may read and watch, not change (403). Repeated wrong tokens from one address get 429.
//   4. A body sent to /api/ must be JSON (415): no HTML form or "simple" cross-site request
//      reaches an endpoint.
// POST /api/session trades a token for the dashboard's HttpOnly, SameSite=Strict cookie.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api_types.hpp"
#include "failure_limiter.hpp"

namespace grainlab::server {

struct AccessSettings {
  std::string bindHost;             ///< the address the server listens on, as given (--host)
  std::string token;                ///< full access; empty = no token asked (loopback only)
  std::string readOnlyToken;        ///< may GET and watch streams; empty = none
  std::vector<std::string> allowedHosts;    ///< more Host names; "*" = any
  std::vector<std::string> allowedOrigins;  ///< more Origins ("https://lab.example"); "*" = any
};

/// The request's headers as sent (empty = absent).
struct AccessRequest {
  std::string_view method;
  std::string_view target;
  std::string_view host;
  std::string_view origin;
  std::string_view contentType;
  std::string_view authorization;
  std::string_view cookie;
  std::string_view peer;  ///< the client's address, for counting its failures
  bool upgrade = false;   ///< a WebSocket upgrade
  bool hasBody = false;   ///< Content-Length > 0 or chunked
};

class AccessPolicy {
 public:
  explicit AccessPolicy(AccessSettings settings, FailureLimiter::Limits limits = {});

  /// Nothing if the request may go on to the routes; otherwise the answer to send instead
  /// (a refusal, or POST/DELETE /api/session's cookie). Thread-safe.
  std::optional<ApiResponse> check(const AccessRequest& request);

  /// The port the server listens on: the cookie is named after it, since browsers share
  /// cookies between the ports of one host. Call before serving.
  void setPort(unsigned short port) { port_ = port; }
  std::string cookieName() const { return "grainlab_token_" + std::to_string(port_); }
  bool tokenRequired() const { return !settings_.token.empty(); }

 private:
  bool hostAllowed(std::string_view host) const;
  bool originAllowed(std::string_view origin, std::string_view host) const;
  std::string presentedToken(const AccessRequest& request) const;

  AccessSettings settings_;
  FailureLimiter failures_;
  unsigned short port_ = 0;
};

/// True for an IPv4 address in 127.0.0.0/8, ::1 or an IPv4-mapped loopback address; false for
/// anything else, names included.
bool isLoopbackAddress(std::string_view address);
/// True for 0.0.0.0 and ::, which listen on every address of the machine.
bool isUnspecifiedAddress(std::string_view address);
/// The host name of a Host header ("Example.org:8080" -> "example.org", "[::1]:80" -> "::1").
std::string hostName(std::string_view hostHeader);
/// Compares two secrets in time that does not depend on where they differ.
bool sameSecret(std::string_view a, std::string_view b);

}  // namespace grainlab::server
