// Parameter files: the shipped Bo 105 file loads; a missing or out-of-range value is reported with
// its field and file; the airfoil table follows its published characteristics.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "ship_lrm/flight/controls.hpp"
#include "ship_lrm/flight/parameters.hpp"

using namespace ship_lrm::flight;
namespace fs = std::filesystem;

namespace {
std::string read(const std::string& path) {
  std::ifstream f(path);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}
// A copy of the shipped files with one edit applied to bo105.yaml.
std::string edited_copy(const std::string& name, const std::string& pattern, const std::string& replacement) {
  const fs::path dir = fs::temp_directory_path() / ("ship_lrm_params_" + name);
  fs::create_directories(dir);
  const std::string cfg = default_config_directory();
  fs::copy_file(cfg + "/naca23012.yaml", dir / "naca23012.yaml", fs::copy_options::overwrite_existing);
  const std::string text = std::regex_replace(read(cfg + "/bo105.yaml"), std::regex(pattern), replacement);
  std::ofstream(dir / "bo105.yaml") << text;
  return (dir / "bo105.yaml").string();
}
std::string error_of(const std::string& path) {
  try {
    load_helicopter_parameters(path);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Parameters, ShippedBo105Loads) {
  const auto p = load_default_bo105();
  EXPECT_DOUBLE_EQ(p.mass.mass, 2200.0);  // thesis table 6.5
  EXPECT_DOUBLE_EQ(p.mass.ixz, 660.0);
  EXPECT_EQ(p.main_rotor.blades, 4);
  EXPECT_EQ(p.main_rotor.stations.size(), 8u);  // thesis 6.6: 8 stations, 7 elements
  EXPECT_DOUBLE_EQ(p.main_rotor.stations.front(), 0.223);
  EXPECT_NEAR(p.main_rotor.twist, -6.2 * M_PI / 180, 1e-12);
}

TEST(Parameters, MissingFieldNamesFieldAndFile) {
  const std::string path = edited_copy("missing", "  chord: 0.27[^\\n]*\\n", "");
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("main_rotor.chord"), std::string::npos) << msg;
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  EXPECT_NE(msg.find("missing"), std::string::npos) << msg;
}

TEST(Parameters, OutOfRangeNamesFieldAndFile) {
  const std::string path = edited_copy("range", "mass: 2200.0", "mass: -5");
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("mass.mass"), std::string::npos) << msg;
  EXPECT_NE(msg.find("out of range"), std::string::npos) << msg;
  EXPECT_NE(msg.find(path), std::string::npos) << msg;
  const std::string msg2 = error_of(edited_copy("rotation", "rotation: clockwise", "rotation: sideways"));
  EXPECT_NE(msg2.find("main_rotor.rotation"), std::string::npos) << msg2;
  const std::string msg3 = error_of(edited_copy("stations", "stations: \\[0.223, 0.42", "stations: [0.5, 0.42"));
  EXPECT_NE(msg3.find("main_rotor.stations"), std::string::npos) << msg3;
  const std::string msg4 = error_of(edited_copy("polar", "polar: naca23012.yaml", "polar: no_such_polar.yaml"));
  EXPECT_NE(msg4.find("no_such_polar.yaml"), std::string::npos) << msg4;
  EXPECT_NE(error_of("/nonexistent/bo105.yaml").find("cannot open"), std::string::npos);
}

TEST(Parameters, ControlsOutsideTravelAreRejected) {
  const auto p = load_default_bo105();
  PilotControls c;
  c.lateral = 120;
  try {
    map_controls(c, p.controls, true);
    FAIL() << "accepted 120 % lateral";
  } catch (const ControlError& e) {
    EXPECT_NE(std::string(e.what()).find("lateral"), std::string::npos);
  }
  c.lateral = 50;
  c.collective = std::nan("");
  EXPECT_THROW(map_controls(c, p.controls, true), ControlError);
}

TEST(AirfoilTable, Naca23012FollowsPublishedCharacteristics) {
  const auto p = load_default_bo105();
  const AirfoilTable& t = p.main_rotor.polar;
  const double deg = M_PI / 180;
  // Abbott & von Doenhoff app. IV, Re 6e6: zero lift at -1.2 deg, slope ~0.104/deg, cd_min ~0.006
  EXPECT_NEAR(t.lookup(-1.2 * deg, 0).cl, 0.0, 0.01);
  EXPECT_NEAR((t.lookup(6 * deg, 0).cl - t.lookup(0, 0).cl) / 6.0, 0.104, 0.002);
  EXPECT_NEAR(t.lookup(-1.2 * deg, 0).cd, 0.006, 0.0005);
  // Prandtl-Glauert at M 0.5: slope grows by 1/sqrt(1 - 0.25)
  const double s5 = (t.lookup(4 * deg, 0.5).cl - t.lookup(0, 0.5).cl) / 4.0;
  EXPECT_NEAR(s5, 0.104 / std::sqrt(0.75), 0.003);
  // stall: no more than cl_max 1.6 at low Mach; lift drops beyond
  double clmax = 0;
  for (int a = 0; a <= 30; ++a) clmax = std::max(clmax, t.lookup(a * deg, 0).cl);
  EXPECT_NEAR(clmax, 1.6, 0.02);
  // fully separated and reverse flow: flat plate (NACA TN 3361): cd ~2 at 90 deg, cl 0 at 180 deg
  EXPECT_NEAR(t.lookup(90 * deg, 0.2).cd, 1.96, 0.05);
  EXPECT_NEAR(t.lookup(M_PI, 0.2).cl, 0.0, 1e-6);
  // wrapping: 190 deg is -170 deg
  EXPECT_NEAR(t.lookup(190 * deg, 0.3).cl, t.lookup(-170 * deg, 0.3).cl, 1e-12);
  // drag rise above the drag-divergence Mach number
  EXPECT_GT(t.lookup(2 * deg, 0.9).cd, 5 * t.lookup(2 * deg, 0.5).cd);
}

// The landing gear is optional (a file without it flies, no contact is detected); where given, its
// four skid ends are the contact points, and a rear end ahead of the front one is refused by name.
TEST(Parameters, LandingGearIsOptionalAndChecked) {
  const auto p = load_default_bo105();
  ASSERT_EQ(p.landing_gear.contact_points.size(), 4u);
  for (const auto& c : p.landing_gear.contact_points) EXPECT_DOUBLE_EQ(c.z(), 1.2);  // below the cg (FRD)
  const auto without = load_helicopter_parameters(edited_copy("nogear", "landing_gear:(\\n[ #][^\\n]*)*\\n", ""));
  EXPECT_TRUE(without.landing_gear.contact_points.empty());
  const std::string msg = error_of(edited_copy("gear", "skid_rear: -1.4", "skid_rear: 2.0"));
  EXPECT_NE(msg.find("landing_gear.skid_rear"), std::string::npos) << msg;
}
