// Feeding the LRM faces from a wake table (issue 5): a table holding a uniform stream must give
// exactly the domain that the uniform stream gives, and a refresh happens only when it is due.
#include <gtest/gtest.h>

#include <filesystem>

#include "ship_lrm/lrm/wake_feed.hpp"

using namespace ship_lrm;
namespace fs = std::filesystem;

TEST(WakeFaceFeed, UniformTableGivesTheUniformStreamDomain) {
  const fs::path dir = fs::temp_directory_path() / "ship_lrm_test_feed";
  fs::create_directories(dir);
  const std::string path = (dir / "uniform.h5").string();
  wake::WakeTableInfo info;
  info.origin = {-60, -30, -30};
  info.spacing = 2.0;
  info.shape = {61, 31, 31};
  info.frame_interval = 0.1;
  info.free_stream = {-20, 0, 0};
  info.ship = "none";
  info.scale = "full";
  info.motion = "static";
  info.half_precision = false;
  const Eigen::Vector3d wind(-12.0, 1.0, 0.5);  // inside the table: not the free stream
  {
    wake::WakeTableWriter w(path, info);
    std::vector<float> u(3 * info.points()), rho(info.points(), 1.1934f);
    for (std::size_t p = 0; p < info.points(); ++p)
      for (int d = 0; d < 3; ++d) u[3 * p + d] = static_cast<float>(wind[d]);
    w.append(u, rho);
    w.append(u, rho);
  }
  lrm::LrmConfig cfg;
  cfg.nodes = 16;
  cfg.reach = 1.25;
  cfg.backend = lbm::Backend::Cpu;
  lrm::LrmDomain fed(cfg), uniform(cfg);
  lrm::WakeFaceFeed feed(std::make_shared<wake::WakeTable>(path));
  lrm::WakeFaceFeed::Pose pose;
  pose.hub = Eigen::Vector3d(0, 0, -5);
  pose.hub_velocity = Eigen::Vector3d(3, 0, 0);
  const Eigen::Vector3d air = wind - pose.hub_velocity;
  fed.set_stream(air);
  fed.restart_flow();
  uniform.set_stream(air);
  uniform.restart_flow();
  EXPECT_TRUE(feed.apply(fed, 0.0, pose));
  EXPECT_FALSE(feed.apply(fed, 0.001, pose));  // nothing moved: not due
  fed.step(30);
  uniform.step(30);
  const auto a = fed.solver().fields(), b = uniform.solver().fields();
  double worst = 0;
  for (std::size_t k = 0; k < a.u.size(); ++k) worst = std::max(worst, std::abs(double(a.u[k]) - b.u[k]));
  EXPECT_LT(worst, 1e-6);
  // moved by a quarter cell: due
  pose.hub.x() += 0.3 * fed.units().dx();
  EXPECT_TRUE(feed.apply(fed, 0.002, pose));
}
