// Feeding the LRM faces from a wake table: a table holding a uniform stream must give
// exactly the domain that the uniform stream gives, and a refresh happens only when it is due.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../lbm/backend_difference.hpp"
#include "ship_lrm/lrm/wake_feed.hpp"
#include "temp_path.hpp"
#include "tiny_approach.hpp"

using namespace ship_lrm;

namespace {

std::string temp(const std::string& name) { return ship_lrm::test::temp_path("ship_lrm_test_feed", name); }

// A float32 full-scale table without a ship: a 2 m grid of `shape` points from `origin`, 0.1 s frames.
wake::WakeTableInfo table_info(const std::array<double, 3>& origin, const std::array<int, 3>& shape) {
  wake::WakeTableInfo info;
  info.origin = origin;
  info.spacing = 2.0;
  info.shape = shape;
  info.frame_interval = 0.1;
  info.free_stream = {-20, 0, 0};
  info.ship = "none";
  info.scale = "full";
  info.motion = "static";
  info.half_precision = false;
  return info;
}

}  // namespace

TEST(WakeFaceFeed, UniformTableGivesTheUniformStreamDomain) {
  const std::string path = temp("uniform.h5");
  const wake::WakeTableInfo info = table_info({-60, -30, -30}, {61, 31, 31});
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

namespace {

// A float32 table of two frames whose velocity is linear in space and time, u = u0 + G x + a t (m,
// s): trilinear-in-space, linear-in-time interpolation reproduces it exactly (up to float rounding).
struct LinearTable {
  Eigen::Vector3d u0{-15.0, 2.0, 0.5}, a{4.0, -3.0, 1.0};
  Eigen::Matrix3d G;
  wake::WakeTableInfo info;
  std::string path;
  explicit LinearTable(const std::string& name, double scale = 1.0) {
    G << 0.05, -0.02, 0.01, 0.03, 0.04, -0.015, -0.01, 0.02, 0.025;
    u0 *= scale;
    G *= scale;
    a *= scale;
    path = temp(name);
    info = table_info({-40, -40, -45}, {41, 41, 41});
    wake::WakeTableWriter w(path, info);
    for (int f = 0; f < 2; ++f) {
      std::vector<float> u(3 * info.points()), rho(info.points(), 1.1934f);
      std::size_t p = 0;
      for (int k = 0; k < info.shape[2]; ++k)
        for (int j = 0; j < info.shape[1]; ++j)
          for (int i = 0; i < info.shape[0]; ++i, ++p) {
            const Eigen::Vector3d v = velocity(point(i, j, k), f * info.frame_interval);
            for (int d = 0; d < 3; ++d) u[3 * p + d] = static_cast<float>(v[d]);
          }
      w.append(u, rho);
    }
  }
  Eigen::Vector3d point(int i, int j, int k) const {
    return Eigen::Vector3d(info.origin[0] + i * info.spacing, info.origin[1] + j * info.spacing, info.origin[2] + k * info.spacing);
  }
  Eigen::Vector3d velocity(const Eigen::Vector3d& x, double t) const { return u0 + G * x + a * t; }
};

// A turned, moving, turning domain fed from the linear table at t.
struct FedDomain {
  lrm::LrmDomain domain;
  lrm::WakeFaceFeed feed;
  lrm::WakeFaceFeed::Pose pose;
  lrm::LrmDomain::Motion motion;
  FedDomain(const LinearTable& table, lbm::Backend backend, double t)
      : domain(config(backend)), feed(std::make_shared<wake::WakeTable>(table.path)) {
    pose.hub = Eigen::Vector3d(1.5, -2.0, -6.0);
    pose.rotation = (Eigen::AngleAxisd(0.35, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.08, Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()))
                        .toRotationMatrix();
    pose.hub_velocity = Eigen::Vector3d(4.0, 1.0, -0.5);
    motion.air_velocity = pose.rotation.transpose() * (table.velocity(pose.hub, t) - pose.hub_velocity);
    motion.omega = Eigen::Vector3d(0.02, -0.05, 0.1);
    domain.set_motion(motion);
    domain.restart_flow();
    feed.apply(domain, t, pose, true);
  }
  static lrm::LrmConfig config(lbm::Backend backend) {
    lrm::LrmConfig cfg;
    cfg.nodes = 16;
    cfg.reach = 1.25;
    cfg.backend = backend;
    return cfg;
  }
};

}  // namespace

// table round trip for the path that feeds the faces: every velocity inlet and impedance outlet
// of a turned domain that moves and turns gets R^T (u(hub + R r, t) - v_hub) - omega x r of a field
// linear in space and time, in lattice units (grid_feed.hpp; thesis 5.2: the faces impose the
// undisturbed air relative to the moving domain).
TEST(WakeFaceFeed, FacesTakeALinearFieldExactly) {
  const LinearTable table("linear.h5");
  const double t = 0.037;
  FedDomain fed(table, lbm::Backend::Cpu, t);
  lrm::LrmDomain& d = fed.domain;
  const auto& cells = d.solver().lattice().boundary_cells();
  const std::vector<float>& values = d.solver().boundary_values();
  const double to_lattice = d.units().dt() / d.units().dx();
  const int e = d.cells_per_edge();
  double worst = 0, largest = 0;
  std::size_t checked = 0;
  for (std::size_t b = 0; b < cells.size(); ++b) {
    const auto type = static_cast<lbm::CellType>(d.solver().lattice().types()[cells[b]] & ~lbm::kGeneralBit);
    if (type != lbm::CellType::VelocityInlet && type != lbm::CellType::ImpedanceOutlet) continue;
    const int i = static_cast<int>(cells[b] % e), j = static_cast<int>(cells[b] / e % e), k = static_cast<int>(cells[b] / (e * e));
    const Eigen::Vector3d r = d.position(i, j, k);
    const Eigen::Vector3d air = fed.pose.rotation.transpose() * (table.velocity(fed.pose.to_mean(r), t) - fed.pose.hub_velocity);
    const Eigen::Vector3d want = (air - fed.motion.omega.cross(r)) * to_lattice;
    for (int a = 0; a < 3; ++a) {
      worst = std::max(worst, std::abs(values[4 * b + a] - want[a]));
      largest = std::max(largest, std::abs(want[a]));
    }
    ++checked;
  }
  EXPECT_EQ(checked, cells.size());  // the LRM's faces are velocity inlets and impedance outlets only
  EXPECT_GT(largest, 0.01);
  EXPECT_LT(worst, 2e-6 * largest) << "worst " << worst << " of " << largest;
}

// A face beyond the lattice Mach limit is refused before the faces change (host path).
TEST(WakeFaceFeed, FaceBeyondTheMachLimitIsRefused) {
  const LinearTable table("fast.h5", 12.0);  // some 200 m/s at the faces
  lrm::LrmDomain d(FedDomain::config(lbm::Backend::Cpu));
  d.set_stream(Eigen::Vector3d(-20, 0, 0));
  const std::vector<float> before = d.solver().boundary_values();
  lrm::WakeFaceFeed feed(std::make_shared<wake::WakeTable>(table.path));
  lrm::WakeFaceFeed::Pose pose;
  EXPECT_THROW(feed.apply(d, 0.0, pose, true), ship_lrm::ConfigError);
  EXPECT_EQ(d.solver().boundary_values(), before);
  EXPECT_FALSE(d.has_face_grid());
}

// The CUDA backend interpolates the faces on the device with the same functions: the same values,
// bit for bit, and the same flow after steps in which the impedance outlets follow the change.
// Runs where a CUDA device exists (scripts/gpu_check.sh).
TEST(WakeFaceFeed, CudaFeedMatchesTheHostFeed) {
  if (!lbm::cuda_available()) GTEST_SKIP() << "no CUDA device";
  const LinearTable table("linear_cuda.h5");
  FedDomain cpu(table, lbm::Backend::Cpu, 0.037), gpu(table, lbm::Backend::Cuda, 0.037);
  ASSERT_STREQ(gpu.domain.solver().backend_name(), "cuda");
  EXPECT_EQ(cpu.domain.solver().boundary_values(), gpu.domain.solver().boundary_values());
  // where the flows part, if they do (the worst cell after each stage)
  const auto report = [&](const char* stage, int round) {
    const auto d = lbm::test::backend_difference(cpu.domain.solver().lattice(), cpu.domain.solver().fields(), gpu.domain.solver().fields());
    std::printf("round %d, %s (step %ld): %s\n", round, stage, cpu.domain.solver().steps_done(), d.text.c_str());
  };
  report("fed", -1);
  for (int s = 0; s < 3; ++s) {  // refresh, step; then a new omega re-feeds from the kept windows
    for (FedDomain* f : {&cpu, &gpu}) {
      f->pose.hub.x() += 0.5;
      f->feed.apply(f->domain, 0.037 + 0.02 * (s + 1), f->pose);
      f->domain.step(1);
    }
    report("refreshed", s);
    for (FedDomain* f : {&cpu, &gpu}) {
      f->domain.step(4);
      f->motion.omega.z() += 0.01;
      f->domain.set_motion(f->motion);
      f->domain.step(1);
    }
    report("turned", s);
    for (FedDomain* f : {&cpu, &gpu}) f->domain.step(4);
    EXPECT_EQ(cpu.domain.solver().boundary_values(), gpu.domain.solver().boundary_values()) << "round " << s;
  }
  const auto a = cpu.domain.solver().fields(), b = gpu.domain.solver().fields();
  EXPECT_EQ(a.u, b.u);
  EXPECT_EQ(a.rho, b.rho);
}

// bench wake (face-feed cost target) over the tiny table: the faces are refreshed as the hub flies
// through it, and the feed is timed both ways, each step to its end and in the loop without waits.
TEST(WakeFaceFeed, BenchmarkTimesTheFeedEachStepAndInTheLoop) {
  lrm::LrmConfig c;
  c.nodes = 16;
  c.backend = lbm::Backend::Cpu;
  const lrm::WakeFeedBenchmark r = lrm::run_wake_feed_benchmark(test::tiny_table(), c, 20);
  EXPECT_EQ(r.steps, 20);
  EXPECT_GT(r.refreshes, 0u);
  EXPECT_LE(r.refreshes, 20u);
  for (double t : {r.step_seconds, r.feed_seconds, r.loop_fed_seconds, r.loop_alone_seconds}) {
    EXPECT_TRUE(std::isfinite(t));
    EXPECT_GT(t, 0.0);
  }
  EXPECT_NE(r.to_json().find("\"loop_feed_fraction\""), std::string::npos);
}
