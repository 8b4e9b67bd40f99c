#pragma once
// Writes a run's output directory (contracts.md): series.csv as the run goes, then
// particles_final.csv, contacts_final.csv and summary.json at the end. Each final file is
// written to a temporary name and renamed, so a reader never sees half a file.
#include <chrono>
#include <fstream>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "grainlab/run.hpp"

namespace grainlab {

class OutputWriter : public RunObserver {
 public:
  /// Creates `directory` if needed. `progress` (may be null) receives a progress line now and then.
  OutputWriter(std::string directory, std::ostream* progress);
  void onEstimate(const RunCost&) override;
  /// The validity envelope's warnings, each on a line of the progress stream.
  void onWarnings(const std::vector<ValidityWarning>& warnings) override;
  void onStart(const Scene&, const World&) override;
  void onSample(const Sample&, const World&) override;
  void onProgress(double fraction, std::string_view stage, const World&) override;
  void onFinish(const RunSummary&, const World&) override;
  /// Checkpoints: series.csv's length, flushed to disk first.
  void persistOutput(StateArchive& a) override;
  /// series.csv cut back to its length at the checkpoint, then appended to.
  void onResume(const Scene&, const World&) override;

 private:
  /// Appends to series.csv and flushes; if that fails (a full disk), cuts the file back to
  /// its last whole row and throws, naming the file and the system's reason.
  void appendSeries(const std::string& text);

  std::string dir_;
  std::ostream* progress_;
  std::ofstream series_;
  std::uint64_t seriesGood_ = 0;   // series.csv's length after its last whole row
  std::uint64_t seriesBytes_ = 0;  // at the checkpoint being loaded
  int lastPercent_ = -1;
  std::chrono::steady_clock::time_point started_;  // for the time left
};

/// The CSV text of one series row (empty cells for values not measured).
std::string formatSeriesRow(const Sample& sample);
/// summary.json's content for a finished run (what OutputWriter writes).
nlohmann::json summaryJson(const RunSummary& summary, const World& world);
/// The header line of series.csv.
std::string seriesHeader();
/// One line of series.csv split into its cells (series.csv never quotes: its only text
/// cells are stage names); a trailing empty cell is kept.
std::vector<std::string> splitSeriesRow(const std::string& line);

/// Writes `text` to `path` through a temporary file and a rename: a reader (or a resume)
/// sees the whole file or none of it. Throws std::runtime_error naming `path` and the
/// system's reason ("No space left on device") if it cannot, and leaves no temporary file.
void writeFileAtomically(const std::string& path, const std::string& text);
/// The same for a file made of several pieces, written one after the other.
void writeFileAtomically(const std::string& path, std::initializer_list<std::string_view> parts);

}  // namespace grainlab
