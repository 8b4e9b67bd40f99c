#include "grainlab/studies/paper/shearing_recorder.hpp"

namespace grainlab::report {

ShearingRecorder::ShearingRecorder(AssemblyResult& result) : result_(&result), collector_(result, -1) {}

void ShearingRecorder::onStart(const Scene& scene, const World&) {
  collector_ = ShearingCollector(*result_, biaxialStageIndex(scene));
}

void ShearingRecorder::onSample(const Sample& sample, const World&) {
  collector_.add(sample.step, sample.values, sample.histograms);
}

}  // namespace grainlab::report
