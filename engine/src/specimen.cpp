// generateSpecimen: plan the size classes, orient and place the particles at random without
// overlap in a circle looser than the final specimen, number them along space, then close a
// ring of boundary discs around them.
#include "grainlab/specimen.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "grainlab/errors.hpp"
#include "specimen_order.hpp"
#include "specimen_placement.hpp"
#include "specimen_random.hpp"
#include "specimen_recipe.hpp"
#include "specimen_ring.hpp"

namespace grainlab {
namespace {

using specimen::Grain;
using specimen::SizeClass;

// Area fraction of the placement circle. Random sequential placement jams near 0.55 for
// discs (and about as high for aspect-1.5 shapes) and slows sharply on the way; at these
// it takes milliseconds for thousands of particles, and the compaction stage has less to
// shrink than from a looser start. Elongated shapes get a looser circle because a random
// orientation leaves more awkward holes.
constexpr double kDiscPlacementFraction = 0.45;
constexpr double kPolygonPlacementFraction = 0.40;
// If a grain finds no room (only a handful of grains in a tight circle can run out), the
// whole placement starts again in a circle this much looser by area, a few times.
constexpr double kLoosenFactor = 0.85;
constexpr int kPlacementRounds = 12;

// Clearance between the placement circle and the ring discs' inner edge, as a fraction of
// the ring disc radius: the ring starts just clear of every particle.
constexpr double kRingClearance = 0.01;

// Never denser than the consolidated specimen, so compaction always shrinks the ring.
double firstPlacementFraction(const SpecimenRecipe& recipe) {
  const bool discs = recipe.shape == SpecimenRecipe::Shape::Disc;
  return std::min(discs ? kDiscPlacementFraction : kPolygonPlacementFraction, 1 / (1 + recipe.targetVoidRatio));
}

// The boundary ring around a placement circle of radius `placementRadius`.
struct RingLayout {
  double discRadius = 0;  // m
  double radius = 0;      // m, of the disc centres
  int count = 0;
};
RingLayout layoutRing(const SpecimenRecipe& recipe, const specimen::SpecimenPlan& plan, double placementRadius) {
  double smallestWidth = INFINITY;
  for (const SizeClass& c : plan.classes) {
    if (c.count > 0) smallestWidth = std::min(smallestWidth, c.minWidth);
  }
  RingLayout ring;
  // Automatic ring discs are as wide as the narrowest particle: never so big that a
  // particle nests deep in the cusp between two of them.
  ring.discRadius = recipe.boundaryRadius > 0 ? recipe.boundaryRadius : 0.5 * smallestWidth;
  ring.radius = placementRadius + (1 + kRingClearance) * ring.discRadius;
  specimen::RingPath path;
  const double solidFraction = 1 / (1 + recipe.targetVoidRatio);
  path.consolidatedRadius = std::sqrt(plan.solidArea / (kPi * solidFraction)) + ring.discRadius;
  ring.count = specimen::ringDiscCount(ring.radius, ring.discRadius, path);
  return ring;
}

}  // namespace

int plannedParticleCount(const SpecimenRecipe& recipe) {
  const specimen::SpecimenPlan plan = specimen::planSpecimen(recipe, "assembly");
  const double placementRadius = std::sqrt(plan.solidArea / (kPi * firstPlacementFraction(recipe)));
  return plan.count + layoutRing(recipe, plan, placementRadius).count;
}

namespace {

// The recipe's grains, largest first (big particles find room while the container is empty,
// small ones fill in), each turned to its orientation (drawn from `random` for a random fabric).
struct Grains {
  std::vector<Grain> grains;
  std::vector<const SizeClass*> classOf;
  std::vector<double> angles;
};
Grains makeGrains(const SpecimenRecipe& recipe, const specimen::SpecimenPlan& plan, specimen::SpecimenRandom& random) {
  const bool discs = recipe.shape == SpecimenRecipe::Shape::Disc;
  const bool clumps = recipe.shape == SpecimenRecipe::Shape::Clump;
  Grains out;
  std::vector<Grain>& grains = out.grains;
  std::vector<const SizeClass*>& classOf = out.classOf;
  std::vector<double>& angles = out.angles;
  grains.reserve(static_cast<std::size_t>(plan.count));
  for (auto c = plan.classes.rbegin(); c != plan.classes.rend(); ++c) {
    for (int k = 0; k < c->count; ++k) {
      Grain g;
      g.shape = discs ? ShapeKind::Disc : clumps ? ShapeKind::Clump : ShapeKind::Polygon;
      g.radius = c->radius;
      g.reach = c->reach;
      double angle = 0;
      if (!discs) {
        // Drawn once per particle, before its placement tries, so which orientations get
        // placed cannot depend on where there is room.
        angle = recipe.orientation == SpecimenRecipe::Orientation::Bedding ? recipe.beddingAngle
                                                                          : 2 * kPi * random.uniform();
        for (const Vec2& v : c->vertices) g.vertices.push_back(rotate(v, angle));
        for (const ClumpMember& m : c->members) g.members.push_back({rotate(m.centre, angle), m.radius});
      }
      grains.push_back(std::move(g));
      classOf.push_back(&*c);
      angles.push_back(angle);
    }
  }
  return out;
}

// Grain i as a particle at `centre`.
ParticleSpec particleOf(const SpecimenRecipe& recipe, const Grains& g, std::size_t i, const Vec2& centre) {
  ParticleSpec p;
  p.shape = g.grains[i].shape;
  p.position = centre;
  if (recipe.shape == SpecimenRecipe::Shape::Disc) {
    p.radius = g.classOf[i]->radius;
  } else if (recipe.shape == SpecimenRecipe::Shape::Clump) {
    // Body-frame members (long axis along +x about the centroid) turned by `angle`.
    p.members = g.classOf[i]->members;
    p.angle = g.angles[i];
  } else {
    // Body-frame vertices (long axis along +x, centroid at the origin) turned by `angle`:
    // the angle is then the long axis's direction for the whole run.
    p.vertices = g.classOf[i]->vertices;
    p.angle = g.angles[i];
  }
  return p;
}

}  // namespace

Specimen generateSpecimen(const SpecimenRecipe& recipe, std::uint64_t seed) {
  const specimen::SpecimenPlan plan = specimen::planSpecimen(recipe, "assembly");
  specimen::SpecimenRandom random(seed);
  const Grains made = makeGrains(recipe, plan, random);
  const std::vector<Grain>& grains = made.grains;

  double placementFraction = firstPlacementFraction(recipe);
  double placementRadius = 0;
  std::optional<std::vector<Vec2>> placed;
  for (int round = 0; round < kPlacementRounds && !placed; ++round, placementFraction *= kLoosenFactor) {
    placementRadius = std::sqrt(plan.solidArea / (kPi * placementFraction));
    placed = specimen::placeWithoutOverlap(grains, placementRadius, random);
  }
  if (!placed) throw SceneError("assembly", "could not place the particles without overlap");
  const std::vector<Vec2>& centres = *placed;

  Specimen out;
  out.specimenCount = plan.count;
  out.particles.reserve(centres.size());
  // Numbered along space (specimen_order.hpp): placed at random, numbered in bands.
  const double spacing = placementRadius * std::sqrt(kPi / static_cast<double>(std::max<std::size_t>(centres.size(), 1)));
  for (std::size_t i : specimen::orderAlongSpace(centres, spacing)) out.particles.push_back(particleOf(recipe, made, i, centres[i]));

  const RingLayout ring = layoutRing(recipe, plan, placementRadius);
  for (int k = 0; k < ring.count; ++k) {
    const double t = 2 * kPi * k / ring.count;
    ParticleSpec p;
    p.shape = ShapeKind::Disc;
    p.radius = ring.discRadius;
    p.position = Vec2(ring.radius * std::cos(t), ring.radius * std::sin(t));
    p.motion = Motion::Kinematic;
    p.boundary = true;
    out.particles.push_back(std::move(p));
  }
  out.initialRingRadius = ring.radius;
  return out;
}

CellSpecimen generateCellSpecimen(const SpecimenRecipe& recipe, std::uint64_t seed) {
  const specimen::SpecimenPlan plan = specimen::planSpecimen(recipe, "assembly");
  specimen::SpecimenRandom random(seed);
  const Grains made = makeGrains(recipe, plan, random);
  double placementFraction = firstPlacementFraction(recipe);
  double side = 0;
  std::optional<std::vector<Vec2>> placed;
  for (int round = 0; round < kPlacementRounds && !placed; ++round, placementFraction *= kLoosenFactor) {
    side = std::sqrt(plan.solidArea / placementFraction);
    placed = specimen::placeInPeriodicSquare(made.grains, side, random);
  }
  if (!placed) throw SceneError("assembly", "could not place the particles without overlap in a periodic cell");
  CellSpecimen out;
  // Numbered along space, as the ring's specimens are: the cell's particles are placed at
  // random; its bands end at the cell's edges, where the first band meets the last.
  const std::vector<Vec2>& centres = *placed;
  const double spacing = side / std::sqrt(static_cast<double>(std::max<std::size_t>(centres.size(), 1)));
  for (std::size_t i : specimen::orderAlongSpace(centres, spacing)) out.particles.push_back(particleOf(recipe, made, i, centres[i]));
  out.edges = Eigen::Matrix2d::Identity() * side;
  out.solidArea = plan.solidArea;
  return out;
}

}  // namespace grainlab
