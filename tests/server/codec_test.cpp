// Frames, shapes, series rows and paths: the formats clients decode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "frame_codec.hpp"
#include "grainlab/periodic_cell.hpp"
#include "grainlab/output_writer.hpp"
#include "grainlab/run.hpp"
#include "grainlab/world.hpp"
#include "series_format.hpp"
#include "static_files.hpp"

namespace grainlab::server {
namespace {

TEST(FrameCodec, EncodesParticlesAndCompressedContacts) {
  World world(Material{});
  ParticleSpec p;
  p.radius = 0.002;
  world.addParticle(p);
  p.position = Vec2(0.0039, 0);  // overlapping the first: one contact in compression
  world.addParticle(p);
  ParticleSpec poly;
  poly.shape = ShapeKind::Polygon;
  poly.vertices = {Vec2(0, 0), Vec2(0.002, 0), Vec2(0.001, 0.002)};
  poly.position = Vec2(0.02, 0.02);
  world.addParticle(poly);
  world.step();

  std::vector<ContactRecord> scratch;
  const auto bytes = encodeFrame(world, scratch);
  ASSERT_EQ(bytes.size(), frame::kHeaderBytes + 3 * frame::kParticleBytes + 1 * frame::kContactBytes);
  const auto f = decodeFrame(bytes);
  EXPECT_EQ(f.step, 1);
  EXPECT_DOUBLE_EQ(f.time, world.time());
  ASSERT_EQ(f.particles.size(), 12u);
  EXPECT_FLOAT_EQ(f.particles[4], static_cast<float>(world.positions()[1].x()));
  ASSERT_EQ(f.pairs, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_GT(f.forces[0], 0);
  EXPECT_FLOAT_EQ(f.maxContactForce, f.forces[0]);
  EXPECT_GT(f.particles[3], 0);   // particle 0 feels the contact
  EXPECT_EQ(f.particles[11], 0);  // the polygon touches nothing

  auto shapes = shapesMessage(world);
  EXPECT_EQ(shapes["type"], "shapes");
  EXPECT_EQ(shapes["count"], 3);
  EXPECT_DOUBLE_EQ(shapes["shapes"][0]["disc"].get<double>(), 0.002);
  EXPECT_EQ(shapes["shapes"][2]["polygon"].size(), 6u);

  EXPECT_THROW(decodeFrame("nope"), std::invalid_argument);
  EXPECT_THROW(decodeFrame(bytes.substr(0, bytes.size() - 1)), std::invalid_argument);
}

TEST(FrameCodec, ARingRunsFrameHasTheVersion1HeaderAndNoCell) {
  World world(Material{});
  ParticleSpec p;
  p.radius = 0.002;
  world.addParticle(p);
  std::vector<ContactRecord> scratch;
  const auto bytes = encodeFrame(world, scratch);
  std::uint16_t header;
  std::memcpy(&header, bytes.data() + 6, 2);
  EXPECT_EQ(header, frame::kHeaderBytes);  // byte for byte what clients before the cell read
  EXPECT_FALSE(decodeFrame(bytes).cell.has_value());
}

TEST(FrameCodec, ACellRunsFrameCarriesTheCellsEdgesAfterTheVersion1Header) {
  World world(Material{});
  Eigen::Matrix2d h;
  h << 0.03, 0.012, 0.001, 0.025;  // edges (0.03, 0.001) and (0.012, 0.025): tilted, not square
  world.setPeriodicCell(h);
  ParticleSpec p;
  p.radius = 0.002;
  p.position = Vec2(0.001, 0.01);  // crosses the left edge
  world.addParticle(p);
  p.position = Vec2(0.015, 0.012);
  world.addParticle(p);
  // Shear the cell so the edges sent are the current ones, not the ones it was built with.
  Eigen::Matrix2d L;
  L << 0, 2.0, 0, 0;
  world.setCellVelocityGradient(L);
  for (int k = 0; k < 50; ++k) world.step();
  const auto& now = world.periodicCell()->edges();
  ASSERT_GT(std::abs(now(0, 1) - h(0, 1)), 1e-6);

  std::vector<ContactRecord> scratch;
  const auto bytes = encodeFrame(world, scratch);
  ASSERT_EQ(bytes.size(), frame::kCellHeaderBytes + 2 * frame::kParticleBytes);
  const auto f = decodeFrame(bytes);
  ASSERT_TRUE(f.cell.has_value());
  EXPECT_EQ((*f.cell)[0], static_cast<float>(now(0, 0)));  // h1 x
  EXPECT_EQ((*f.cell)[1], static_cast<float>(now(1, 0)));  // h1 y
  EXPECT_EQ((*f.cell)[2], static_cast<float>(now(0, 1)));  // h2 x
  EXPECT_EQ((*f.cell)[3], static_cast<float>(now(1, 1)));  // h2 y
  // A reader of version 1 that knows nothing of the cell finds the particles where the header
  // size says they start.
  std::uint16_t header;
  std::memcpy(&header, bytes.data() + 6, 2);
  float x1;
  std::memcpy(&x1, bytes.data() + header + frame::kParticleBytes, 4);
  EXPECT_EQ(x1, static_cast<float>(world.positions()[1].x()));
  EXPECT_EQ(f.particles[4], x1);
  // A header claiming to be shorter than version 1's is refused, not read past.
  auto broken = bytes;
  const std::uint16_t tiny = 20;
  std::memcpy(broken.data() + 6, &tiny, 2);
  EXPECT_THROW(decodeFrame(broken), std::invalid_argument);
}

TEST(FrameCodec, AClumpsShapeIsItsDiscsAboutItsCentroid) {
  World world(Material{});
  ParticleSpec clump;
  clump.shape = ShapeKind::Clump;
  // Unequal discs: the centroid is off the reference point, nearer the bigger disc.
  clump.members = {{Vec2(0, 0), 0.002}, {Vec2(0.0025, 0), 0.001}};
  clump.position = Vec2(0.01, 0.02);
  world.addParticle(clump);
  const auto shapes = shapesMessage(world);
  const auto& m = shapes["shapes"][0]["clump"];
  ASSERT_EQ(m.size(), 6u);
  EXPECT_DOUBLE_EQ(m[2].get<double>(), 0.002);
  EXPECT_DOUBLE_EQ(m[5].get<double>(), 0.001);
  // About the centroid: the members' centres in the world are the reference point's offsets.
  EXPECT_NEAR(world.positions()[0].x() + m[0].get<double>(), 0.01, 1e-15);
  EXPECT_NEAR(world.positions()[0].x() + m[3].get<double>(), 0.0125, 1e-15);
  EXPECT_GT(world.positions()[0].x(), 0.01);
  EXPECT_LT(world.positions()[0].x(), 0.0115);
}

TEST(SeriesFormat, CsvIsTheClisAndJsonHasNullForNotMeasured) {
  SeriesFormat format;
  SampleRecord s;
  s.step = 120;
  s.time = 0.25;
  s.stage = "shearing";
  const auto& columns = seriesColumns();
  for (std::size_t c = 0; c < columns.size(); ++c) s.values.push_back(c == 5 ? NAN : 0.1 * c);
  s.values[0] = 120;
  s.values[1] = 0.25;
  Sample engine;
  engine.step = s.step;
  engine.time = s.time;
  engine.stage = s.stage;
  engine.values = s.values;
  EXPECT_EQ(format.csvRow(s), formatSeriesRow(engine) + "\n");
  // The header the API serves is the contract's (contracts.md: these columns at least, each
  // once), in seriesColumns() order: checked against the contract's own list, not against the
  // function that builds it.
  const std::string header = format.csvHeader();
  ASSERT_EQ(header.back(), '\n');
  std::vector<std::string> fields;
  for (std::size_t at = 0, comma; at < header.size() - 1; at = comma + 1) {
    comma = std::min(header.find(',', at), header.size() - 1);
    fields.push_back(header.substr(at, comma - at));
  }
  EXPECT_EQ(fields, columns);
  for (const char* contract :
       {"step", "time", "stage", "axial_strain", "lateral_strain", "volumetric_strain", "sigma11", "sigma22",
        "sigma12", "sigma21", "p", "q", "phi_mob_deg", "void_ratio", "coordination", "contacts", "a_c",
        "theta_c_deg", "a_n", "theta_n_deg", "a_t", "theta_t_deg", "a_w", "a_ln", "theta_ln_deg", "a_lt",
        "theta_lt_deg", "theta_sigma_macro_deg", "theta_sigma_micro_deg", "theta_sigma_eq10_deg",
        "theta_sigma_eq11_deg", "omega_macro_deg", "omega_micro_deg", "kinetic_energy"}) {
    EXPECT_EQ(std::count(fields.begin(), fields.end(), contract), 1) << contract;
  }
  EXPECT_EQ(std::vector<std::string>(fields.begin(), fields.begin() + 3),
            (std::vector<std::string>{"step", "time", "stage"}));
  const auto row = format.rowObject(s);
  EXPECT_EQ(row["step"], 120);
  EXPECT_EQ(row["stage"], "shearing");
  EXPECT_TRUE(row[columns[5]].is_null());
  EXPECT_DOUBLE_EQ(row[columns[6]].get<double>(), 0.6000000000000001);
  EXPECT_EQ(format.rowArray(s).size(), columns.size());
}

TEST(StaticFiles, PercentDecodingAndTypes) {
  EXPECT_EQ(*percentDecode("/a%20b%2Fc"), "/a b/c");
  EXPECT_FALSE(percentDecode("/%2"));
  EXPECT_FALSE(percentDecode("/%g0"));
  EXPECT_FALSE(percentDecode("/%00"));
  EXPECT_EQ(mimeType("a/b/index.HTML"), "text/html; charset=utf-8");
  EXPECT_EQ(mimeType("x.mjs"), "text/javascript; charset=utf-8");
  EXPECT_EQ(mimeType("x.svg"), "image/svg+xml");
  EXPECT_EQ(mimeType("x.wasm"), "application/wasm");
  EXPECT_EQ(mimeType("Makefile"), "application/octet-stream");
}

}  // namespace
}  // namespace grainlab::server
