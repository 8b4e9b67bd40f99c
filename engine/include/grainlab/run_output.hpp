#pragma once
// Everything `grainlab run` writes into a run's directory: the output files (OutputWriter),
// the rose data when the scene asks for histograms (HistogramWriter, output.histograms) and
// the ParaView frames when it asks for them (VtkWriter, output.vtk). The CLI
// and the sweeps' batches both use it, so a sweep's run folder is what `grainlab run` writes.
#include <optional>
#include <ostream>
#include <string>

#include "grainlab/histogram_writer.hpp"
#include "grainlab/observer_tee.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/vtk_writer.hpp"

namespace grainlab {

class RunOutput : public ObserverTee {
 public:
  /// `progress` (may be null) receives OutputWriter's progress lines.
  RunOutput(const std::string& directory, const Scene& scene, std::ostream* progress)
      : files_(directory, progress) {
    add(files_);
    if (scene.output.histograms) add(histograms_.emplace(directory));
    if (scene.output.vtk) add(vtk_.emplace(directory, scene.output.vtkEvery));
  }
  RunOutput(const RunOutput&) = delete;  // the tee points at the members
  RunOutput& operator=(const RunOutput&) = delete;
  /// The ParaView writer, if the scene asked for frames.
  const VtkWriter* vtk() const { return vtk_ ? &*vtk_ : nullptr; }

 private:
  OutputWriter files_;
  std::optional<HistogramWriter> histograms_;
  std::optional<VtkWriter> vtk_;
};

}  // namespace grainlab
