#include "grainlab/report/assembly_recorder.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "grainlab/report/run_loader.hpp"

namespace grainlab::report {

AssemblyRecorder::AssemblyRecorder(AssemblyResult& result, std::string runDir, ProgressBoard* board, size_t index)
    : result_(result), runDir_(runDir), writer_(std::move(runDir), nullptr), board_(board), index_(index),
      collector_(result, -1) {}

void AssemblyRecorder::onStart(const Scene& scene, const World& world) {
  writer_.onStart(scene, world);
  collector_ = ShearingCollector(result_, biaxialStageIndex(scene));
}

void AssemblyRecorder::onSample(const Sample& sample, const World& world) {
  writer_.onSample(sample, world);
  collector_.add(sample.step, sample.values, sample.histograms);
}

void AssemblyRecorder::onProgress(double fraction, std::string_view stage, const World& world) {
  writer_.onProgress(fraction, stage, world);
  if (board_) board_->update(index_, fraction, stage);
}

void AssemblyRecorder::onFinish(const RunSummary& summary, const World& world) {
  writer_.onFinish(summary, world);
  result_.summary = summary;
  // The histograms are not in series.csv: keep them so the report can be rebuilt from the run.
  const std::filesystem::path path = std::filesystem::path(runDir_) / kRosesFile;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << rosesToJson(result_.roses).dump() << "\n";
  if (board_) board_->finished(index_, summary.status, summary.wallSeconds);
}

}  // namespace grainlab::report
