// The wake table: write -> read -> interpolate round trip and bad files .
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "ship_lrm/wake/wake_table.hpp"
#include "temp_path.hpp"

using namespace ship_lrm::wake;
namespace fs = std::filesystem;

namespace {

std::string temp(const std::string& name) { return ship_lrm::test::temp_path("ship_lrm_test_table", name); }

WakeTableInfo grid(bool half) {
  WakeTableInfo i;
  i.origin = {-10.0, -4.0, -6.0};
  i.spacing = 0.5;
  i.shape = {21, 13, 9};
  i.frame_interval = 0.1;
  i.start_time = 2.0;
  i.free_stream = {-12.0, 0.0, 0.0};
  i.free_density = 1.2;
  i.ship = "test";
  i.scale = "full";
  i.motion = "static";
  i.half_precision = half;
  return i;
}

// A field linear in space and time: trilinear + linear interpolation reproduces it exactly.
std::array<double, 4> linear(double x, double y, double z, double t) {
  return {-10 + 0.3 * x - 0.2 * y + 0.1 * z + 2.0 * t, 0.5 * x + 0.25 * z - t, 0.1 * y + 0.05 * x + 0.5 * t,
          1.2 + 0.001 * x - 0.002 * z + 0.01 * t};
}

std::string write_linear(const std::string& name, bool half, int frames) {
  const std::string path = temp(name);
  const WakeTableInfo info = grid(half);
  WakeTableWriter w(path, info);
  for (int f = 0; f < frames; ++f) {
    const double t = info.start_time + f * info.frame_interval;
    std::vector<float> u(3 * info.points()), rho(info.points());
    std::size_t p = 0;
    for (int k = 0; k < info.shape[2]; ++k)
      for (int j = 0; j < info.shape[1]; ++j)
        for (int i = 0; i < info.shape[0]; ++i, ++p) {
          const auto v = linear(info.origin[0] + i * info.spacing, info.origin[1] + j * info.spacing, info.origin[2] + k * info.spacing, t);
          for (int d = 0; d < 3; ++d) u[3 * p + d] = static_cast<float>(v[d]);
          rho[p] = static_cast<float>(v[3]);
        }
    w.append(u, rho);
  }
  return path;
}

}  // namespace

TEST(WakeTable, Float32ExactAtGridPointsAndForLinearFieldsAnywhere) {
  const std::string path = write_linear("linear32.h5", false, 4);
  EXPECT_TRUE(fs::exists(fs::path(path).replace_extension(".xdmf")));
  WakeTable table(path);
  ASSERT_EQ(table.info().frames, 4);
  EXPECT_FALSE(table.info().half_precision);
  const WakeTableInfo& in = table.info();
  // grid points at frame times: exact (float32 stored, float32 returned)
  std::vector<double> xyz;
  std::vector<std::array<double, 4>> want;
  for (int k = 0; k < in.shape[2]; k += 2)
    for (int j = 0; j < in.shape[1]; j += 3)
      for (int i = 0; i < in.shape[0]; i += 4) {
        const double x = in.origin[0] + i * in.spacing, y = in.origin[1] + j * in.spacing, z = in.origin[2] + k * in.spacing;
        xyz.insert(xyz.end(), {x, y, z});
        want.push_back(linear(x, y, z, in.start_time + 0.2));
      }
  std::vector<WakeSample> got;
  table.sample(in.start_time + 0.2, xyz, got);
  for (std::size_t p = 0; p < want.size(); ++p) {
    for (int d = 0; d < 3; ++d) ASSERT_EQ(got[p].u[d], static_cast<float>(want[p][d])) << p;
    ASSERT_EQ(got[p].rho, static_cast<float>(want[p][3]));
  }
  // anywhere inside, between frames: linear fields come back to float rounding
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const double t = in.start_time + ux(rng) * 0.3;
    xyz.clear();
    want.clear();
    for (int p = 0; p < 50; ++p) {
      const double x = in.origin[0] + ux(rng) * 10, y = in.origin[1] + ux(rng) * 6, z = in.origin[2] + ux(rng) * 4;
      xyz.insert(xyz.end(), {x, y, z});
      want.push_back(linear(x, y, z, t));
    }
    table.sample(t, xyz, got);
    for (std::size_t p = 0; p < want.size(); ++p) {
      for (int d = 0; d < 3; ++d) ASSERT_NEAR(got[p].u[d], want[p][d], 2e-5 * (1 + std::abs(want[p][d])));
      ASSERT_NEAR(got[p].rho, want[p][3], 2e-6);
    }
  }
  // outside the box: the free stream; before the first frame: the first frame
  table.sample(in.start_time, {100.0, 0.0, 0.0}, got);
  EXPECT_EQ(got[0].u[0], -12.0f);
  EXPECT_EQ(got[0].rho, 1.2f);
  table.sample(in.start_time - 5, {in.origin[0], in.origin[1], in.origin[2]}, got);
  EXPECT_EQ(got[0].u[0], static_cast<float>(linear(in.origin[0], in.origin[1], in.origin[2], in.start_time)[0]));
}

TEST(WakeTable, Float16KeepsHalfPrecisionAndTheWindowBoundsMemory) {
  const std::string path = write_linear("linear16.h5", true, 2);
  WakeTable table(path, 200);  // at most 200 grid points per frame in memory
  EXPECT_TRUE(table.info().half_precision);
  const WakeTableInfo& in = table.info();
  std::vector<WakeSample> got;
  const double x = in.origin[0] + 3 * in.spacing, y = in.origin[1] + 2 * in.spacing, z = in.origin[2] + 1 * in.spacing;
  table.sample(in.start_time, {x, y, z}, got);
  const auto want = linear(x, y, z, in.start_time);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(got[0].u[d], want[d], 1e-3 * (1 + std::abs(want[d])));  // 11-bit mantissa
  // a region larger than the window is refused with a message, not read
  EXPECT_THROW(
      table.sample(in.start_time, {in.origin[0], in.origin[1], in.origin[2], in.origin[0] + 9, in.origin[1] + 5, in.origin[2] + 3}, got),
      TableError);
}

// The reader widens binary16 itself (HDF5's soft conversion was slow): every value must come out as
// HDF5's own conversion gives it, across the half range (subnormals, signed zero, the largest half).
TEST(WakeTable, Float16IsReadAsHdf5ConvertsIt) {
  const std::string path = temp("range16.h5");
  const WakeTableInfo info = grid(true);
  std::vector<float> u(3 * info.points()), rho(info.points());
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> exponent(-26.0f, 16.0f);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = (k % 2 ? -1.0f : 1.0f) * std::exp2(exponent(rng));
  u[0] = 0.0f, u[1] = -0.0f, u[2] = 65504.0f, u[3] = -65504.0f, u[4] = 6.0e-8f,
  u[5] = 6.1035156e-05f;  // half: max, min subnormal, min normal
  for (std::size_t k = 0; k < rho.size(); ++k) rho[k] = 1.0f + 1e-3f * static_cast<float>(k);
  {
    WakeTableWriter w(path, info);
    w.append(u, rho);
  }
  std::vector<float> want_u(u.size()), want_rho(rho.size());
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t v = H5Dopen2(f, "/velocity", H5P_DEFAULT), r = H5Dopen2(f, "/density", H5P_DEFAULT);
  ASSERT_GE(H5Dread(v, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, want_u.data()), 0);
  ASSERT_GE(H5Dread(r, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, want_rho.data()), 0);
  H5Dclose(v), H5Dclose(r), H5Fclose(f);
  WakeTable table(path);
  ASSERT_TRUE(table.info().half_precision);
  std::vector<float> got_u, got_rho;
  table.read_frame(0, got_u, got_rho);
  ASSERT_EQ(got_u.size(), want_u.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < u.size(); ++k) differ += std::memcmp(&got_u[k], &want_u[k], sizeof(float)) != 0;
  for (std::size_t k = 0; k < rho.size(); ++k) differ += std::memcmp(&got_rho[k], &want_rho[k], sizeof(float)) != 0;
  EXPECT_EQ(differ, 0u);
  EXPECT_EQ(got_u[2], 65504.0f);
  EXPECT_TRUE(std::signbit(got_u[1]));
  EXPECT_GT(got_u[4], 0.0f);  // a subnormal half, not flushed to zero
  EXPECT_LT(got_u[4], 6.1e-5f);
}

TEST(WakeTable, BadFilesGiveClearErrors) {
  EXPECT_THROW(WakeTable(temp("none.h5")), TableError);
  const std::string junk = temp("junk.h5");
  std::ofstream(junk) << "not hdf5";
  EXPECT_THROW(WakeTable{junk}, TableError);
  // truncated: half of a valid file
  const std::string good = write_linear("good.h5", false, 3);
  const std::string cut = temp("cut.h5");
  fs::copy_file(good, cut, fs::copy_options::overwrite_existing);
  fs::resize_file(cut, fs::file_size(cut) / 2);
  try {
    WakeTable t(cut);
    std::vector<float> u, r;
    for (int f = 0; f < t.info().frames; ++f) t.read_frame(f, u, r);
    FAIL() << "a truncated table was read";
  } catch (const TableError& e) {
    SUCCEED() << e.what();
  }
  // wrong format version, wrong units
  for (const char* what : {"version", "units"}) {
    const std::string bad = temp(std::string("bad_") + what + ".h5");
    fs::copy_file(good, bad, fs::copy_options::overwrite_existing);
    const hid_t f = H5Fopen(bad.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    if (std::string(what) == "version") {
      const hid_t a = H5Aopen(f, "format_version", H5P_DEFAULT);
      const double v = 99;
      H5Awrite(a, H5T_NATIVE_DOUBLE, &v);
      H5Aclose(a);
    } else {
      H5Adelete(f, "units");
      const hid_t type = H5Tcopy(H5T_C_S1);
      H5Tset_size(type, 6);
      const hid_t space = H5Screate(H5S_SCALAR);
      const hid_t a = H5Acreate2(f, "units", type, space, H5P_DEFAULT, H5P_DEFAULT);
      H5Awrite(a, type, "ft, s ");
      H5Aclose(a);
      H5Sclose(space);
      H5Tclose(type);
    }
    H5Fclose(f);
    try {
      WakeTable t(bad);
      FAIL() << "accepted a table with a bad " << what;
    } catch (const TableError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
}

// The next frame is read ahead on a background thread: stepping through the frames, every frame
// change after the first finds its window read in time, and the samples stay exact (linear field).
TEST(WakeTable, ReadAheadServesTheNextFrame) {
  const std::string path = write_linear("read_ahead.h5", false, 6);
  WakeTable table(path);
  const auto& in = table.info();
  const std::vector<double> xyz = {-3.2, 1.1, -2.4, -0.7, -0.3, -3.1};  // inside the table
  std::vector<WakeSample> got;
  double worst = 0;
  for (double t = in.start_time + 0.03; t < in.end_time(); t += 0.02) {
    table.sample(t, xyz, got);
    for (std::size_t p = 0; p < 2; ++p) {
      const auto want = linear(xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2], t);
      for (int d = 0; d < 3; ++d) worst = std::max(worst, std::abs(got[p].u[d] - want[d]));
    }
  }
  EXPECT_LT(worst, 2e-5);
  // frames 0 and 1 at the start, then frames 2 .. 5 as the time moves on: each read ahead
  EXPECT_EQ(table.window_loads(), 6u);
  EXPECT_EQ(table.window_read_ahead_hits(), 4u);
}

// A table whose windows come from elsewhere (the ROS wake server's service: WindowSource) gives the
// file's values bit for bit, sampled and as the LRM's face windows; a source that fails names itself
// and why, and a bad box or frame asked of the file is refused by name.
TEST(WakeTable, AServedTableIsTheFileBitForBit) {
  const std::string path = write_linear("served.h5", false, 4);
  auto file = std::make_shared<WakeTable>(path);
  class FromTable final : public WindowSource {
   public:
    explicit FromTable(std::shared_ptr<WakeTable> t) : t_(std::move(t)) {}
    bool read(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* u, float* rho) override {
      if (fail) return false;
      std::vector<float> a, b;
      t_->read_box(frame, lo, n, a, b);  // what the wake server answers
      std::copy(a.begin(), a.end(), u);
      std::copy(b.begin(), b.end(), rho);
      ++reads;
      return true;
    }
    std::string name() const override { return "served test table"; }
    bool fail = false;
    int reads = 0;

   private:
    std::shared_ptr<WakeTable> t_;
  };
  auto source = std::make_unique<FromTable>(file);
  FromTable* src = source.get();
  WakeTable served(file->info(), std::move(source));
  WakeTable reference(path);
  const WakeTableInfo& in = reference.info();
  std::vector<double> xyz;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(0, 1);
  for (int p = 0; p < 200; ++p)
    xyz.insert(xyz.end(), {in.origin[0] + ux(rng) * 10, in.origin[1] + ux(rng) * 6, in.origin[2] + ux(rng) * 4});
  std::vector<WakeSample> a, b;
  for (double t : {in.start_time + 0.05, in.start_time + 0.17, in.start_time + 0.29}) {
    reference.sample(t, xyz, a);
    served.sample(t, xyz, b);
    for (std::size_t p = 0; p < a.size(); ++p) {
      ASSERT_EQ(a[p].u, b[p].u) << p;
      ASSERT_EQ(a[p].rho, b[p].rho) << p;
    }
    const auto fa = reference.frames(t, {-9.0, -3.0, -5.0}, {-2.0, 1.0, -3.0}),
               fb = served.frames(t, {-9.0, -3.0, -5.0}, {-2.0, 1.0, -3.0});
    EXPECT_EQ(fa.grid.weight1, fb.grid.weight1);
    for (int s = 0; s < 2; ++s) {
      const std::size_t pts = static_cast<std::size_t>(fa.window[s].n[0]) * fa.window[s].n[1] * fa.window[s].n[2];
      ASSERT_EQ(pts, static_cast<std::size_t>(fb.window[s].n[0]) * fb.window[s].n[1] * fb.window[s].n[2]);
      EXPECT_TRUE(std::equal(fa.window[s].u, fa.window[s].u + 3 * pts, fb.window[s].u));
    }
  }
  EXPECT_GT(src->reads, 0);
  src->fail = true;
  try {
    served.sample(in.start_time, xyz, b);  // frame 0: no longer in memory (frames 2 and 3 are)
    FAIL() << "a failing source was not reported";
  } catch (const TableError& e) {
    EXPECT_NE(std::string(e.what()).find("served test table"), std::string::npos) << e.what();
  }
  std::vector<float> u, rho;
  EXPECT_THROW(file->read_box(4, {0, 0, 0}, {2, 2, 2}, u, rho), TableError);                // no frame 4
  EXPECT_THROW(file->read_box(0, {20, 0, 0}, {2, 2, 2}, u, rho), TableError);               // past the grid
  EXPECT_THROW(WakeTable(WakeTableInfo{}, std::make_unique<FromTable>(file)), TableError);  // no grid, no frames
}
