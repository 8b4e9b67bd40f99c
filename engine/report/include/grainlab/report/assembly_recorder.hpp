#pragma once
// The observer of one assembly's run: writes the run's own output directory (OutputWriter)
// and keeps, for the report, the shearing stage's series and the histograms nearest to the
// rose diagrams' strains.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grainlab/analysis/histogram.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/report/assembly_result.hpp"
#include "grainlab/report/progress_board.hpp"

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
  void appendShearingRow(std::vector<double> values, const analysis::PolarHistograms* histograms);

  AssemblyResult& result_;
  OutputWriter writer_;
  ProgressBoard* board_;
  size_t index_;
  int shearingStage_ = -1;  // index of the biaxial stage; -1 if the scene has none
  bool shearingStarted_ = false;
  // The latest sample before the shearing stage: the state it starts from.
  std::optional<std::vector<double>> before_;
  std::int64_t beforeStep_ = -1;
  std::optional<analysis::PolarHistograms> beforeHistograms_;
};

}  // namespace grainlab::report
