// libFuzzer: raw bytes as an HTTP request, parsed by Beast's parser with the server's limits,
// passed through the access checks (Host, Origin, token, cookie, content type: a policy with
// a full and a read-only token, as on a server reachable from other machines) and answered by
// the server's own request -> response handler (a real database and run queue, a fake run
// function). Every answer must be a known status with a well-formed body; a 500 is a bug, and
// so is a token in any answer but the login cookie.
#include <unistd.h>

#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "access_policy.hpp"
#include "application.hpp"
#include "fake_run.hpp"
#include "router.hpp"

namespace {

namespace http = boost::beast::http;
using grainlab::server::Application;

Application& app() {
  static auto dir = std::filesystem::temp_directory_path() / ("grainlab-fuzz-http-" + std::to_string(::getpid()));
  static Application* instance = [] {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "web");
    grainlab::server::ServeOptions o;
    o.db = (dir / "fuzz.db").string();
    o.webRoot = (dir / "web").string();
    o.maxConcurrentRuns = 1;
    o.maxQueuedRuns = 4;
    o.maxParticles = 2000;
    o.runFunction = grainlab::server::testing::fakeRun({.samples = 2});
    std::atexit([] { std::filesystem::remove_all(dir); });
    // Deliberately not destroyed: libFuzzer may exit from any thread.
    return new Application(o);
  }();
  return *instance;
}

// The seeds in corpus/http carry these, so the fuzzer reaches the routes behind the checks.
const std::string kToken = "fuzz-full-token-0123456789";
const std::string kReadOnly = "fuzz-read-only-token-0123";

grainlab::server::AccessPolicy& policy() {
  static auto* instance = [] {
    auto* p = new grainlab::server::AccessPolicy({"0.0.0.0", kToken, kReadOnly, {"lab.example"}, {"https://lab.example"}},
                                                 {.maxFailures = 1000000});
    p->setPort(8080);
    return p;
  }();
  return *instance;
}

bool mentionsToken(const grainlab::server::ApiResponse& r) {
  return r.body.find(kToken) != std::string::npos || r.body.find(kReadOnly) != std::string::npos;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  http::request_parser<http::string_body> parser;
  parser.body_limit(1 << 20);
  parser.header_limit(16 * 1024);
  parser.eager(true);
  boost::beast::error_code ec;
  parser.put(boost::asio::buffer(data, size), ec);
  if (ec && ec != http::error::need_more) return 0;
  if (!parser.is_header_done()) return 0;
  if (!parser.is_done()) {
    parser.put_eof(ec);
    if (ec) return 0;
  }
  auto request = parser.release();
  const grainlab::server::AccessRequest access{
      request.method_string(), request.target(), request[http::field::host], request[http::field::origin],
      request[http::field::content_type], request[http::field::authorization], request[http::field::cookie],
      "192.0.2.1", boost::beast::websocket::is_upgrade(request), !request.body().empty()};
  if (const auto refused = policy().check(access)) {
    static const int refusals[] = {204, 401, 403, 405, 415, 421, 429};
    if (std::find(std::begin(refusals), std::end(refusals), refused->status) == std::end(refusals) ||
        (refused->status != 204 && (mentionsToken(*refused) || (!refused->headers.empty() &&
                                     refused->headers[0].first == "Set-Cookie"))) ||
        nlohmann::json::parse(refused->status == 204 ? "{}" : refused->body, nullptr, false).is_discarded()) {
      std::cerr << request.method_string() << " " << request.target() << " -> " << refused->status << " "
                << refused->body << "\n";
      std::abort();
    }
    return 0;
  }
  grainlab::server::ApiRequest api{std::string(request.method_string()), std::string(request.target()),
                                   std::move(request.body())};
  const auto response = app().router().handle(api);
  static const int known[] = {200, 201, 202, 204, 400, 403, 404, 405, 409, 426, 429, 503};
  if (std::find(std::begin(known), std::end(known), response.status) == std::end(known)) {
    std::cerr << api.method << " " << api.target << " -> " << response.status << " " << response.body << "\n";
    std::abort();
  }
  if (response.contentType == "application/json" && !response.body.empty() &&
      nlohmann::json::parse(response.body, nullptr, false).is_discarded()) {
    std::cerr << "malformed JSON from " << api.target << ": " << response.body << "\n";
    std::abort();
  }
  return 0;
}
