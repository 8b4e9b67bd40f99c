#pragma once
// What the report keeps of one assembly's run: its summary, the shearing stage's series and
// the polar histograms nearest to the strains the rose diagrams show.
#include <optional>
#include <string>
#include <vector>

#include "grainlab/analysis/histogram.hpp"
#include "grainlab/studies/paper/shearing_series.hpp"
#include "grainlab/run.hpp"
#include "grainlab/scene.hpp"

namespace grainlab::report {

/// The paper's three kinds of assembly (section 4).
enum class AssemblyKind { Circular, Random, Bedding };

/// The histograms of the sample nearest to a target axial strain of the shearing stage.
struct RoseSnapshot {
  double targetStrain = 0;                          ///< ε22 asked for (0.05 = 5 %)
  double axialStrain = 0;                           ///< ε22 of the sample taken
  std::optional<analysis::PolarHistograms> histograms;  ///< empty if no sample had them
};

/// The axial strains (ε22 of the shearing stage) at which rose diagrams are drawn: 0, 5, 20 %.
const std::vector<double>& roseStrains();

struct AssemblyResult {
  std::string preset;                   ///< e.g. "elongated-bedding-30-quick"
  AssemblyKind kind = AssemblyKind::Circular;
  double beddingDeg = 0;                ///< α, degrees (Bedding only)
  bool quick = false;                   ///< a -quick preset
  int seed = 1;                         ///< the scene's seed: one member of a seed ensemble
  RunSummary summary;
  ShearingSeries shearing;              ///< the biaxial stage, first row at ε22 = 0
  std::vector<RoseSnapshot> roses;      ///< one per roseStrains() entry
  /// "circular", "random" or "α = 30°".
  std::string label() const;
};

/// Fills preset, kind, beddingDeg and quick from the scene (its assembly recipe) and name.
AssemblyResult describeAssembly(const std::string& preset, const Scene& scene);

}  // namespace grainlab::report
