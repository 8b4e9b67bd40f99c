#include "grainlab/name_table.hpp"
#include "grainlab/scene.hpp"

namespace grainlab {
namespace {

using Type = StageSpec::Type;
constexpr NameTable<Type, 7> kNames{{
    {Type::Free, "free"},
    {Type::Compaction, "compaction"},
    {Type::Isotropic, "isotropic"},
    {Type::Biaxial, "biaxial"},
    {Type::Rotation, "rotation"},
    {Type::Cyclic, "cyclic"},
    {Type::SimpleShear, "simple_shear"},
}};
constexpr std::array<Type, kNames.size()> kTypes = [] {
  std::array<Type, kNames.size()> types{};
  for (size_t k = 0; k < kNames.size(); ++k) types[k] = kNames[k].first;
  return types;
}();

}  // namespace

std::string_view toString(StageSpec::Type type) { return nameIn(kNames, type); }

std::optional<StageSpec::Type> parseStageType(std::string_view name) { return valueIn(kNames, name); }

std::span<const StageSpec::Type> stageTypes() { return kTypes; }

}  // namespace grainlab
