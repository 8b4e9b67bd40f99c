#include "specimen_recipe.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "grainlab/errors.hpp"
#include "specimen_grading.hpp"
#include "specimen_shapes.hpp"

namespace grainlab::specimen {
namespace {

// The fraction sums a user may type ("0.3, 0.3, 0.4") and still be taken as 1.
constexpr double kFractionSumTolerance = 1e-6;

void require(bool ok, const std::string& path, const std::string& key, const std::string& reason) {
  if (!ok) throw SceneError(path + "." + key, reason);
}

void checkFields(const SpecimenRecipe& r, const std::string& path) {
  const auto finite = [](double x) { return std::isfinite(x); };
  require(finite(r.discRadius) && r.discRadius > 0, path, "disc_radius", "must be a positive length (m)");
  require(!r.longAxes.empty(), path, "long_axes", "must list at least one long axis");
  for (std::size_t i = 0; i < r.longAxes.size(); ++i) {
    const std::string key = "long_axes[" + std::to_string(i) + "]";
    require(finite(r.longAxes[i]) && r.longAxes[i] > 0, path, key, "must be a positive length (m)");
    require(i == 0 || r.longAxes[i] > r.longAxes[i - 1], path, key, "long axes must be strictly increasing");
  }
  if (!r.countFractions.empty()) {
    require(r.countFractions.size() == r.longAxes.size(), path, "count_fractions",
            "must have one entry per long axis (" + std::to_string(r.longAxes.size()) + ")");
    for (std::size_t i = 0; i < r.countFractions.size(); ++i) {
      require(finite(r.countFractions[i]) && r.countFractions[i] >= 0, path,
              "count_fractions[" + std::to_string(i) + "]", "must be a fraction >= 0");
    }
    const double sum = std::accumulate(r.countFractions.begin(), r.countFractions.end(), 0.0);
    require(std::abs(sum - 1) <= kFractionSumTolerance, path, "count_fractions", "must sum to 1");
  }
  require(finite(r.aspectRatio) && r.aspectRatio >= 1 && r.aspectRatio <= 10, path, "aspect_ratio",
          "must be between 1 and 10");
  require(r.vertices >= 3 && r.vertices <= kMaxPolygonVertices, path, "vertices", "must be between 3 and 8");
  require(r.clumpDiscs >= 2 && r.clumpDiscs <= kMaxClumpDiscs, path, "clump_discs",
          "must be between 2 and " + std::to_string(kMaxClumpDiscs));
  if (r.shape == SpecimenRecipe::Shape::Clump) {
    require(r.aspectRatio < r.clumpDiscs, path, "aspect_ratio",
            "must be below clump_discs (" + std::to_string(r.clumpDiscs) +
                ") for a clump: longer, its discs would not overlap");
  }
  // A little slack so that ±180° converted to radians is accepted.
  require(finite(r.beddingAngle) && std::abs(r.beddingAngle) <= kPi * (1 + 1e-12), path, "bedding_angle_deg",
          "must be between -180 and 180");
  require(finite(r.specimenDiameter) && r.specimenDiameter > 0, path, "specimen_diameter",
          "must be a positive length (m)");
  require(finite(r.targetVoidRatio) && r.targetVoidRatio > 0 && r.targetVoidRatio <= 10, path,
          "target_void_ratio", "must be greater than 0 and at most 10");
  if (r.particleCount) {
    require(*r.particleCount >= 1 && *r.particleCount <= kMaxSpecimenParticles, path, "particle_count",
            "must be between 1 and " + std::to_string(kMaxSpecimenParticles));
  }
  require(finite(r.boundaryRadius) && r.boundaryRadius >= 0, path, "boundary_radius",
          "must be a length >= 0 (m; 0 = automatic)");
}

std::vector<double> countFractions(const SpecimenRecipe& r, const std::string& path) {
  if (!r.countFractions.empty()) {
    const double sum = std::accumulate(r.countFractions.begin(), r.countFractions.end(), 0.0);
    std::vector<double> f = r.countFractions;
    for (double& x : f) x /= sum;
    return f;
  }
  if (r.longAxes.size() == 1) return {1.0};
  require(r.longAxes.size() == 3, path, "count_fractions",
          "must be given when long_axes has " + std::to_string(r.longAxes.size()) +
              " sizes (the paper's grading is solved for 3)");
  std::optional<std::vector<double>> solved = solveCountFractions(r.longAxes);
  require(solved.has_value(), path, "long_axes",
          "no mix of these sizes gives D60/D10 = 1.35 and D30²/(D10·D60) = 1.2; give count_fractions");
  return *solved;
}

std::vector<SizeClass> sizeClasses(const SpecimenRecipe& r, const std::string& path) {
  if (r.shape == SpecimenRecipe::Shape::Disc) {
    SizeClass c;
    c.size = 2 * r.discRadius;
    c.radius = r.discRadius;
    c.area = discArea(r.discRadius);
    c.reach = r.discRadius;
    c.minWidth = 2 * r.discRadius;
    c.fraction = 1;
    return {c};
  }
  const std::vector<double> fractions = countFractions(r, path);
  std::vector<SizeClass> classes;
  for (std::size_t i = 0; i < r.longAxes.size(); ++i) {
    SizeClass c;
    c.size = r.longAxes[i];
    c.fraction = fractions[i];
    if (r.shape == SpecimenRecipe::Shape::Clump) {
      c.members = lineClump(r.longAxes[i], r.aspectRatio, r.clumpDiscs);
      c.area = makeClump(c.members).area;
      c.reach = 0.5 * r.longAxes[i];
      c.minWidth = 2 * c.members.front().radius;
      classes.push_back(std::move(c));
      continue;
    }
    c.vertices = ellipsePolygon(r.longAxes[i], r.aspectRatio, r.vertices);
    c.area = polygonArea(c.vertices);
    c.reach = polygonReach(c.vertices);
    c.minWidth = polygonMinWidth(c.vertices);
    classes.push_back(std::move(c));
  }
  return classes;
}

// Largest-remainder rounding: counts within one of fraction·total, summing to total; ties
// go to the smaller size.
void splitCount(std::vector<SizeClass>& classes, int total) {
  std::vector<double> remainder(classes.size());
  int assigned = 0;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const double exact = classes[i].fraction * total;
    classes[i].count = static_cast<int>(std::floor(exact));
    remainder[i] = exact - classes[i].count;
    assigned += classes[i].count;
  }
  std::vector<std::size_t> order(classes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; assigned < total; k = (k + 1) % order.size(), ++assigned) ++classes[order[k]].count;
}

}  // namespace

SpecimenPlan planSpecimen(const SpecimenRecipe& recipe, const std::string& path) {
  checkFields(recipe, path);
  SpecimenPlan plan;
  plan.classes = sizeClasses(recipe, path);

  if (recipe.particleCount) {
    plan.count = *recipe.particleCount;
  } else {
    double meanArea = 0;
    for (const SizeClass& c : plan.classes) meanArea += c.fraction * c.area;
    const double radius = 0.5 * recipe.specimenDiameter;
    const double solid = kPi * radius * radius / (1 + recipe.targetVoidRatio);
    const double count = std::round(solid / meanArea);
    require(count <= kMaxSpecimenParticles, path, "specimen_diameter",
            "gives " + std::to_string(static_cast<long long>(std::min(count, 1e15))) + " particles, more than " +
                std::to_string(kMaxSpecimenParticles));
    plan.count = std::max(1, static_cast<int>(count));
  }
  splitCount(plan.classes, plan.count);
  for (const SizeClass& c : plan.classes) plan.solidArea += c.count * c.area;
  return plan;
}

}  // namespace grainlab::specimen
