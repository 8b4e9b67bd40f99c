#include "grainlab/studies/paper/assembly_recorder.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "grainlab/studies/paper/run_loader.hpp"

namespace grainlab::report {

AssemblyRecorder::AssemblyRecorder(AssemblyResult result, std::string runDir)
    : result_(std::move(result)), runDir_(runDir), writer_(std::move(runDir), nullptr), shearing_(result_) {}

void AssemblyRecorder::onStart(const Scene& scene, const World& world) {
  writer_.onStart(scene, world);
  shearing_.onStart(scene, world);
}

void AssemblyRecorder::onSample(const Sample& sample, const World& world) {
  writer_.onSample(sample, world);
  shearing_.onSample(sample, world);
}

void AssemblyRecorder::onFinish(const RunSummary& summary, const World& world) {
  writer_.onFinish(summary, world);
  result_.summary = summary;
  // The histograms are not in series.csv: keep them so the report can be rebuilt from the run.
  const std::filesystem::path path = std::filesystem::path(runDir_) / kRosesFile;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << rosesToJson(result_.roses).dump() << "\n";
}

}  // namespace grainlab::report
