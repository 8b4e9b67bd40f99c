#pragma once
// The observer of one assembly's run: writes the run's own output directory (OutputWriter,
// plus roses.json with the histograms the rose diagrams use) and keeps, for the report, the
// shearing stage's series and those histograms.
#include <string>

#include "grainlab/output_writer.hpp"
#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/shearing_recorder.hpp"

namespace grainlab::report {

class AssemblyRecorder : public RunObserver {
 public:
  /// Fills its own copy of `result` (see result()) and writes the run's files into `runDir`.
  AssemblyRecorder(AssemblyResult result, std::string runDir);
  AssemblyRecorder(const AssemblyRecorder&) = delete;  // shearing_ refers to result_
  AssemblyRecorder& operator=(const AssemblyRecorder&) = delete;
  const AssemblyResult& result() const { return result_; }
  void onStart(const Scene&, const World&) override;
  void onSample(const Sample&, const World&) override;
  void onFinish(const RunSummary&, const World&) override;

 private:
  AssemblyResult result_;
  std::string runDir_;
  OutputWriter writer_;
  ShearingRecorder shearing_;
};

/// The name of the file in a run's directory that keeps its rose snapshots.
inline constexpr const char* kRosesFile = "roses.json";

}  // namespace grainlab::report
