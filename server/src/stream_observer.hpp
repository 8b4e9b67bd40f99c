#pragma once
// Watches one run on its worker thread: turns samples, histograms and particle states into
// stream messages (published to the hub) and database rows (queued to the writer). Every call
// returns without waiting for a client or the disk; live frames are grabbed in onProgress at
// most `framesPerSecond` times a second by the steady clock.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "grainlab/contact.hpp"
#include "grainlab/run.hpp"

namespace grainlab::server {

class LiveRun;
class Repository;
class SeriesFormat;
class StreamHub;

/// {"type":"status","id","status","progress","stage","steps","error"} as text.
std::string statusMessage(std::int64_t id, RunStatus status, double progress,
                          const std::string& stage, std::int64_t steps, const std::string& error);

class StreamObserver : public RunObserver {
 public:
  struct Settings {
    double framesPerSecond = 20;   ///< live frames, at most
    int replayFrameEvery = 4;      ///< a stored frame every N samples
    double progressPerSecond = 4;  ///< progress status messages, at most
    double storeProgressSeconds = 1;  ///< progress written to the database this often
  };

  StreamObserver(LiveRun& run, Repository& repo, StreamHub& hub, const SeriesFormat& format,
                 Settings settings);

  void onStart(const Scene& scene, const World& world) override;
  void onSample(const Sample& sample, const World& world) override;
  void onProgress(double fraction, std::string_view stage, const World& world) override;
  /// DELETE or POST /cancel: the run ends cancelled.
  bool cancelRequested() override;
  /// The server is stopping: the run ends interrupted, after a checkpoint.
  bool stopRequested() override;
  /// Saving: waits until every row queued so far is committed, then records how many
  /// samples and frames there are; loading reads that back.
  void persistOutput(StateArchive& a) override;
  /// Deletes what was stored past the checkpoint (the server may have been killed after
  /// it) and sends the shapes and the current frame to the watchers, as onStart does.
  void onResume(const Scene& scene, const World& world) override;
  void onFinish(const RunSummary& summary, const World& world) override;

  std::int64_t samples() const { return samples_; }
  std::int64_t framesSent() const { return framesSent_; }

 private:
  using Clock = std::chrono::steady_clock;
  void storeFrame(const World& world, std::string bytes);
  void publishShapesAndFrame(const World& world);

  LiveRun& run_;
  Repository& repo_;
  StreamHub& hub_;
  const SeriesFormat& format_;
  Settings settings_;
  Clock::duration frameInterval_, progressInterval_, storeInterval_;
  Clock::time_point lastFrame_{}, lastProgress_{}, lastStore_{};
  std::int64_t samples_ = 0;
  std::int64_t storedFrames_ = 0;
  std::int64_t lastStoredStep_ = -1;
  std::int64_t framesSent_ = 0;
  std::vector<ContactRecord> scratch_;
  std::uint64_t writeFailuresAtStart_;  // the repository's count when this run began
};

}  // namespace grainlab::server
