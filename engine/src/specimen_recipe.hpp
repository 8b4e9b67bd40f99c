#pragma once
// What a specimen recipe asks for, checked: its size classes with their outlines and
// particle counts. Shared by the JSON parser (so a bad recipe fails at parse time, naming
// the field) and the generator.
#include <string>
#include <vector>

#include "grainlab/clump.hpp"
#include "grainlab/math.hpp"
#include "grainlab/specimen.hpp"

namespace grainlab::specimen {

/// The most specimen particles a recipe may ask for (directly or through its size).
inline constexpr int kMaxSpecimenParticles = 200'000;
/// The most discs a generated clump may have.
inline constexpr int kMaxClumpDiscs = 8;

/// One particle size of a recipe.
struct SizeClass {
  double size = 0;             ///< m: disc diameter, or polygon or clump long axis L
  double radius = 0;           ///< m, discs
  std::vector<Vec2> vertices;  ///< m, polygons: body frame, long axis along +x, centroid at origin
  std::vector<ClumpMember> members;  ///< m, clumps: body frame, along +x, centroid at origin
  double area = 0;             ///< m²
  double reach = 0;            ///< m, largest distance of the outline from the centroid
  double minWidth = 0;         ///< m, smallest width
  double fraction = 0;         ///< by count, the classes summing to 1
  int count = 0;               ///< particles of this class in the specimen
};

struct SpecimenPlan {
  std::vector<SizeClass> classes;  ///< in the recipe's order (ascending size)
  int count = 0;                   ///< specimen particles, the classes' counts summed
  double solidArea = 0;            ///< m², the particles' areas summed
};

/// The recipe's size classes and counts. The count is recipe.particleCount, or the solid
/// area of the consolidated specimen, π(D/2)²/(1 + e), over the mean particle area by
/// count, rounded; it is split over the classes by largest remainder. Elongated count
/// fractions are the recipe's (normalised) or, when it gives none, solved for the paper's
/// grading (specimen_grading.hpp). Throws SceneError(path + "." + key, reason), key as in
/// the scene JSON, for anything out of range.
SpecimenPlan planSpecimen(const SpecimenRecipe& recipe, const std::string& path);

}  // namespace grainlab::specimen
