#include "grainlab/studies/batch_progress.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace grainlab::studies {
namespace {
// A run's own progress is shown at most this often: a batch is long, a terminal is not.
constexpr double kAdvanceLineSeconds = 10;
}  // namespace

std::string formatDuration(double seconds) {
  std::ostringstream os;
  if (seconds < 90) os << static_cast<long>(std::lround(seconds)) << " s";
  else if (seconds < 90 * 60) os << static_cast<long>(std::lround(seconds / 60)) << " min";
  else os << std::round(seconds / 360) / 10 << " h";
  return os.str();
}

BatchProgress::BatchProgress(std::ostream* out, std::string label, size_t toRun, size_t reused)
    : out_(out), label_(std::move(label)), toRun_(toRun), reused_(reused),
      start_(std::chrono::steady_clock::now()), lastLine_(start_) {
  if (!out_) return;
  *out_ << "[" << label_ << "] " << toRun_ + reused_ << " runs";
  if (reused_) *out_ << ", " << reused_ << " already completed (kept)";
  *out_ << ", " << toRun_ << " to run\n";
  out_->flush();
}

void BatchProgress::started(const std::string& id) {
  std::lock_guard lock(mutex_);
  running_.emplace_back(id, 0.0);
  print("started " + id);
}

void BatchProgress::advanced(const std::string& id, double fraction) {
  std::lock_guard lock(mutex_);
  for (auto& [name, f] : running_) {
    if (name == id) f = std::clamp(fraction, 0.0, 1.0);
  }
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - lastLine_).count() >= kAdvanceLineSeconds) print("");
}

void BatchProgress::finished(const std::string& id, RunStatus status, double wallSeconds, int threadsLent) {
  std::lock_guard lock(mutex_);
  std::erase_if(running_, [&](const auto& r) { return r.first == id; });
  ++done_;
  if (status != RunStatus::Completed) ++failed_;
  std::string event = id + " " + std::string(toString(status)) + " in " + formatDuration(wallSeconds);
  if (threadsLent > 0) event += ", with " + std::to_string(threadsLent) + (threadsLent == 1 ? " idle core" : " idle cores") + " lent";
  print(event);
}

void BatchProgress::print(const std::string& event) {
  lastLine_ = std::chrono::steady_clock::now();
  if (!out_) return;
  const double elapsed = std::chrono::duration<double>(lastLine_ - start_).count();
  double work = static_cast<double>(done_);
  for (const auto& r : running_) work += r.second;
  std::ostringstream line;
  line << "[" << label_ << "] " << reused_ + done_ << "/" << reused_ + toRun_ << " done, " << running_.size()
       << " running, " << failed_ << " failed";
  if (done_ < toRun_) {
    if (work > 0.02 && elapsed > 1) line << ", about " << formatDuration(elapsed * (toRun_ - work) / work) << " left";
    else line << ", time left not known yet";
  }
  if (!event.empty()) line << "  (" << event << ")";
  *out_ << line.str() << "\n";
  out_->flush();
}

}  // namespace grainlab::studies
