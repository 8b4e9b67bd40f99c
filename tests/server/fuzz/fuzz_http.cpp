// libFuzzer: raw bytes as an HTTP request, parsed by Beast's parser with the server's limits
// and answered by the server's own request -> response handler (a real database and run
// queue, a fake run function). Every answer must be a known status with a well-formed body;
// a 500 is a bug.
#include <unistd.h>

#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

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
  grainlab::server::ApiRequest api{std::string(request.method_string()), std::string(request.target()),
                                   std::move(request.body())};
  const auto response = app().router().handle(api);
  static const int known[] = {200, 201, 202, 204, 400, 404, 405, 409, 426, 429, 503};
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
