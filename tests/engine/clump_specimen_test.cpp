// Clump assemblies and clump scenes: the paper's grading by long axis, the hexagons' length
// over width, the bedding angle, placement without overlap; scene keys refused by field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "../support/refused_field.hpp"
#include "grainlab/errors.hpp"
#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"
#include "grainlab/specimen.hpp"
#include "grainlab/world.hpp"

namespace grainlab {
namespace {

using nlohmann::json;

SpecimenRecipe clumps(int discs, SpecimenRecipe::Orientation orientation, double beddingDeg = 0) {
  SpecimenRecipe r;
  r.shape = SpecimenRecipe::Shape::Clump;
  r.clumpDiscs = discs;
  r.aspectRatio = std::sqrt(3.0);
  r.orientation = orientation;
  r.beddingAngle = radians(beddingDeg);
  r.specimenDiameter = 0.06;
  return r;
}

// World-frame member discs of a generated clump.
std::vector<ClumpMember> worldMembers(const ParticleSpec& p) {
  Vec2 centroid;
  makeClump(p.members, &centroid);
  std::vector<ClumpMember> out;
  for (const ClumpMember& m : p.members) out.push_back({p.position + rotate(m.centre, p.angle), m.radius});
  return out;
}

TEST(ClumpSpecimen, LongAxesWidthAndBeddingAreTheRecipes) {
  for (int n : {2, 3, 5}) {
    const Specimen s = generateSpecimen(clumps(n, SpecimenRecipe::Orientation::Bedding, 30), 3);
    ASSERT_GT(s.specimenCount, 50);
    std::map<double, int> bySize;
    for (int k = 0; k < s.specimenCount; ++k) {
      const ParticleSpec& p = s.particles[static_cast<size_t>(k)];
      ASSERT_EQ(p.shape, ShapeKind::Clump);
      ASSERT_EQ(static_cast<int>(p.members.size()), n);
      EXPECT_EQ(p.angle, radians(30.0));
      const std::vector<ClumpMember> w = worldMembers(p);
      // The long axis: from the first disc's far edge to the last's, along the bedding angle.
      const Vec2 axis = w.back().centre - w.front().centre;
      EXPECT_NEAR(std::atan2(axis.y(), axis.x()), radians(30.0), 1e-12);
      const double length = axis.norm() + 2 * w.front().radius;
      EXPECT_NEAR(length / (2 * w.front().radius), std::sqrt(3.0), 1e-12);
      ++bySize[std::round(length * 1e7) / 1e7];
    }
    // The paper's three sizes, by count in the solved fractions (D60/D10 = 1.35 and
    // D30²/(D10·D60) = 1.2 are checked on the fractions by SpecimenGrading's tests).
    ASSERT_EQ(bySize.size(), 3u);
    EXPECT_NEAR(bySize.begin()->first, 0.0045, 1e-9);
    EXPECT_NEAR(bySize.rbegin()->first, 0.007, 1e-9);
  }
}

TEST(ClumpSpecimen, NoMembersOfTwoClumpsOverlapAndRandomOrientationsSpread) {
  const Specimen s = generateSpecimen(clumps(3, SpecimenRecipe::Orientation::Random), 5);
  std::vector<std::vector<ClumpMember>> all;
  double meanCos2 = 0, meanSin2 = 0;
  for (int k = 0; k < s.specimenCount; ++k) {
    const ParticleSpec& p = s.particles[static_cast<size_t>(k)];
    all.push_back(worldMembers(p));
    meanCos2 += std::cos(2 * p.angle) / s.specimenCount;
    meanSin2 += std::sin(2 * p.angle) / s.specimenCount;
  }
  for (size_t a = 0; a < all.size(); ++a) {
    for (size_t b = a + 1; b < all.size(); ++b) {
      for (const ClumpMember& ma : all[a]) {
        for (const ClumpMember& mb : all[b]) {
          ASSERT_GE((ma.centre - mb.centre).norm(), ma.radius + mb.radius) << a << " " << b;
        }
      }
    }
  }
  // Uniform orientations: the second harmonic's mean is within a few 1/√N of zero.
  EXPECT_LT(std::hypot(meanCos2, meanSin2), 4 / std::sqrt(static_cast<double>(s.specimenCount)));
}

TEST(ClumpSpecimen, VoidRatioCountsTheUnionsArea) {
  // The World's area of a generated clump is its union's, less than its discs' sum.
  const Specimen s = generateSpecimen(clumps(3, SpecimenRecipe::Orientation::Random), 2);
  World world(Material{});
  const ParticleSpec& p = s.particles.front();
  world.addParticle(p);
  double discs = 0;
  for (const ClumpMember& m : p.members) discs += discArea(m.radius);
  EXPECT_LT(world.area(0), 0.8 * discs);
  EXPECT_NEAR(world.area(0), makeClump(p.members).area, 0);
}

std::string fieldOf(const json& j) { return testing::refusedField(j); }

json oneClump() {
  return json::parse(R"({"particles": [{"shape": "clump", "position": [0, 0],
      "members": [{"position": [-0.001, 0], "radius": 0.0015}, {"position": [0.001, 0], "radius": 0.0015}]}]})");
}

TEST(ClumpScene, KeysAreRefusedByField) {
  EXPECT_EQ(fieldOf(oneClump()), "(accepted)");
  json j = oneClump();
  j["particles"][0]["members"][1]["radius"] = 0;
  EXPECT_EQ(fieldOf(j), "particles[0].members[1].radius");
  j = oneClump();
  j["particles"][0]["members"][1].erase("radius");
  EXPECT_EQ(fieldOf(j), "particles[0].members[1].radius");
  j = oneClump();
  j["particles"][0]["members"][1]["position"] = {0.01, 0};  // apart from the other
  EXPECT_EQ(fieldOf(j), "particles[0].members");
  j = oneClump();
  j["particles"][0]["members"] = json::array();
  EXPECT_EQ(fieldOf(j), "particles[0].members");
  j = oneClump();
  j["particles"][0]["members"][0]["centre"] = {0, 0};  // unknown key
  EXPECT_EQ(fieldOf(j), "particles[0].members[0].centre");
  j = oneClump();
  j["solver"] = {{"engine", "box2d"}};
  EXPECT_EQ(fieldOf(j), "particles[0].shape");

  j = oneClump();
  j["particles"].push_back({{"shape", "polygon"}, {"vertices", {{0, 0}, {0.001, 0}, {0, 0.001}}}, {"position", {0.01, 0}}});
  EXPECT_EQ(fieldOf(j), "particles[0].shape");

  json a = presetScene("clump-random-quick");
  a["assembly"]["clump_discs"] = 1;
  EXPECT_EQ(fieldOf(a), "assembly.clump_discs");
  a = presetScene("clump-random-quick");
  a["assembly"]["clump_discs"] = 2;
  a["assembly"]["aspect_ratio"] = 2.5;  // two discs that long would not overlap
  EXPECT_EQ(fieldOf(a), "assembly.aspect_ratio");
  a = presetScene("clump-bedding-30-quick");
  a["solver"]["engine"] = "box2d";
  EXPECT_EQ(fieldOf(a), "assembly.shape");
}

TEST(ClumpScene, PresetsAreTheHexagonsSizesAsThreeDiscClumps) {
  for (const char* name : {"clump-random", "clump-random-quick", "clump-bedding-30", "clump-bedding-30-quick"}) {
    const Scene s = parseScene(presetScene(name));
    ASSERT_TRUE(s.assembly.has_value()) << name;
    EXPECT_EQ(s.assembly->shape, SpecimenRecipe::Shape::Clump);
    EXPECT_EQ(s.assembly->clumpDiscs, 3);
    // The hexagon of the elongated presets spans its long axis over √3 of its width.
    EXPECT_NEAR(s.assembly->aspectRatio, std::sqrt(3.0), 1e-12);
    const Scene hexagons = parseScene(presetScene(std::string(name).replace(0, 5, "elongated")));
    EXPECT_EQ(s.assembly->longAxes, hexagons.assembly->longAxes);
    EXPECT_EQ(s.assembly->orientation, hexagons.assembly->orientation);
    EXPECT_EQ(s.assembly->beddingAngle, hexagons.assembly->beddingAngle);
    EXPECT_EQ(s.assembly->specimenDiameter, hexagons.assembly->specimenDiameter);
  }
}

}  // namespace
}  // namespace grainlab
