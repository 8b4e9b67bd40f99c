#include "grainlab/studies/paper/assembly_result.hpp"

#include <cmath>

#include "grainlab/math.hpp"

namespace grainlab::report {

const std::vector<double>& roseStrains() {
  static const std::vector<double> strains{0.0, 0.05, 0.20};
  return strains;
}

std::string AssemblyResult::label() const {
  switch (kind) {
    case AssemblyKind::Circular: return "circular";
    case AssemblyKind::Random: return "random";
    case AssemblyKind::Bedding: return "α = " + std::to_string(static_cast<int>(std::lround(beddingDeg))) + "°";
  }
  return preset;
}

AssemblyResult describeAssembly(const std::string& preset, const Scene& scene) {
  AssemblyResult r;
  r.preset = preset;
  r.quick = preset.size() > 6 && preset.ends_with("-quick");
  if (scene.assembly) {
    const SpecimenRecipe& recipe = *scene.assembly;
    if (recipe.shape == SpecimenRecipe::Shape::Disc) {
      r.kind = AssemblyKind::Circular;
    } else if (recipe.orientation == SpecimenRecipe::Orientation::Random) {
      r.kind = AssemblyKind::Random;
    } else {
      r.kind = AssemblyKind::Bedding;
      r.beddingDeg = degrees(recipe.beddingAngle);
    }
  }
  for (double strain : roseStrains()) r.roses.push_back({strain, std::nan(""), std::nullopt});
  return r;
}

}  // namespace grainlab::report
