// The routes as a plain request -> response function over a real database and run queue, with
// a fake run function: every status code the API promises, without a socket.
#include "router.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "application.hpp"
#include "fake_run.hpp"
#include "frame_codec.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "repository.hpp"

namespace grainlab::server {
namespace {

using nlohmann::json;
using namespace std::chrono_literals;

const char* kTinyScene =
    R"({"name":"tiny","particles":[{"shape":"disc","radius":0.002,"position":[0,0]}],)"
    R"("stages":[{"type":"free","duration":0.001}]})";

class RouterTest : public ::testing::Test {
 protected:
  void start(testing::FakeRun fake, int maxConcurrent = 1, int maxQueued = 8) {
    dir_ = std::filesystem::temp_directory_path() /
           ("grainlab-router-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "web" / "js");
    std::ofstream(dir_ / "web" / "index.html") << "<!doctype html><title>grainlab</title>";
    std::ofstream(dir_ / "web" / "js" / "app.js") << "export {};";
    std::ofstream(dir_ / "secret.txt") << "outside the web root";
    ServeOptions o;
    o.db = (dir_ / "db" / "test.db").string();
    o.webRoot = (dir_ / "web").string();
    o.maxConcurrentRuns = maxConcurrent;
    o.maxQueuedRuns = maxQueued;
    o.maxParticles = 100;
    o.runFunction = testing::fakeRun(fake);
    app_ = std::make_unique<Application>(o);
  }
  void TearDown() override {
    app_.reset();
    std::filesystem::remove_all(dir_);
  }
  ApiResponse call(const std::string& method, const std::string& target, const std::string& body = {}) {
    return app_->router().handle({method, target, body});
  }
  json callJson(const std::string& method, const std::string& target, int expect, const std::string& body = {}) {
    auto r = call(method, target, body);
    EXPECT_EQ(r.status, expect) << method << " " << target << " -> " << r.body;
    return r.body.empty() ? json() : json::parse(r.body);
  }
  std::int64_t create(const std::string& body = kTinyScene) {
    return callJson("POST", "/api/runs", 201, body)["id"].get<std::int64_t>();
  }
  json waitFor(std::int64_t id, const std::string& status) {
    json run;
    for (int i = 0; i < 1000; ++i) {
      run = callJson("GET", "/api/runs/" + std::to_string(id), 200);
      if (run["status"] == status) return run;
      std::this_thread::sleep_for(5ms);
    }
    ADD_FAILURE() << "run " << id << " never became " << status << ": " << run.dump();
    return run;
  }
  static std::string header(const ApiResponse& r, const std::string& name) {
    for (const auto& [k, v] : r.headers)
      if (k == name) return v;
    return {};
  }

  std::filesystem::path dir_;
  std::unique_ptr<Application> app_;
};

TEST_F(RouterTest, HealthAndPresets) {
  start({});
  EXPECT_EQ(callJson("GET", "/api/health", 200)["status"], "ok");
  auto presets = callJson("GET", "/api/presets", 200)["presets"];
  EXPECT_NE(std::find(presets.begin(), presets.end(), "circular-quick"), presets.end());
  EXPECT_TRUE(callJson("GET", "/api/presets/circular-quick", 200).contains("assembly"));
  EXPECT_EQ(callJson("GET", "/api/presets/nope", 404)["field"], "preset");
}

TEST_F(RouterTest, ARunGoesFromCreateToCompletedWithItsSeries) {
  start({.samples = 4});
  const auto id = create();
  auto run = waitFor(id, "completed");
  EXPECT_EQ(run["name"], "tiny");
  EXPECT_EQ(run["progress"], 1.0);
  EXPECT_TRUE(run["wall_seconds"].is_number());
  // One thread's CPU time cannot exceed the wall time around it (clock ticks aside).
  ASSERT_TRUE(run["cpu_seconds"].is_number());
  EXPECT_GE(run["cpu_seconds"].get<double>(), 0.0);
  EXPECT_LE(run["cpu_seconds"].get<double>(), run["wall_seconds"].get<double>() + 0.01);
  EXPECT_TRUE(run["created_at"].get<std::string>().ends_with("Z"));
  EXPECT_EQ(run["scene"]["name"], "tiny");

  auto listed = callJson("GET", "/api/runs", 200)["runs"];
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_EQ(listed[0]["id"], id);

  auto series = callJson("GET", "/api/runs/" + std::to_string(id) + "/series", 200);
  EXPECT_EQ(series["columns"], json(seriesColumns()));
  ASSERT_EQ(series["rows"].size(), 4u);
  EXPECT_EQ(series["rows"][3][2], "free");

  auto csv = call("GET", "/api/runs/" + std::to_string(id) + "/series?format=csv");
  EXPECT_EQ(csv.status, 200);
  EXPECT_EQ(csv.contentType, "text/csv; charset=utf-8");
  EXPECT_EQ(csv.body.substr(0, csv.body.find('\n')), seriesHeader());
  EXPECT_EQ(std::count(csv.body.begin(), csv.body.end(), '\n'), 5);

  auto frames = callJson("GET", "/api/runs/" + std::to_string(id) + "/frames", 200)["frames"];
  ASSERT_GE(frames.size(), 2u);  // the first state and the last
  auto frame = call("GET", "/api/runs/" + std::to_string(id) + "/frames?index=0");
  EXPECT_EQ(frame.contentType, "application/octet-stream");
  EXPECT_EQ(decodeFrame(frame.body).particles.size(), 12u);
  EXPECT_EQ(callJson("GET", "/api/runs/" + std::to_string(id) + "/shapes", 200)["count"], 3);
}

TEST_F(RouterTest, AFailingRunEndsFailedWithItsReason) {
  start({.fail = true});
  const auto id = create();
  auto run = waitFor(id, "failed");
  EXPECT_NE(run["error"].get<std::string>().find("non-finite"), std::string::npos);
  EXPECT_EQ(callJson("GET", "/api/health", 200)["status"], "ok");
}

TEST_F(RouterTest, CancelAndDelete) {
  start({.samples = 1000, .delayPerSample = 2ms}, 1);
  const auto running = create();
  const auto queued = create();
  waitFor(running, "running");
  EXPECT_EQ(callJson("POST", "/api/runs/" + std::to_string(queued) + "/cancel", 200)["status"], "cancelled");
  EXPECT_EQ(callJson("POST", "/api/runs/" + std::to_string(running) + "/cancel", 202)["cancel_requested"], true);
  waitFor(running, "cancelled");
  EXPECT_EQ(callJson("POST", "/api/runs/" + std::to_string(running) + "/cancel", 409)["error"],
            "run " + std::to_string(running) + " has already ended (cancelled)");
  EXPECT_EQ(call("DELETE", "/api/runs/" + std::to_string(running)).status, 204);
  callJson("GET", "/api/runs/" + std::to_string(running), 404);
  callJson("DELETE", "/api/runs/" + std::to_string(running), 404);

  // Deleting a running run stops it and leaves nothing behind.
  const auto third = create();
  waitFor(third, "running");
  EXPECT_EQ(call("DELETE", "/api/runs/" + std::to_string(third)).status, 204);
  callJson("GET", "/api/runs/" + std::to_string(third), 404);
  for (int i = 0; i < 400 && app_->repository().findRun(third); ++i) std::this_thread::sleep_for(5ms);
  EXPECT_FALSE(app_->repository().findRun(third));
}

TEST_F(RouterTest, BadScenesNameTheFieldAndStoreNothing) {
  start({});
  auto e = callJson("POST", "/api/runs", 400, "{not json");
  EXPECT_EQ(e["field"], "(json)");
  e = callJson("POST", "/api/runs", 400, "[1,2]");
  EXPECT_EQ(e["field"], "(json)");
  e = callJson("POST", "/api/runs", 400, R"({"name":"x","particles":[{"shape":"disc","position":[0,0]}]})");
  EXPECT_EQ(e["field"], "particles[0].radius");
  EXPECT_FALSE(e["error"].get<std::string>().empty());
  e = callJson("POST", "/api/runs", 400, R"({"name":"x","bogus":1,"particles":[]})");
  EXPECT_FALSE(e["field"].get<std::string>().empty());
  e = callJson("POST", "/api/runs", 400, R"({"preset":"no-such-preset"})");
  EXPECT_EQ(e["field"], "preset");
  e = callJson("POST", "/api/runs", 400, R"({"preset":7})");
  EXPECT_EQ(e["field"], "preset");
  e = callJson("POST", "/api/runs", 400, R"({"preset":"circular-quick","seed":2})");
  EXPECT_EQ(e["field"], "preset");
  EXPECT_TRUE(callJson("GET", "/api/runs", 200)["runs"].empty());
}

TEST_F(RouterTest, LimitsAnswer503And429) {
  start({.samples = 1000, .delayPerSample = 2ms}, 1, 1);
  // 101 explicit particles against a limit of 100.
  json scene = json::parse(kTinyScene);
  for (int i = 1; i <= 100; ++i)
    scene["particles"].push_back({{"shape", "disc"}, {"radius", 0.001}, {"position", {0.01 * i, 0}}});
  auto e = callJson("POST", "/api/runs", 503, scene.dump());
  EXPECT_EQ(e["field"], "particles");
  const auto a = create();
  waitFor(a, "running");
  create();  // queued
  auto full = call("POST", "/api/runs", kTinyScene);
  EXPECT_EQ(full.status, 429);
  EXPECT_EQ(header(full, "Retry-After"), "5");
  EXPECT_NE(json::parse(full.body)["error"].get<std::string>().find("queue is full"), std::string::npos);
}

TEST_F(RouterTest, UnknownRoutesIdsAndMethods) {
  start({});
  callJson("GET", "/api/nothing", 404);
  callJson("GET", "/api/runs/999", 404);
  callJson("GET", "/api/runs/abc", 404);
  callJson("GET", "/api/runs/999/series", 404);
  callJson("GET", "/api/runs/1/bogus", 404);
  auto r = call("PUT", "/api/runs");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(header(r, "Allow"), "GET, HEAD, POST");
  r = call("POST", "/api/health");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(header(r, "Allow"), "GET, HEAD");
  r = call("GET", "/api/runs/1/cancel");
  EXPECT_EQ(r.status, 405);
  EXPECT_EQ(header(r, "Allow"), "POST");
  r = call("DELETE", "/index.html");
  EXPECT_EQ(r.status, 405);
  const auto id = create();
  EXPECT_EQ(call("GET", "/api/runs/" + std::to_string(id) + "/stream").status, 426);
  EXPECT_EQ(callJson("GET", "/api/runs/" + std::to_string(id) + "/series?format=xml", 400)["field"], "format");
  EXPECT_EQ(callJson("GET", "/api/runs/" + std::to_string(id) + "/frames?index=-1", 400)["field"], "index");
  EXPECT_EQ(callJson("GET", "/api/runs/" + std::to_string(id) + "/frames?index=%zz", 400)["field"], "query");
}

TEST_F(RouterTest, StaticFilesWithTypesAndNoWayOut) {
  start({});
  auto r = call("GET", "/");
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.contentType, "text/html; charset=utf-8");
  r = call("GET", "/js/app.js");
  EXPECT_EQ(r.contentType, "text/javascript; charset=utf-8");
  r = call("HEAD", "/js/app.js");
  EXPECT_TRUE(r.headOnly);
  EXPECT_EQ(call("GET", "/missing.css").status, 404);
  for (const char* evil : {"/../secret.txt", "/js/../../secret.txt", "/%2e%2e/secret.txt", "/%2E%2E%2Fsecret.txt",
                           "/js/%2e%2e/%2e%2e/secret.txt", "/..%5csecret.txt", "/%00", "/%", "relative"}) {
    r = call("GET", evil);
    EXPECT_EQ(r.status, 400) << evil;
    EXPECT_EQ(r.body.find("outside the web root"), std::string::npos) << evil;
  }
}

}  // namespace
}  // namespace grainlab::server
