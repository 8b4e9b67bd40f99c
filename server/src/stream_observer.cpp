#include "stream_observer.hpp"

#include <iostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "frame_codec.hpp"
#include "grainlab/analysis/histogram.hpp"
#include "grainlab/world.hpp"
#include "live_run.hpp"
#include "outgoing.hpp"
#include "repository.hpp"
#include "series_format.hpp"
#include "stream_hub.hpp"

namespace grainlab::server {
namespace {

std::chrono::steady_clock::duration every(double perSecond) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(perSecond > 0 ? 1.0 / perSecond : 0.0));
}

}  // namespace

std::string statusMessage(std::int64_t id, RunStatus status, double progress,
                          const std::string& stage, std::int64_t steps, const std::string& error) {
  nlohmann::json m = {{"type", "status"}, {"id", id},       {"status", toString(status)},
                      {"progress", progress}, {"stage", stage}, {"steps", steps}};
  m["error"] = error.empty() ? nlohmann::json(nullptr) : nlohmann::json(error);
  return m.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

StreamObserver::StreamObserver(LiveRun& run, Repository& repo, StreamHub& hub,
                               const SeriesFormat& format, Settings settings)
    : run_(run),
      repo_(repo),
      hub_(hub),
      format_(format),
      settings_(settings),
      frameInterval_(every(settings.framesPerSecond)),
      progressInterval_(every(settings.progressPerSecond)),
      storeInterval_(every(1.0 / settings.storeProgressSeconds)),
      writeFailuresAtStart_(repo.writeFailures()) {}

void StreamObserver::onStart(const Scene&, const World& world) {
  publishShapesAndFrame(world);
  storeFrame(world, encodeFrame(world, scratch_));
}

void StreamObserver::onResume(const Scene&, const World& world) {
  std::cerr << "grainlab serve: run " << run_.id() << " resumes at step " << world.stepCount() << " (sample "
            << samples_ << ")" << std::endl;
  repo_.truncateRun(run_.id(), samples_, storedFrames_);
  // No frame is stored here: the uninterrupted run stored none at this step either.
  publishShapesAndFrame(world);
}

void StreamObserver::persistOutput(StateArchive& a) {
  a.section("server run");
  if (!a.loading()) {
    repo_.flush().get();  // the rows before the checkpoint are durable...
    // ...unless a write failed (a full disk): a checkpoint counting rows that are not stored
    // would resume with a gap, so this one is not written and the previous one stands.
    if (repo_.writeFailures() != writeFailuresAtStart_)
      throw std::runtime_error("the database could not be written (" + repo_.lastWriteError() + ")");
  }
  a(samples_);
  a(storedFrames_);
  a(lastStoredStep_);
}

void StreamObserver::publishShapesAndFrame(const World& world) {
  // Shapes never change during a run: sent once per client, stored once for replay.
  auto shapes = shapesMessage(world).dump();
  run_.update([&](LiveRun::State& s) { s.particles = world.size(); });
  repo_.setShapes(run_.id(), world.size(), shapes);
  hub_.publish(run_.id(), makeOutgoing(std::move(shapes), MessageKind::Shapes));
  hub_.publish(run_.id(), makeOutgoing(encodeFrame(world, scratch_), MessageKind::Frame));
  ++framesSent_;
  lastFrame_ = Clock::now();
}

void StreamObserver::onSample(const Sample& sample, const World& world) {
  const auto seq = samples_++;
  auto record = toRecord(sample, seq);
  nlohmann::json message = {{"type", "sample"}, {"seq", seq}, {"row", format_.rowObject(record)}};
  hub_.publish(run_.id(), makeOutgoing(message.dump(), MessageKind::Sample));
  repo_.appendSample(run_.id(), std::move(record));

  if (sample.histograms) {
    nlohmann::json h = {{"type", "histogram"},
                        {"seq", seq},
                        {"step", sample.step},
                        {"time", sample.time},
                        {"stage", sample.stage},
                        {"histograms", *sample.histograms}};
    auto text = h.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    repo_.appendHistogram(run_.id(), seq, sample.step, text);
    hub_.publish(run_.id(), makeOutgoing(std::move(text), MessageKind::Histogram));
  }
  if (settings_.replayFrameEvery > 0 && seq % settings_.replayFrameEvery == 0)
    storeFrame(world, encodeFrame(world, scratch_));
}

void StreamObserver::onProgress(double fraction, std::string_view stage, const World& world) {
  const auto now = Clock::now();
  run_.update([&](LiveRun::State& s) {
    s.progress = fraction;
    s.stage = stage;
    s.steps = world.stepCount();
  });
  if (now - lastFrame_ >= frameInterval_) {
    lastFrame_ = now;
    hub_.publish(run_.id(), makeOutgoing(encodeFrame(world, scratch_), MessageKind::Frame));
    ++framesSent_;
  }
  if (now - lastProgress_ >= progressInterval_) {
    lastProgress_ = now;
    hub_.publish(run_.id(),
                 makeOutgoing(statusMessage(run_.id(), RunStatus::Running, fraction,
                                            std::string(stage), world.stepCount(), {}),
                              MessageKind::Progress));
  }
  if (now - lastStore_ >= storeInterval_) {
    lastStore_ = now;
    repo_.updateProgress(run_.id(), fraction, std::string(stage), world.stepCount());
  }
}

bool StreamObserver::cancelRequested() {
  return run_.stopRequested() && run_.stopReason() != StopReason::Shutdown;
}

bool StreamObserver::stopRequested() { return run_.stopReason() == StopReason::Shutdown; }

void StreamObserver::onFinish(const RunSummary&, const World& world) {
  // The final state, live and for replay: a viewer ends on what the run ended on.
  auto bytes = encodeFrame(world, scratch_);
  hub_.publish(run_.id(), makeOutgoing(bytes, MessageKind::Frame));
  ++framesSent_;
  storeFrame(world, std::move(bytes));
}

void StreamObserver::storeFrame(const World& world, std::string bytes) {
  if (world.stepCount() == lastStoredStep_) return;
  lastStoredStep_ = world.stepCount();
  repo_.appendFrame(run_.id(), storedFrames_++, world.stepCount(), world.time(), std::move(bytes));
}

}  // namespace grainlab::server
