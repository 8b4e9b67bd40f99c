#include "grainlab/report/progress_board.hpp"

#include <cmath>

#include "grainlab/report/markup.hpp"

namespace grainlab::report {

ProgressBoard::ProgressBoard(std::ostream* out, std::vector<std::string> names)
    : out_(out), names_(std::move(names)), lastDecile_(names_.size(), -1) {}

double ProgressBoard::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBoard::update(size_t index, double fraction, std::string_view stage) {
  if (!out_ || index >= names_.size()) return;
  const int decile = static_cast<int>(std::floor(fraction * 10));
  std::lock_guard lock(mutex_);
  if (decile <= lastDecile_[index]) return;
  lastDecile_[index] = decile;
  *out_ << "[paper " << fixed(elapsed(), 0) << " s] " << names_[index] << ": " << decile * 10 << "% " << stage << "\n";
  out_->flush();
}

void ProgressBoard::finished(size_t index, std::string_view status, double wallSeconds) {
  if (!out_ || index >= names_.size()) return;
  std::lock_guard lock(mutex_);
  ++done_;
  *out_ << "[paper " << fixed(elapsed(), 0) << " s] " << names_[index] << ": " << status << " in "
        << fixed(wallSeconds, 1) << " s (" << done_ << " of " << names_.size() << " runs done)\n";
  out_->flush();
}

void ProgressBoard::note(std::string_view text) {
  if (!out_) return;
  std::lock_guard lock(mutex_);
  *out_ << "[paper " << fixed(elapsed(), 0) << " s] " << text << "\n";
  out_->flush();
}

}  // namespace grainlab::report
