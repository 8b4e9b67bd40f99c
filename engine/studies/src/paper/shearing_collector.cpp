#include "grainlab/studies/paper/shearing_collector.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "grainlab/run.hpp"

namespace grainlab::report {

int biaxialStageIndex(const Scene& scene) {
  for (size_t s = 0; s < scene.stages.size(); ++s) {
    if (scene.stages[s].type == StageSpec::Type::Biaxial) return static_cast<int>(s);
  }
  return -1;
}

ShearingCollector::ShearingCollector(AssemblyResult& result, int shearingStage)
    : result_(&result), shearingStage_(shearingStage) {}

void ShearingCollector::add(std::int64_t step, const std::vector<double>& values,
                            const analysis::PolarHistograms* histograms) {
  constexpr size_t stageColumn = columnIndex(SeriesColumnId::Stage);
  const double stageValue = stageColumn < values.size() ? values[stageColumn] : NAN;
  const int stage = std::isfinite(stageValue) ? static_cast<int>(stageValue) : -1;
  if (shearingStage_ < 0 || stage < 0 || stage > shearingStage_) return;
  if (stage < shearingStage_) {
    before_ = values;
    beforeStep_ = step;
    if (histograms) beforeHistograms_ = *histograms;
    else beforeHistograms_.reset();
    return;
  }
  if (!started_) {
    started_ = true;
    // The run samples a stage's start only when it differs from the previous stage's end,
    // so the shearing's ε22 = 0 state is usually the consolidation's last sample.
    if (before_ && beforeStep_ != step) {
      std::vector<double> start = *before_;
      // Strains are measured from the shearing's start, which is this very state.
      using Id = SeriesColumnId;
      for (Id c : {Id::AxialStrain, Id::LateralStrain, Id::VolumetricStrain}) start[columnIndex(c)] = 0.0;
      start[stageColumn] = shearingStage_;
      append(std::move(start), beforeHistograms_ ? &*beforeHistograms_ : nullptr);
    }
  }
  append(values, histograms);
}

void ShearingCollector::append(std::vector<double> values, const analysis::PolarHistograms* histograms) {
  constexpr size_t strainColumn = columnIndex(SeriesColumnId::AxialStrain);
  const double strain = values[strainColumn];
  result_->shearing.append(seriesColumns(), values);
  if (!histograms || !std::isfinite(strain)) return;
  for (RoseSnapshot& rose : result_->roses) {
    // Nearest sample wins; on a tie the earlier one stays.
    if (!rose.histograms || std::abs(strain - rose.targetStrain) < std::abs(rose.axialStrain - rose.targetStrain)) {
      rose.axialStrain = strain;
      rose.histograms = *histograms;
    }
  }
}

}  // namespace grainlab::report
