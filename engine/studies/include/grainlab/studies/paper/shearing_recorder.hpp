#pragma once
// The observer that keeps a run's shearing stage as it goes (through a ShearingCollector):
// the one piece that does so, for the paper's runs (inside AssemblyRecorder) and the
// trade-off's.
#include "grainlab/run.hpp"
#include "grainlab/studies/paper/assembly_result.hpp"
#include "grainlab/studies/paper/shearing_collector.hpp"

namespace grainlab::report {

class ShearingRecorder : public RunObserver {
 public:
  /// Fills result.shearing and result.roses (snapshots only for the roses already listed);
  /// `result` must outlive the recorder.
  explicit ShearingRecorder(AssemblyResult& result);
  void onStart(const Scene& scene, const World&) override;
  void onSample(const Sample& sample, const World&) override;

 private:
  AssemblyResult* result_;
  ShearingCollector collector_;
};

}  // namespace grainlab::report
