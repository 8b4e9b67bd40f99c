#pragma once
// Picks the shearing stage out of a run's samples as they come: the rows of the biaxial stage,
// preceded by the state it starts from (ε22 = 0), and the histograms nearest to the rose
// diagrams' strains. Used while a run goes (ShearingRecorder) and when reading one back.
#include <cstdint>
#include <optional>
#include <vector>

#include "grainlab/analysis/histogram.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/studies/paper/assembly_result.hpp"

namespace grainlab::report {

/// The index of the scene's first biaxial stage, −1 if it has none.
int biaxialStageIndex(const Scene& scene);

class ShearingCollector {
 public:
  /// Fills `result` (which must outlive the collector). `shearingStage` is the index of the
  /// scene's biaxial stage, −1 if it has none (then nothing is collected).
  ShearingCollector(AssemblyResult& result, int shearingStage);
  /// One sample: its step, its values by seriesColumns() (the "stage" column holds the stage's
  /// index) and its histograms, if any.
  void add(std::int64_t step, const std::vector<double>& values, const analysis::PolarHistograms* histograms);

 private:
  void append(std::vector<double> values, const analysis::PolarHistograms* histograms);

  AssemblyResult* result_;  // a pointer, so a recorder can replace its collector once it knows the scene
  int shearingStage_;
  bool started_ = false;
  // The latest sample before the shearing stage: the state it starts from.
  std::optional<std::vector<double>> before_;
  std::int64_t beforeStep_ = -1;
  std::optional<analysis::PolarHistograms> beforeHistograms_;
};

}  // namespace grainlab::report
