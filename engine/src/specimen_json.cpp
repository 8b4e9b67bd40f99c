// The scene's "assembly" object <-> SpecimenRecipe. Keys are snake_case; lengths in m;
// the bedding angle is in degrees in JSON and radians in the struct.
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "grainlab/errors.hpp"
#include "grainlab/specimen.hpp"
#include "json_reader.hpp"
#include "specimen_recipe.hpp"

namespace grainlab {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::vector<double> numberArray(const nlohmann::json& value, const std::string& path,
                                const std::vector<double>& fallback) {
  if (value.is_null()) return fallback;
  if (!value.is_array()) throw SceneError(path, "must be an array of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < value.size(); ++i) {
    if (!value[i].is_number()) throw SceneError(path + "[" + std::to_string(i) + "]", "must be a number");
    out.push_back(value[i].get<double>());
  }
  return out;
}

}  // namespace

SpecimenRecipe parseSpecimenRecipe(const nlohmann::json& assembly, const std::string& path) {
  JsonReader r(assembly, path);
  SpecimenRecipe recipe;
  const std::string shape = r.choice("shape", "disc", {"disc", "elongated", "clump"});
  recipe.shape = shape == "disc"        ? SpecimenRecipe::Shape::Disc
                 : shape == "elongated" ? SpecimenRecipe::Shape::Elongated
                                        : SpecimenRecipe::Shape::Clump;
  recipe.discRadius = r.number("disc_radius", recipe.discRadius, 0, kInfinity, true);
  recipe.longAxes = numberArray(r.raw("long_axes"), r.fieldPath("long_axes"), recipe.longAxes);
  recipe.countFractions = numberArray(r.raw("count_fractions"), r.fieldPath("count_fractions"), {});
  recipe.aspectRatio = r.number("aspect_ratio", recipe.aspectRatio, 1, 10);
  recipe.vertices = static_cast<int>(r.integer("vertices", recipe.vertices, 3, kMaxPolygonVertices));
  recipe.clumpDiscs = static_cast<int>(r.integer("clump_discs", recipe.clumpDiscs, 2, specimen::kMaxClumpDiscs));
  recipe.orientation = r.choice("orientation", "random", {"random", "bedding"}) == "random"
                           ? SpecimenRecipe::Orientation::Random
                           : SpecimenRecipe::Orientation::Bedding;
  recipe.beddingAngle = radians(r.number("bedding_angle_deg", degrees(recipe.beddingAngle), -180, 180));
  recipe.specimenDiameter = r.number("specimen_diameter", recipe.specimenDiameter, 0, kInfinity, true);
  recipe.targetVoidRatio = r.number("target_void_ratio", recipe.targetVoidRatio, 0, 10, true);
  // null is accepted as "derive the count", like an omitted key.
  if (!r.raw("particle_count").is_null()) {
    recipe.particleCount =
        static_cast<int>(r.integer("particle_count", 0, 1, specimen::kMaxSpecimenParticles));
  }
  recipe.boundaryRadius = r.number("boundary_radius", recipe.boundaryRadius, 0, kInfinity);
  r.finish();
  // The checks across fields (element ranges, the grading solve, the particle count) are
  // the generator's own, so a recipe that parses always generates.
  try {
    specimen::planSpecimen(recipe, path);
  } catch (const SceneError& e) {
    // Too many particles follows from the specimen's size over the grains': name the grains'
    // size when it is the further of the two from its default.
    const SpecimenRecipe defaults;
    const bool discs = recipe.shape == SpecimenRecipe::Shape::Disc;
    const double grain = discs ? recipe.discRadius : recipe.longAxes.front();
    const double grainDefault = discs ? defaults.discRadius : defaults.longAxes.front();
    const bool grainsSmall = std::log(grainDefault / grain) > std::log(recipe.specimenDiameter / defaults.specimenDiameter);
    if (e.field() == path + ".specimen_diameter" && e.reason().find("particles, more than") != std::string::npos &&
        grain > 0 && grainsSmall)
      throw SceneError(path + (discs ? ".disc_radius" : ".long_axes"), e.reason());
    throw;
  }
  return recipe;
}

nlohmann::json specimenRecipeToJson(const SpecimenRecipe& recipe) {
  nlohmann::json j = {
      {"shape", recipe.shape == SpecimenRecipe::Shape::Disc        ? "disc"
                : recipe.shape == SpecimenRecipe::Shape::Elongated ? "elongated"
                                                                    : "clump"},
      {"disc_radius", recipe.discRadius},
      {"long_axes", recipe.longAxes},
      {"count_fractions", recipe.countFractions},
      {"aspect_ratio", recipe.aspectRatio},
      {"vertices", recipe.vertices},
      {"clump_discs", recipe.clumpDiscs},
      {"orientation", recipe.orientation == SpecimenRecipe::Orientation::Random ? "random" : "bedding"},
      {"bedding_angle_deg", degrees(recipe.beddingAngle)},
      {"specimen_diameter", recipe.specimenDiameter},
      {"target_void_ratio", recipe.targetVoidRatio},
      {"boundary_radius", recipe.boundaryRadius},
  };
  if (recipe.particleCount) j["particle_count"] = *recipe.particleCount;
  return j;
}

}  // namespace grainlab
