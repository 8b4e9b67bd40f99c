#include "grainlab/server/lammps_import.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "frame_codec.hpp"
#include "grainlab/analysis/histogram.hpp"
#include "grainlab/run.hpp"
#include "grainlab/series_column.hpp"
#include "repository.hpp"
#include "run_service.hpp"
#include "series_format.hpp"

namespace grainlab::server {
namespace {

namespace fs = std::filesystem;

// The frames of the import, stored as the run's rows, histograms and replay frames while the
// import reads them (memory: one encoded frame, the last, kept until the end).
class DatabaseFrames final : public lammps::ImportObserver {
 public:
  DatabaseFrames(Repository& repo, std::int64_t runId, int frameEvery)
      : repo_(repo), runId_(runId), frameEvery_(frameEvery) {}

  void onFrame(const Sample& row, const lammps::FrameContacts& frame) override {
    // The database keeps each row's time; an import without a clock has none to give it.
    if (!std::isfinite(row.time))
      throw std::invalid_argument(
          "--db needs the run's timestep: give --timestep SECONDS, or keep the export.json "
          "`grainlab export lammps` wrote beside the dumps");
    const std::int64_t seq = rows_++;
    repo_.appendSample(runId_, toRecord(row, seq));
    if (row.histograms) {
      const nlohmann::json h = {{"type", "histogram"}, {"seq", seq},         {"step", row.step},
                                {"time", row.time},    {"stage", row.stage}, {"histograms", *row.histograms}};
      repo_.appendHistogram(runId_, seq, row.step,
                            h.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    }
    const double phi = row.values[columnIndex(SeriesColumnId::PhiMobDeg)];
    if (std::isfinite(phi)) peakPhiMobDeg_ = std::max(peakPhiMobDeg_.value_or(phi), phi);
    lastStep_ = row.step;

    // Replay frames index the shapes of the first frame: a frame with other atoms is not drawn.
    if (rows_ == 1) {
      particles_ = frame.particles;
      nlohmann::json shapes = nlohmann::json::array();
      for (int k = 0; k < frame.particles; ++k) shapes.push_back({{"disc", frame.radii[static_cast<std::size_t>(k)]}});
      repo_.setShapes(runId_, frame.particles,
                      shapesMessage(std::move(shapes), nlohmann::json::array(), nlohmann::json::array()).dump());
    }
    if (frame.particles != particles_) {
      ++framesSkipped_;
      return;
    }
    const auto n = static_cast<std::size_t>(frame.particles);
    angles_.resize(n, 0.0);  // discs: the dump has no orientation to draw
    lastFrame_ = encodeFrame(row.step, row.time, std::span<const Vec2>(frame.centroids.data(), n), angles_,
                             frame.contacts);
    lastFrameTime_ = row.time;
    lastFrameStored_ = frameEvery_ > 0 && (seq % frameEvery_) == 0;
    if (lastFrameStored_) repo_.appendFrame(runId_, frames_++, row.step, row.time, lastFrame_);
  }

  // The last frame, if it was not kept already: the replay ends where the run did.
  void keepLastFrame() {
    if (!lastFrameStored_ && !lastFrame_.empty())
      repo_.appendFrame(runId_, frames_++, lastStep_, lastFrameTime_, std::move(lastFrame_));
  }

  std::optional<double> peakPhiMobDeg() const { return peakPhiMobDeg_; }
  int particles() const { return particles_; }
  std::int64_t framesSkipped() const { return framesSkipped_; }

 private:
  Repository& repo_;
  std::int64_t runId_;
  int frameEvery_;
  std::int64_t rows_ = 0, frames_ = 0, framesSkipped_ = 0, lastStep_ = 0;
  int particles_ = 0;
  std::optional<double> peakPhiMobDeg_;
  std::vector<double> angles_;
  std::string lastFrame_;
  double lastFrameTime_ = 0;
  bool lastFrameStored_ = false;
};

// What the run's "scene" says of it: where it came from, and one stage the charts read against
// axial strain (the cell's deformation). export.json, when the dumps came from an export.
nlohmann::json importedScene(const std::string& name, const std::vector<std::string>& dumps) {
  nlohmann::json files = nlohmann::json::array();
  for (const std::string& d : dumps) files.push_back(fs::absolute(d).lexically_normal().string());
  nlohmann::json scene = {{"name", name},
                          {"origin", "lammps"},
                          {"dumps", std::move(files)},
                          {"stages", {{{"name", "lammps"}, {"type", "lammps_deformation"}}}}};
  for (const std::string& d : dumps) {
    const fs::path meta = fs::path(d).parent_path() / "export.json";
    if (!fs::exists(meta)) continue;
    nlohmann::json exported = nlohmann::json::parse(std::ifstream(meta), nullptr, false);
    if (!exported.is_discarded()) scene["export"] = std::move(exported);
    break;
  }
  return scene;
}

}  // namespace

LammpsRunImport importLammpsRun(const std::vector<std::string>& dumps, const std::string& outDir,
                                const std::string& db, lammps::ImportOptions options, std::string name) {
  if (name.empty()) name = "lammps/" + fs::absolute(outDir).lexically_normal().filename().string();
  Repository repo(db, Repository::Opener::Tool);  // a server may be running on the same file
  RunRecord record;
  record.name = name;
  record.scene = importedScene(name, dumps).dump();
  record.status = RunStatus::Queued;  // until finishRun below, in the same queue of writes
  record.producedBy = "lammps";
  record.createdAt = unixNow();
  const std::int64_t id = repo.insertRun(record).get();
  repo.markStarted(id, record.createdAt);

  DatabaseFrames frames(repo, id, options.framesEvery);
  options.observer = &frames;
  LammpsRunImport outcome;
  outcome.runId = id;
  try {
    outcome.report = lammps::importLammps(dumps, outDir, options);
  } catch (...) {
    repo.deleteRun(id).get();  // nothing half-written: the run goes with its rows
    throw;
  }
  frames.keepLastFrame();
  RunEnd end;
  end.status = RunStatus::Completed;
  end.stage = "lammps";
  end.finishedAt = unixNow();
  end.wallSeconds = outcome.report.seconds;  // the import's: LAMMPS's own time is not in the dumps
  end.steps = outcome.report.lastTimestep;
  end.particles = outcome.report.particles;
  end.peakPhiMobDeg = frames.peakPhiMobDeg();
  repo.finishRun(id, end, [] {});
  repo.flush().get();
  if (repo.writeFailures() > 0) {
    repo.deleteRun(id).get();
    throw std::runtime_error("could not store the run in " + db + ": " + repo.lastWriteError());
  }
  return outcome;
}

}  // namespace grainlab::server
