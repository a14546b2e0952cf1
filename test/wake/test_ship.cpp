// Ship geometry and ship motion.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "ship_lrm/wake/ship_geometry.hpp"
#include "ship_lrm/wake/ship_motion.hpp"
#include "temp_path.hpp"

using namespace ship_lrm::wake;
using ship_lrm::Vec3;
namespace fs = std::filesystem;

namespace {
std::string temp(const std::string& name) { return ship_lrm::test::temp_path("ship_lrm_test_ship", name); }
}  // namespace

TEST(ShipGeometry, NatoGdProportionsAndScale) {
  const auto full = make_natogd(1.0);
  EXPECT_NEAR(full->datum().length, 150.0, 1e-9);  // thesis table 6.3: l = 150 m
  const auto model = make_natogd(1.0 / 50);
  EXPECT_NEAR(model->datum().length, 3.0, 1e-9);  // thesis table 6.2: l = 3 m
  EXPECT_NEAR(model->datum().waterline, full->datum().waterline / 50, 1e-12);
  EXPECT_GT(full->datum().stem_x, 100.0);
  // inside the hangar, just above the flight deck behind it, inside the hull below the deck
  EXPECT_TRUE(full->inside(Vec3(5, 0, -3)));
  EXPECT_FALSE(full->inside(Vec3(-5, 0, -3)));
  EXPECT_TRUE(full->inside(Vec3(-5, 0, 2)));
  EXPECT_FALSE(full->inside(Vec3(5, 0, -8)));  // above the hangar roof
  // the hangar door is a vertical face at x = 0: the distance just behind it is the gap
  EXPECT_NEAR(full->signed_distance(Vec3(-0.5, 0, -3)), 0.5, 1e-9);
  EXPECT_NEAR(full->signed_distance(Vec3(0.5, 0, -3)), -0.5, 1e-9);
}

TEST(ShipGeometry, Sfs2Dimensions) {
  const auto s = make_sfs2(1.0);
  EXPECT_NEAR(s->datum().length, 138.68, 1e-9);
  EXPECT_NEAR(s->datum().beam, 13.72, 1e-9);
}

TEST(ShipGeometry, RejectsBadBlocks) {
  auto b = BlockShip::box("twisted", 0, 1, 0, 1, 0, 1);
  b.corners[6] += Vec3(0.3, 0.0, 0.2);  // top face no longer planar
  EXPECT_THROW(BlockShip("bad", {b}, 0.5), GeometryError);
  EXPECT_THROW(BlockShip("none", {}, 0.5), GeometryError);
  EXPECT_THROW(make_ship("frigate", "full"), GeometryError);
  EXPECT_THROW(make_ship("natogd", "half"), GeometryError);
}

TEST(ShipGeometry, StlRoundTripMatchesTheBlocks) {
  // one block exported and read back: the same inside test at random points
  const BlockShip ship("box", {BlockShip::box("b", -2, 3, -1, 1, -1.5, 0.5)}, 0.5);
  const std::string path = temp("box.stl");
  write_stl(path, ship.mesh());
  const StlShip stl(path);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-3, 4), y(-2, 2), z(-2.5, 1.5);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(x(rng), y(rng), z(rng));
    ASSERT_EQ(stl.inside(p), ship.inside(p)) << p.transpose();
    ASSERT_NEAR(stl.signed_distance(p), ship.signed_distance(p), std::abs(ship.signed_distance(p)) < 0 ? 1e-5 : 1.0);
  }
  EXPECT_NEAR(stl.datum().length, 5.0, 1e-6);
}

TEST(ShipGeometry, StlOfTheBlockShipsReadsBack) {
  // `ship_lrm wake --mesh` exports a block ship as overlapping closed boxes (edges shared between
  // parts, volumes counted twice where they overlap); read back, inside is their union: the same
  // inside test as the blocks, and outside a distance consistent with theirs. Also with every normal
  // turned in.
  for (const auto& ship : {make_natogd(1.0), make_sfs2(1.0)}) {
    std::vector<Triangle> flipped = ship->mesh();
    for (auto& t : flipped) std::swap(t.v[1], t.v[2]);
    for (const auto& [name, tris] : {std::make_pair(std::string("out"), ship->mesh()), std::make_pair(std::string("in"), flipped)}) {
      const std::string path = temp(ship->name() + "_" + name + ".stl");
      write_stl(path, tris);
      const StlShip stl(path);
      Vec3 lo = Vec3::Constant(1e300), hi = -lo;
      for (const auto& t : tris)
        for (const auto& v : t.v) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> u(-0.05, 1.05);
      int inside = 0;
      for (int k = 0; k < 4000; ++k) {
        const Vec3 p = lo + (hi - lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
        ASSERT_EQ(stl.inside(p), ship->inside(p)) << ship->name() << " " << name << ": " << p.transpose();
        inside += ship->inside(p);
        const double d = ship->signed_distance(p);
        // outside, the blocks' distance is the largest over their faces' planes: the Euclidean one
        // where the nearest point lies on a face, less near edges and corners (a box's: at least 1 / sqrt(3) of it)
        if (d > 0) {
          ASSERT_GE(stl.signed_distance(p), d - 1e-4) << p.transpose();
          ASSERT_LE(stl.signed_distance(p), std::sqrt(3.0) * d + 1e-4) << p.transpose();
        }
      }
      EXPECT_GT(inside, 200) << ship->name();  // the samples do reach into the ship
      EXPECT_NEAR(stl.datum().length, ship->datum().length, 1e-4);
    }
  }
}

TEST(ShipGeometry, StlAsciiAndErrors) {
  const std::string ascii = temp("tet.stl");
  {
    std::ofstream o(ascii);
    const char* tris[4][3] = {
        {"0 0 0", "0 1 0", "1 0 0"}, {"0 0 0", "1 0 0", "0 0 1"}, {"0 0 0", "0 0 1", "0 1 0"}, {"1 0 0", "0 1 0", "0 0 1"}};
    o << "solid tet\n";
    for (auto& t : tris)
      o << " facet normal 0 0 0\n  outer loop\n   vertex " << t[0] << "\n   vertex " << t[1] << "\n   vertex " << t[2]
        << "\n  endloop\n endfacet\n";
    o << "endsolid tet\n";
  }
  const StlShip tet(ascii);
  EXPECT_TRUE(tet.inside(Vec3(0.1, 0.1, 0.1)));
  EXPECT_FALSE(tet.inside(Vec3(0.5, 0.5, 0.5)));
  // a hole: drop the last facet
  const std::string holed = temp("holed.stl");
  {
    auto t = read_stl(ascii);
    t.pop_back();
    write_stl(holed, t);
  }
  try {
    StlShip s(holed);
    FAIL() << "an open mesh was accepted";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find("not a closed"), std::string::npos) << e.what();
  }
  // one triangle turned against its neighbours
  const std::string flipped = temp("flipped.stl");
  {
    auto t = read_stl(ascii);
    std::swap(t[0].v[1], t[0].v[2]);
    write_stl(flipped, t);
  }
  EXPECT_THROW(StlShip{flipped}, GeometryError);
  const std::string junk = temp("junk.stl");
  std::ofstream(junk) << "this is not an stl file";
  EXPECT_THROW(StlShip{junk}, GeometryError);
  EXPECT_THROW(StlShip{temp("missing.stl")}, GeometryError);
}

TEST(ShipMotion, PitchBowUpLiftsTheBowAndVelocityIsTheDerivative) {
  SinusoidalMotion::Params p;
  p.frequency = 0.2;
  p.heave = 1.0;
  p.roll = 0.05;
  p.pitch = 0.03;
  p.roll_phase = 0.7;
  const Vec3 centre(50, 0, 6);
  const SinusoidalMotion m("test", p, centre);
  const Vec3 bow(120, 3, 0);
  // at a quarter period the pitch is at its bow-up maximum: the bow rises (z decreases)
  const double tq = 0.25 / p.frequency;
  EXPECT_GT(m.pose(tq).pitch, 0.0);
  SinusoidalMotion::Params only_pitch;
  only_pitch.frequency = 0.2;
  only_pitch.pitch = 0.03;
  const SinusoidalMotion pitch("pitch", only_pitch, centre);
  EXPECT_LT(pitch.position(bow, tq).z(), bow.z() - 0.03 * 60);
  // velocity() is the time derivative of position() for any body point
  for (double t : {0.0, 0.3, 1.7, 4.1}) {
    const double h = 1e-5;
    const Vec3 fd = (m.position(bow, t + h) - m.position(bow, t - h)) / (2 * h);
    EXPECT_LT((fd - m.velocity(bow, t)).norm(), 1e-6) << t;
  }
  EXPECT_THROW(SinusoidalMotion("bad", SinusoidalMotion::Params{0.0}, centre), MotionError);
}

TEST(ShipMotion, FroudeScaledCasesAndTimeSeriesFile) {
  const auto model = make_motion("pitch", 1.0 / 50, Vec3::Zero());
  const auto full = make_motion("pitch", 1.0, Vec3::Zero());
  const auto* pm = dynamic_cast<const SinusoidalMotion*>(model.get());
  const auto* pf = dynamic_cast<const SinusoidalMotion*>(full.get());
  ASSERT_TRUE(pm && pf);
  EXPECT_NEAR(pm->params().frequency, 1.0, 1e-12);  // NRC case: 1 Hz on the 1/50 model
  EXPECT_NEAR(pf->params().frequency, 1.0 / std::sqrt(50.0), 1e-12);
  EXPECT_NEAR(pm->params().pitch, 5.0 * M_PI / 180, 1e-12);
  const auto heave = make_motion("heave", 1.0, Vec3::Zero());
  EXPECT_NEAR(dynamic_cast<const SinusoidalMotion&>(*heave).params().heave, 0.04 * 50, 1e-12);  // 0.04 m on the model
  const std::string csv = temp("motion.csv");
  std::ofstream(csv) << "time_s,heave_m,roll_deg,pitch_deg\n0,0,0,0\n1,1,2,4\n3,-1,0,0\n";
  const TableMotion tm(csv, Vec3::Zero());
  EXPECT_NEAR(tm.pose(0.5).heave, 0.5, 1e-12);
  EXPECT_NEAR(tm.pose(0.5).pitch, 2.0 * M_PI / 180, 1e-12);
  EXPECT_NEAR(tm.pose(2.0).heave_rate, -1.0, 1e-12);
  EXPECT_NEAR(tm.pose(10.0).heave, -1.0, 1e-12);  // held after the end
  std::ofstream(csv) << "t,h,r,p\n0,0,0,0\n1,0,0,0\n";
  EXPECT_THROW(TableMotion(csv, Vec3::Zero()), MotionError);
  std::ofstream(csv) << "time_s,heave_m,roll_deg,pitch_deg\n0,0,0,0\n0,1,0,0\n";
  EXPECT_THROW(TableMotion(csv, Vec3::Zero()), MotionError);
  std::ofstream(csv) << "time_s,heave_m,roll_deg,pitch_deg\n0,0,0,0\n1,nan,0,0\n";
  EXPECT_THROW(TableMotion(csv, Vec3::Zero()), MotionError);
  std::ofstream(csv) << "time_s,heave_m,roll_deg,pitch_deg\n0,0,0,0\n1,0,0,0,7\n";  // a fifth column was ignored
  EXPECT_THROW(TableMotion(csv, Vec3::Zero()), MotionError);
  std::ofstream(csv) << "time_s,heave_m,roll_deg,pitch_deg\n0;0;0;0\n1;0;0;0\n";  // any separator was taken
  EXPECT_THROW(TableMotion(csv, Vec3::Zero()), MotionError);
  std::ofstream(csv) << "time_s,heave_m,roll_deg,pitch_deg\n0, 0, 0, 0\n1, 1, 0, 0 \r\n";  // spaces and CRLF are fine
  EXPECT_NEAR(TableMotion(csv, Vec3::Zero()).pose(0.5).heave, 0.5, 1e-12);
  EXPECT_THROW(make_motion("wobble", 1.0, Vec3::Zero()), MotionError);
}
