#include "grainlab/output_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "grainlab/periodic_cell.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

namespace fs = std::filesystem;

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

void writeFileAtomically(const std::string& path, std::initializer_list<std::string_view> parts) {
  // Plain write(2): every failure is seen with its errno (an ofstream reports a full disk at
  // best as a failed stream, and not at all for what it writes as it closes).
  const std::string tmp = path + ".tmp";
  auto fail = [&](int fd) {
    const std::string why = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + why);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(-1);
  for (std::string_view part : parts) {
    while (!part.empty()) {
      const ssize_t n = ::write(fd, part.data(), part.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) fail(fd);
      part.remove_prefix(static_cast<std::size_t>(n));
    }
  }
  if (::close(fd) != 0) fail(-1);
  fs::rename(tmp, path);
}

void writeFileAtomically(const std::string& path, const std::string& text) { writeFileAtomically(path, {text}); }

nlohmann::json summaryJson(const RunSummary& summary, const World& world) {
  nlohmann::json s;
  s["status"] = toString(summary.status);
  if (!summary.error.empty()) s["error"] = summary.error;
  s["wall_seconds"] = summary.wallSeconds;
  s["sample_seconds"] = summary.sampleSeconds;
  s["steps"] = summary.steps;
  s["particles"] = summary.particles;
  s["peak_phi_mob_deg"] = summary.peakPhiMobDeg;
  if (!summary.notes.empty()) s["notes"] = summary.notes;
  s["warnings"] = warningsJson(summary.warnings);
  if (summary.voidRatioAfterConsolidation >= 0) s["void_ratio_after_consolidation"] = summary.voidRatioAfterConsolidation;
  s["timestep"] = world.timestep();
  s["critical_timestep"] = world.criticalTimestep();
  s["particle_steps_per_second"] =
      summary.wallSeconds > 0 ? summary.particles * static_cast<double>(summary.steps) / summary.wallSeconds : 0.0;
  // What checkpointing cost (wall time, like the keys above; absent if none was written).
  if (summary.checkpoints > 0 || !summary.checkpointError.empty()) {
    s["checkpoints"] = {{"written", summary.checkpoints}, {"seconds", summary.checkpointSeconds}};
    if (!summary.checkpointError.empty()) s["checkpoints"]["last_error"] = summary.checkpointError;
  }
  if (summary.stageCheckpoints > 0) {
    s["stage_checkpoints"] = {{"written", summary.stageCheckpoints}, {"bytes", summary.stageCheckpointBytes},
                              {"seconds", summary.stageCheckpointSeconds}};
  }
  const Profile& p = world.profile();
  s["profile_seconds"] = {{"neighbors", p.neighbors}, {"forces", p.forces}, {"integrate", p.integrate},
                          {"neighbor_rebuilds", p.rebuilds},
                          {"polygon_feature_searches", p.featureSearches}};
  return s;
}

OutputWriter::OutputWriter(std::string directory, std::ostream* progress)
    : dir_(std::move(directory)), progress_(progress) {}

void OutputWriter::onEstimate(const RunCost& cost) {
  if (progress_) *progress_ << "estimate: " << cost.describe() << "\n";
}

void OutputWriter::onWarnings(const std::vector<ValidityWarning>& warnings) {
  if (!progress_) return;
  for (const ValidityWarning& w : warnings) *progress_ << describe(w) << "\n";
}

void OutputWriter::onStart(const Scene&, const World&) {
  started_ = std::chrono::steady_clock::now();
  fs::create_directories(dir_);
  series_.open(fs::path(dir_) / "series.csv", std::ios::binary | std::ios::trunc);
  if (!series_) throw std::runtime_error("cannot write " + dir_ + "/series.csv: " + std::strerror(errno));
  seriesGood_ = 0;
  appendSeries(seriesHeader() + '\n');
}

void OutputWriter::appendSeries(const std::string& text) {
  series_ << text;
  series_.flush();  // a sample is rare; a reader (or a crash) sees every row so far
  if (series_) {
    seriesGood_ = static_cast<std::uint64_t>(series_.tellp());
    return;
  }
  // A full disk: the run stops here, and series.csv keeps its whole rows only.
  const std::string why = std::strerror(errno);
  const fs::path path = fs::path(dir_) / "series.csv";
  series_.close();
  std::error_code ignored;
  fs::resize_file(path, seriesGood_, ignored);
  throw std::runtime_error("cannot write " + path.string() + ": " + why);
}

void OutputWriter::persistOutput(StateArchive& a) {
  a.section("series.csv");
  const fs::path path = fs::path(dir_) / "series.csv";
  if (!a.loading()) {
    series_.flush();
    if (!series_) throw std::runtime_error("cannot write " + path.string());
    seriesBytes_ = static_cast<std::uint64_t>(series_.tellp());
    // The rows up to here must outlive a crash as surely as the checkpoint that counts them.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || ::fsync(fd) != 0) {
      const std::string why = std::strerror(errno);
      if (fd >= 0) ::close(fd);
      throw std::runtime_error("cannot flush " + path.string() + " to disk: " + why);
    }
    ::close(fd);
  }
  a(seriesBytes_);
}

void OutputWriter::onResume(const Scene&, const World&) {
  started_ = std::chrono::steady_clock::now();
  const fs::path path = fs::path(dir_) / "series.csv";
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec || size < seriesBytes_) {
    throw std::runtime_error(path.string() + " is shorter than when the checkpoint was written (" +
                             std::to_string(ec ? 0 : size) + " of " + std::to_string(seriesBytes_) +
                             " bytes): it cannot be continued");
  }
  fs::resize_file(path, seriesBytes_);  // rows written after the checkpoint are written again
  series_.open(path, std::ios::binary | std::ios::app);
  if (!series_) throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
  seriesGood_ = seriesBytes_;
}

void OutputWriter::onSample(const Sample& sample, const World&) { appendSeries(formatSeriesRow(sample) + '\n'); }

void OutputWriter::onProgress(double fraction, std::string_view stage, const World& world) {
  if (!progress_) return;
  const int percent = static_cast<int>(std::floor(fraction * 100));
  if (percent == lastPercent_) return;
  lastPercent_ = percent;
  *progress_ << "[" << percent << "%] " << stage << "  step " << world.stepCount() << "  t = " << world.time() << " s";
  // Time left, from the pace so far (progress is by stage criteria, so it is an estimate).
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  if (fraction > 0.02 && fraction < 1 && elapsed > 2) *progress_ << "  about " << humanDuration(elapsed * (1 - fraction) / fraction) << " left";
  *progress_ << "\n";
  progress_->flush();
}

void OutputWriter::onFinish(const RunSummary& summary, const World& world) {
  series_.close();
  const fs::path dir(dir_);
  const auto x = world.positions();
  const auto v = world.velocities();
  std::string particles = "id,shape,x,y,angle,vx,vy,spin,radius,boundary\n";
  for (int k = 0; k < world.size(); ++k) {
    const ShapeKind shape = world.shapes()[k];
    particles += std::to_string(k) + (shape == ShapeKind::Disc ? ",disc," : shape == ShapeKind::Clump ? ",clump," : ",polygon,") +
                 num(x[k].x()) + "," + num(x[k].y()) + "," + num(world.angles()[k]) + "," + num(v[k].x()) + "," +
                 num(v[k].y()) + "," + num(world.spins()[k]) + "," + num(world.boundingRadii()[k]) + "," +
                 (world.boundaryFlags()[k] ? "1" : "0") + "\n";
  }
  // A final file that cannot be written (a full disk) fails the run: summary.json, small and
  // written last, then says so if it can be written itself.
  // A clump's row is its body (centroid, angle, bounding radius); its discs are listed here.
  std::string members = "id,member,x,y,radius\n";
  std::vector<ClumpMember> world_members;
  for (int k = 0; k < world.size() && world.hasClumps(); ++k) {
    if (world.shapes()[k] != ShapeKind::Clump) continue;
    world.worldMembers(k, world_members);
    for (size_t m = 0; m < world_members.size(); ++m) {
      members += std::to_string(k) + "," + std::to_string(m) + "," + num(world_members[m].centre.x()) + "," +
                 num(world_members[m].centre.y()) + "," + num(world_members[m].radius) + "\n";
    }
  }
  std::string failure;
  try {
    writeFileAtomically((dir / "particles_final.csv").string(), particles);
    if (world.hasClumps()) writeFileAtomically((dir / "clump_members_final.csv").string(), members);
  } catch (const std::exception& e) {
    failure = e.what();
  }

  std::vector<ContactRecord> contacts;
  world.contacts(contacts);
  std::string text = "i,j,px,py,nx,ny,fn,ft,lix,liy,ljx,ljy\n";
  for (const ContactRecord& c : contacts) {
    const Vec2 li = c.point - x[c.i];
    text += std::to_string(c.i) + "," + std::to_string(c.j) + "," + num(c.point.x()) + "," + num(c.point.y()) + "," +
            num(c.normal.x()) + "," + num(c.normal.y()) + "," + num(c.fn) + "," + num(c.ft) + "," + num(li.x()) + "," +
            num(li.y()) + ",";
    if (!c.isWall()) {
      // In a periodic cell, from the image of j that i touches: the branch vector the contact
      // acts through (docs/periodic-cell.md, "Stress").
      const PeriodicCell* cell = world.periodicCell();
      const Vec2 lj = c.point - (cell ? Vec2(x[c.i] + cell->minimumImage(x[c.j] - x[c.i])) : x[c.j]);
      text += num(lj.x()) + "," + num(lj.y());
    } else {
      text += ",";  // a wall has no centroid
    }
    text += "\n";
  }
  if (failure.empty()) {
    try {
      writeFileAtomically((dir / "contacts_final.csv").string(), text);
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }

  RunSummary written = summary;
  if (!failure.empty()) {
    written.status = RunStatus::Failed;
    written.error = !summary.error.empty() ? summary.error + "; then " + failure
                    : summary.status != RunStatus::Completed
                        ? "the run was " + std::string(toString(summary.status)) + "; then " + failure
                        : failure;
    if (!summary.checkpointError.empty()) written.error += "; and its last checkpoint failed: " + summary.checkpointError;
  }
  writeFileAtomically((dir / "summary.json").string(), summaryJson(written, world).dump(2) + "\n");
  if (progress_) {
    *progress_ << written.status << " in " << written.wallSeconds << " s, " << written.steps << " steps"
               << (written.error.empty() ? "" : ": " + written.error) << "\n";
  }
  if (!failure.empty()) throw std::runtime_error(written.error);
}

}  // namespace grainlab
