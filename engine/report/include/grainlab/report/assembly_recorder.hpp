#pragma once
// The observer of one assembly's run: writes the run's own output directory (OutputWriter,
// plus roses.json with the histograms the rose diagrams use) and keeps, for the report, the
// shearing stage's series and those histograms.
#include <string>

#include "grainlab/output_writer.hpp"
#include "grainlab/report/assembly_result.hpp"
#include "grainlab/report/progress_board.hpp"
#include "grainlab/report/shearing_collector.hpp"

namespace grainlab::report {

class AssemblyRecorder : public RunObserver {
 public:
  /// Fills `result` (which must outlive the run) and writes the run's files into `runDir`.
  /// `board` (may be null) receives progress as run `index`.
  AssemblyRecorder(AssemblyResult& result, std::string runDir, ProgressBoard* board, size_t index);
  void onStart(const Scene&, const World&) override;
  void onSample(const Sample&, const World&) override;
  void onProgress(double fraction, std::string_view stage, const World&) override;
  void onFinish(const RunSummary&, const World&) override;

 private:
  AssemblyResult& result_;
  std::string runDir_;
  OutputWriter writer_;
  ProgressBoard* board_;
  size_t index_;
  ShearingCollector collector_;
};

/// The name of the file in a run's directory that keeps its rose snapshots.
inline constexpr const char* kRosesFile = "roses.json";

}  // namespace grainlab::report
