#include "grainlab/report/assembly_recorder.hpp"

#include <cmath>

namespace grainlab::report {
namespace {

size_t columnIndex(const char* name) {
  const auto& columns = seriesColumns();
  for (size_t k = 0; k < columns.size(); ++k) {
    if (columns[k] == name) return k;
  }
  throw std::logic_error(std::string("series has no column ") + name);
}

}  // namespace

AssemblyRecorder::AssemblyRecorder(AssemblyResult& result, std::string runDir, ProgressBoard* board, size_t index)
    : result_(result), writer_(std::move(runDir), nullptr), board_(board), index_(index) {}

void AssemblyRecorder::onStart(const Scene& scene, const World& world) {
  writer_.onStart(scene, world);
  for (size_t s = 0; s < scene.stages.size(); ++s) {
    if (scene.stages[s].type == StageSpec::Type::Biaxial) {
      shearingStage_ = static_cast<int>(s);
      break;
    }
  }
}

void AssemblyRecorder::onSample(const Sample& sample, const World& world) {
  writer_.onSample(sample, world);
  static const size_t stageColumn = columnIndex("stage");
  const int stage = stageColumn < sample.values.size() ? static_cast<int>(sample.values[stageColumn]) : -1;
  if (shearingStage_ < 0 || stage > shearingStage_) return;
  if (stage < shearingStage_) {
    before_ = sample.values;
    beforeStep_ = sample.step;
    if (sample.histograms) beforeHistograms_ = *sample.histograms;
    else beforeHistograms_.reset();
    return;
  }
  if (!shearingStarted_) {
    shearingStarted_ = true;
    // The run samples a stage's start only when it differs from the previous stage's end,
    // so the shearing's ε22 = 0 state is usually the consolidation's last sample.
    if (before_ && beforeStep_ != sample.step) {
      std::vector<double> start = *before_;
      // Strains are measured from the shearing's start, which is this very state.
      for (const char* name : {"axial_strain", "lateral_strain", "volumetric_strain"}) start[columnIndex(name)] = 0.0;
      start[stageColumn] = shearingStage_;
      appendShearingRow(std::move(start), beforeHistograms_ ? &*beforeHistograms_ : nullptr);
    }
  }
  appendShearingRow(sample.values, sample.histograms);
}

void AssemblyRecorder::appendShearingRow(std::vector<double> values, const analysis::PolarHistograms* histograms) {
  static const size_t strainColumn = columnIndex("axial_strain");
  const double strain = values[strainColumn];
  result_.shearing.append(seriesColumns(), values);
  if (!histograms || !std::isfinite(strain)) return;
  for (RoseSnapshot& rose : result_.roses) {
    // Nearest sample wins; on a tie the earlier one stays.
    if (!rose.histograms || std::abs(strain - rose.targetStrain) < std::abs(rose.axialStrain - rose.targetStrain)) {
      rose.axialStrain = strain;
      rose.histograms = *histograms;
    }
  }
}

void AssemblyRecorder::onProgress(double fraction, std::string_view stage, const World& world) {
  writer_.onProgress(fraction, stage, world);
  if (board_) board_->update(index_, fraction, stage);
}

void AssemblyRecorder::onFinish(const RunSummary& summary, const World& world) {
  writer_.onFinish(summary, world);
  result_.summary = summary;
  if (board_) board_->finished(index_, summary.status, summary.wallSeconds);
}

}  // namespace grainlab::report
