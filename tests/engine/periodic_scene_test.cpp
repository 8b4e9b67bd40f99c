// A periodic cell in scene JSON: what it accepts, and each refusal naming its field (the
// box2d engine, walls, clumps, gravity, a cell without a size or with two, the ring's own
// stages, a rotation driven as the ring's).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "grainlab/presets.hpp"
#include "grainlab/scene.hpp"

#include "../support/refused_field.hpp"

namespace grainlab {
namespace {

using nlohmann::json;
using grainlab::testing::refusedField;

json cellOfDiscs() {
  return {{"assembly", {{"shape", "disc"}, {"particle_count", 40}}},
          {"boundary", {{"type", "periodic"}}},
          {"stages", json::array({{{"type", "isotropic"}, {"pressure", 1e5}},
                                  {{"type", "biaxial"}, {"pressure", 1e5}, {"lateral", "constant_volume"}},
                                  {{"type", "simple_shear"}, {"shear_rate", 1.0}}})}};
}

json explicitCell() {
  return {{"particles", json::array({{{"radius", 0.001}, {"position", {0.002, 0.002}}}})},
          {"boundary", {{"type", "periodic"}, {"size", {0.01, 0.02}}, {"rate_cap", 5.0}}}};
}

TEST(PeriodicScene, ParsesTheCellAndItsStages) {
  const Scene scene = parseScene(cellOfDiscs());
  EXPECT_EQ(scene.boundary.type, BoundarySpec::Type::Periodic);
  EXPECT_FALSE(scene.boundary.cellSize.has_value());
  EXPECT_EQ(scene.boundary.rateCap, 3.0);
  ASSERT_EQ(scene.stages.size(), 3u);
  EXPECT_EQ(scene.stages[1].lateral, StageSpec::Lateral::ConstantVolume);
  const Scene sized = parseScene(explicitCell());
  ASSERT_TRUE(sized.boundary.cellSize.has_value());
  EXPECT_EQ(sized.boundary.cellSize->y(), 0.02);
  EXPECT_EQ(sized.boundary.rateCap, 5.0);
}

TEST(PeriodicScene, RefusesWhatACellCannotHoldByField) {
  json box2d = cellOfDiscs();
  box2d["solver"] = {{"engine", "box2d"}};
  EXPECT_EQ(refusedField(box2d), "boundary.type");
  json walls = explicitCell();
  walls["walls"] = json::array({{{"point", {0, 0}}, {"normal", {0, 1}}}});
  EXPECT_EQ(refusedField(walls), "walls");
  json clumpAssembly = cellOfDiscs();
  clumpAssembly["assembly"] = {{"shape", "clump"}, {"particle_count", 20}};
  EXPECT_EQ(refusedField(clumpAssembly), "assembly.shape");
  json clump = explicitCell();
  clump["particles"].push_back({{"shape", "clump"},
                                {"members", json::array({{{"position", {-0.0008, 0}}, {"radius", 0.001}},
                                                         {{"position", {0.0008, 0}}, {"radius", 0.001}}})}});
  EXPECT_EQ(refusedField(clump), "particles[1].shape");
  json gravity = explicitCell();
  gravity["gravity"] = {0, -9.81};
  EXPECT_EQ(refusedField(gravity), "gravity");
  json unsized = explicitCell();
  unsized["boundary"].erase("size");
  EXPECT_EQ(refusedField(unsized), "boundary.size");
  json twice = cellOfDiscs();
  twice["boundary"]["size"] = {0.01, 0.01};
  EXPECT_EQ(refusedField(twice), "boundary.size");
  json flat = explicitCell();
  flat["boundary"]["size"] = {0.01, 0};
  EXPECT_EQ(refusedField(flat), "boundary.size");
  json cap = explicitCell();
  cap["boundary"]["rate_cap"] = 0;
  EXPECT_EQ(refusedField(cap), "boundary.rate_cap");
  json compaction = cellOfDiscs();
  compaction["stages"][1] = {{"type", "compaction"}};
  EXPECT_EQ(refusedField(compaction), "stages[1].type");
  json cyclic = cellOfDiscs();
  cyclic["stages"][0] = {{"type", "cyclic"}, {"strain_amplitude", 0.01}, {"cycles", 1}};
  EXPECT_EQ(refusedField(cyclic), "stages[0].type");
  // Keys of the cell are the cell's: a membrane has no size.
  json ring = cellOfDiscs();
  ring["boundary"] = {{"type", "membrane"}, {"size", {0.01, 0.01}}};
  EXPECT_EQ(refusedField(ring), "boundary.size");
}

json cellRotation() {
  json scene = cellOfDiscs();
  scene["stages"][2] = {{"type", "rotation"}, {"mean_stress", 2e5}, {"deviatoric_stress", 5e4},
                        {"initial_direction_deg", 45}, {"rotation_rate_deg_per_s", 300}, {"duration", 0.2}};
  return scene;
}

// The cell's rotation is stress-controlled: it holds p and q while the stress axes turn.
TEST(PeriodicScene, ParsesTheCellsStressControlledRotation) {
  const Scene scene = parseScene(cellRotation());
  const StageSpec& s = scene.stages[2];
  EXPECT_EQ(s.type, StageSpec::Type::Rotation);
  EXPECT_EQ(s.pressure, 2e5);
  EXPECT_EQ(s.deviatoricStress, 5e4);
  EXPECT_EQ(s.deviatoricStrainRate, 0.0);
  EXPECT_EQ(s.initialDirectionDeg, 45.0);
  EXPECT_EQ(s.rotationRateDeg, 300.0);
  EXPECT_EQ(s.duration, 0.2);
}

TEST(PeriodicScene, RefusesARotationDrivenAsTheRingsByField) {
  json strainDriven = cellRotation();
  strainDriven["stages"][2]["deviatoric_strain_rate"] = 1.0;
  EXPECT_EQ(refusedField(strainDriven), "stages[2].deviatoric_strain_rate");
  json noQ = cellRotation();
  noQ["stages"][2].erase("deviatoric_stress");
  EXPECT_EQ(refusedField(noQ), "stages[2].deviatoric_stress");
  json tension = cellRotation();  // q = p would put σ2 at zero
  tension["stages"][2]["deviatoric_stress"] = 2e5;
  EXPECT_EQ(refusedField(tension), "stages[2].deviatoric_stress");
  json noSpeed = cellRotation();
  noSpeed["stages"][2].erase("duration");
  EXPECT_EQ(refusedField(noSpeed), "stages[2].duration");
  // The ring's rotation keeps its own drive: q is the cell's key.
  json ring = cellRotation();
  ring["boundary"] = {{"type", "membrane"}};
  EXPECT_EQ(refusedField(ring), "stages[2].deviatoric_strain_rate");
  ring["stages"][2]["deviatoric_strain_rate"] = 1.0;
  EXPECT_EQ(refusedField(ring), "stages[2].deviatoric_stress");
}

TEST(PeriodicScene, PresetsAreCellScenes) {
  for (const char* name : {"periodic-biaxial-circular", "periodic-biaxial-circular-quick"}) {
    const Scene scene = parseScene(presetScene(name));
    EXPECT_EQ(scene.boundary.type, BoundarySpec::Type::Periodic) << name;
    EXPECT_EQ(scene.stages.back().type, StageSpec::Type::Biaxial) << name;
  }
  for (const char* name : {"periodic-rotation-circular", "periodic-rotation-circular-quick"}) {
    const Scene scene = parseScene(presetScene(name));
    EXPECT_EQ(scene.boundary.type, BoundarySpec::Type::Periodic) << name;
    EXPECT_EQ(scene.stages.back().type, StageSpec::Type::Rotation) << name;
    EXPECT_GT(scene.stages.back().deviatoricStress, 0) << name;
  }
}

}  // namespace
}  // namespace grainlab
