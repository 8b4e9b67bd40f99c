// The access rules on their own (access_policy.hpp): each attack of docs/security.md as the
// headers a browser or a script would send, and the requests the dashboard and clients make.
#include "access_policy.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "access_tokens.hpp"

namespace grainlab::server {
namespace {

const std::string kToken = "0123456789abcdef0123456789abcdef";
const std::string kReadOnly = "fedcba9876543210fedcba9876543210";

AccessRequest get(std::string_view target, std::string_view host = "127.0.0.1:8080") {
  AccessRequest r;
  r.method = "GET";
  r.target = target;
  r.host = host;
  r.peer = "127.0.0.1";
  return r;
}

AccessRequest post(std::string_view target, std::string_view host = "127.0.0.1:8080") {
  AccessRequest r = get(target, host);
  r.method = "POST";
  r.contentType = "application/json";
  r.hasBody = true;
  return r;
}

int status(AccessPolicy& policy, const AccessRequest& request) {
  const auto answer = policy.check(request);
  return answer ? answer->status : 0;  // 0: on to the routes
}

AccessPolicy loopback() { return AccessPolicy({"127.0.0.1", "", "", {}, {}}); }
AccessPolicy withTokens(std::string bind = "0.0.0.0") { return AccessPolicy({bind, kToken, kReadOnly, {}, {}}); }

TEST(AccessPolicy, LoopbackWithoutTokenAnswersItsOwnPagesAndScripts) {
  auto policy = loopback();
  EXPECT_EQ(status(policy, get("/api/runs")), 0);
  EXPECT_EQ(status(policy, get("/api/runs", "localhost:8080")), 0);
  EXPECT_EQ(status(policy, post("/api/runs")), 0);
  auto own = post("/api/runs");
  own.origin = "http://127.0.0.1:8080";
  EXPECT_EQ(status(policy, own), 0);
  auto del = get("/api/runs/1");
  del.method = "DELETE";
  EXPECT_EQ(status(policy, del), 0);  // curl: no Origin, no body
}

TEST(AccessPolicy, ForeignHostIsRefusedBeforeAnythingElse) {
  auto policy = loopback();
  // A page at evil.example whose name now resolves to 127.0.0.1 (DNS rebinding).
  EXPECT_EQ(status(policy, get("/api/runs", "evil.example:8080")), 421);
  EXPECT_EQ(status(policy, get("/", "evil.example")), 421);
  EXPECT_EQ(status(policy, get("/api/health", "evil.example")), 421);
  EXPECT_EQ(status(policy, get("/api/runs", "localhost.evil.example")), 421);
  // Loopback names and addresses are never rebound.
  for (const char* host : {"localhost", "LOCALHOST:1", "app.localhost", "127.0.0.2:9", "[::1]:8080", "localhost."})
    EXPECT_EQ(status(policy, get("/api/runs", host)), 0) << host;
  // Another machine's address is no name of a loopback-bound server.
  EXPECT_EQ(status(policy, get("/api/runs", "10.0.0.5:8080")), 421);
}

TEST(AccessPolicy, AllowedHostsAndEveryAddressOfAnUnspecifiedBind) {
  AccessPolicy named({"127.0.0.1", "", "", {"lab.example", "Other.Example:443"}, {}});
  EXPECT_EQ(status(named, get("/api/runs", "lab.example:8080")), 0);
  EXPECT_EQ(status(named, get("/api/runs", "other.example")), 0);
  EXPECT_EQ(status(named, get("/api/runs", "evil.example")), 421);
  AccessPolicy any({"0.0.0.0", kToken, "", {}, {}});
  auto request = get("/api/health", "192.168.1.20:8080");
  EXPECT_EQ(status(any, request), 0);
  EXPECT_EQ(status(any, get("/api/health", "lab.example:8080")), 421);
  AccessPolicy star({"0.0.0.0", kToken, "", {"*"}, {}});
  EXPECT_EQ(status(star, get("/api/health", "lab.example:8080")), 0);
}

TEST(AccessPolicy, ChangesFromAnotherSitesPageAreRefused) {
  auto policy = loopback();
  // A "simple" cross-site POST: text/plain needs no CORS preflight.
  auto csrf = post("/api/runs");
  csrf.origin = "http://evil.example";
  csrf.contentType = "text/plain;charset=UTF-8";
  EXPECT_EQ(status(policy, csrf), 403);
  auto del = get("/api/runs/1");
  del.method = "DELETE";
  del.origin = "http://evil.example";
  EXPECT_EQ(status(policy, del), 403);
  del.origin = "null";  // a sandboxed frame
  EXPECT_EQ(status(policy, del), 403);
  del.origin = "http://127.0.0.1:9999";  // another port is another origin
  EXPECT_EQ(status(policy, del), 403);
  // Cross-site WebSocket hijacking: the upgrade is a GET, checked all the same.
  auto ws = get("/api/runs/1/stream");
  ws.upgrade = true;
  ws.origin = "http://evil.example";
  EXPECT_EQ(status(policy, ws), 403);
  ws.origin = "http://127.0.0.1:8080";
  EXPECT_EQ(status(policy, ws), 0);
  // Reading is left to the browser's same-origin rule: a foreign page cannot see the answer.
  auto read = get("/api/runs");
  read.origin = "http://evil.example";
  EXPECT_EQ(status(policy, read), 0);
}

TEST(AccessPolicy, OwnOriginBehindAProxyAndAllowedOrigins) {
  auto policy = loopback();
  auto own = post("/api/runs", "localhost");
  own.origin = "http://localhost:80";  // default port written out
  EXPECT_EQ(status(policy, own), 0);
  AccessPolicy proxied({"127.0.0.1", "", "", {}, {"https://lab.example/"}});
  auto viaProxy = post("/api/runs", "127.0.0.1:8080");  // the proxy rewrote Host
  viaProxy.origin = "https://lab.example";
  EXPECT_EQ(status(proxied, viaProxy), 0);
  viaProxy.origin = "https://evil.example";
  EXPECT_EQ(status(proxied, viaProxy), 403);
}

TEST(AccessPolicy, JsonEndpointsTakeOnlyJson) {
  auto policy = loopback();
  for (const char* type : {"text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x"}) {
    auto request = post("/api/runs");
    request.contentType = type;
    EXPECT_EQ(status(policy, request), 415) << type;
  }
  auto noType = post("/api/runs");
  noType.contentType = "";
  EXPECT_EQ(status(policy, noType), 415);
  auto charset = post("/api/runs");
  charset.contentType = "Application/JSON; charset=utf-8";
  EXPECT_EQ(status(policy, charset), 0);
  auto cancel = post("/api/runs/1/cancel");  // no body, no type: fine
  cancel.contentType = "";
  cancel.hasBody = false;
  EXPECT_EQ(status(policy, cancel), 0);
  cancel.contentType = "text/plain";  // a simple request even without a body
  EXPECT_EQ(status(policy, cancel), 415);
  // Percent-encoding does not take a path out of /api/.
  auto encoded = post("/%61pi/runs");
  encoded.contentType = "text/plain";
  EXPECT_EQ(status(policy, encoded), 415);
}

TEST(AccessPolicy, TokenRequiredForTheApiButNotForHealthOrTheDashboardFiles) {
  auto policy = withTokens();
  EXPECT_EQ(status(policy, get("/api/runs")), 401);
  EXPECT_EQ(policy.check(get("/api/runs"))->body.find(kToken), std::string::npos);
  EXPECT_EQ(status(policy, get("/%61pi/runs")), 401);
  EXPECT_EQ(status(policy, get("/%:bad-escape")), 401);  // found by fuzz_http: held to the API's rules
  EXPECT_EQ(status(policy, get("/api/health")), 0);
  EXPECT_EQ(status(policy, get("/")), 0);
  EXPECT_EQ(status(policy, get("/js/main.js")), 0);
  auto bearer = get("/api/runs");
  const std::string header = "Bearer " + kToken;
  bearer.authorization = header;
  EXPECT_EQ(status(policy, bearer), 0);
  const std::string wrongHeader = "Bearer " + kToken.substr(1) + "x";
  bearer.authorization = wrongHeader;
  EXPECT_EQ(status(policy, bearer), 401);
  bearer.authorization = "Basic " + kToken;
  EXPECT_EQ(status(policy, bearer), 401);
}

TEST(AccessPolicy, ReadOnlyTokenReadsAndWatchesButChangesNothing) {
  auto policy = withTokens();
  const std::string header = "Bearer " + kReadOnly;
  auto read = get("/api/runs/1/series");
  read.authorization = header;
  EXPECT_EQ(status(policy, read), 0);
  auto watch = get("/api/runs/1/stream");
  watch.upgrade = true;
  watch.authorization = header;
  EXPECT_EQ(status(policy, watch), 0);
  auto create = post("/api/runs");
  create.authorization = header;
  EXPECT_EQ(status(policy, create), 403);
  auto del = get("/api/runs/1");
  del.method = "DELETE";
  del.authorization = header;
  EXPECT_EQ(status(policy, del), 403);
}

TEST(AccessPolicy, SessionTradesATokenForAStrictHttpOnlyCookie) {
  auto policy = withTokens();
  policy.setPort(8080);
  auto login = post("/api/session");
  login.contentType = "";
  login.hasBody = false;
  const std::string header = "Bearer " + kToken;
  login.authorization = header;
  const auto answer = policy.check(login);
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 204);
  ASSERT_EQ(answer->headers.size(), 1u);
  EXPECT_EQ(answer->headers[0].first, "Set-Cookie");
  EXPECT_EQ(answer->headers[0].second, "grainlab_token_8080=" + kToken + "; Path=/; HttpOnly; SameSite=Strict");
  // The cookie then stands for the token, on that port only.
  auto withCookie = get("/api/runs");
  const std::string cookie = "theme=dark; grainlab_token_8080=" + kToken;
  withCookie.cookie = cookie;
  EXPECT_EQ(status(policy, withCookie), 0);
  const std::string otherPort = "grainlab_token_8081=" + kToken;
  withCookie.cookie = otherPort;
  EXPECT_EQ(status(policy, withCookie), 401);
  login.authorization = "Bearer nottheright-token-at-all";
  EXPECT_EQ(status(policy, login), 401);
}

TEST(AccessPolicy, RepeatedWrongTokensFromOneAddressAreSlowed) {
  AccessPolicy policy({"0.0.0.0", kToken, "", {}, {}}, {.maxFailures = 3, .window = std::chrono::seconds(60)});
  auto guess = get("/api/runs");
  guess.peer = "10.1.1.1";
  guess.authorization = "Bearer wrong-guess-number-one";
  for (int i = 0; i < 3; ++i) EXPECT_EQ(status(policy, guess), 401);
  EXPECT_EQ(status(policy, guess), 429);
  // Even the right token waits out the window: otherwise guessing goes on.
  const std::string right = "Bearer " + kToken;
  guess.authorization = right;
  const auto answer = policy.check(guess);
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 429);
  ASSERT_FALSE(answer->headers.empty());
  EXPECT_EQ(answer->headers[0].first, "Retry-After");
  EXPECT_GT(std::stol(answer->headers[0].second), 55);
  // Another address is not affected, and asking with no token is no guess.
  guess.peer = "10.1.1.2";
  EXPECT_EQ(status(policy, guess), 0);
  auto bare = get("/api/runs");
  bare.peer = "10.1.1.3";
  for (int i = 0; i < 10; ++i) EXPECT_EQ(status(policy, bare), 401);
}

TEST(FailureLimiter, BlocksForTheRestOfTheWindowThenForgets) {
  FailureLimiter limiter({.maxFailures = 2, .window = std::chrono::seconds(60), .maxAddresses = 2});
  const auto t0 = FailureLimiter::Clock::time_point{} + std::chrono::hours(1);
  limiter.recordFailure("a", t0);
  EXPECT_EQ(limiter.blockedFor("a", t0), 0);
  limiter.recordFailure("a", t0 + std::chrono::seconds(10));
  EXPECT_EQ(limiter.blockedFor("a", t0 + std::chrono::seconds(10)), 50);
  EXPECT_EQ(limiter.blockedFor("a", t0 + std::chrono::seconds(60)), 0);
  // Bounded memory: a third address pushes out the oldest window.
  limiter.recordFailure("b", t0);
  limiter.recordFailure("b", t0);
  limiter.recordFailure("c", t0 + std::chrono::seconds(1));
  limiter.recordFailure("d", t0 + std::chrono::seconds(2));
  EXPECT_EQ(limiter.blockedFor("b", t0 + std::chrono::seconds(3)), 0);
}

TEST(AccessPolicy, AddressHelpers) {
  EXPECT_TRUE(isLoopbackAddress("127.0.0.1"));
  EXPECT_TRUE(isLoopbackAddress("127.200.1.1"));
  EXPECT_TRUE(isLoopbackAddress("::1"));
  EXPECT_TRUE(isLoopbackAddress("::ffff:127.0.0.1"));
  EXPECT_FALSE(isLoopbackAddress("0.0.0.0"));
  EXPECT_FALSE(isLoopbackAddress("10.0.0.1"));
  EXPECT_FALSE(isLoopbackAddress("localhost"));  // a name: resolve it first
  EXPECT_TRUE(isUnspecifiedAddress("0.0.0.0"));
  EXPECT_TRUE(isUnspecifiedAddress("::"));
  EXPECT_FALSE(isUnspecifiedAddress("127.0.0.1"));
  EXPECT_EQ(hostName("Example.ORG:8080"), "example.org");
  EXPECT_EQ(hostName("[::1]:8080"), "::1");
  EXPECT_EQ(hostName("::1"), "::1");
  EXPECT_TRUE(sameSecret("abc", "abc"));
  EXPECT_FALSE(sameSecret("abc", "abd"));
  EXPECT_FALSE(sameSecret("abc", "abcd"));
}

TEST(AccessTokens, FromFileOrEnvironmentNeverMadeOnLoopbackAlwaysOnARemoteBind) {
  ServeOptions options;
  options.host = "127.0.0.1";
  const auto none = [](const char*) -> const char* { return nullptr; };
  EXPECT_TRUE(loadAccessTokens(options, none).full.empty());
  const auto env = [](const char* name) -> const char* {
    return std::string(name) == "GRAINLAB_TOKEN" ? "from-the-environment-0001" : nullptr;
  };
  EXPECT_EQ(loadAccessTokens(options, env).full, "from-the-environment-0001");
  options.host = "0.0.0.0";
  const AccessTokens made = loadAccessTokens(options, none);
  EXPECT_TRUE(made.generated);
  EXPECT_EQ(made.full.size(), 64u);
  EXPECT_NE(made.full, loadAccessTokens(options, none).full);
  options.tokenFile = "/nonexistent/token";
  EXPECT_THROW(loadAccessTokens(options, none), std::invalid_argument);
  const auto tooShort = [](const char* name) -> const char* {
    return std::string(name) == "GRAINLAB_TOKEN" ? "short" : nullptr;
  };
  options.tokenFile.clear();
  EXPECT_THROW(loadAccessTokens(options, tooShort), std::invalid_argument);
  const auto cookieBreaker = [](const char* name) -> const char* {
    return std::string(name) == "GRAINLAB_TOKEN" ? "abcdefghijklmnop;Path=/x" : nullptr;
  };
  EXPECT_THROW(loadAccessTokens(options, cookieBreaker), std::invalid_argument);
}

}  // namespace
}  // namespace grainlab::server
