// A nested wake table: the two levels written, read back and served as one grid with no seam; nested
// tables whose levels disagree refused; a nested precompute served without a seam, resumed bit for bit.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "nrc_model_case.hpp"
#include "ship_lrm/lbm/lattice.hpp"
#include "ship_lrm/wake/nested_table.hpp"
#include "ship_lrm/wake/wake_precompute.hpp"
#include "ship_lrm/wake/wake_table.hpp"
#include "temp_path.hpp"

using namespace ship_lrm::wake;
namespace fs = std::filesystem;

namespace {

std::string temp(const std::string& name) { return ship_lrm::test::temp_path("ship_lrm_test_nested", name); }

// The coarse level: 11 x 9 x 8 points, spacing 2 m; the fine level: ratio 4 over coarse cells
// (2, 2, 1) .. (8, 6, 7), its z+ face (the sea's side) not blended.
WakeTableInfo nested_grid() {
  WakeTableInfo i;
  i.origin = {-10.0, -8.0, -12.0};
  i.spacing = 2.0;
  i.shape = {11, 9, 8};
  i.frame_interval = 0.5;
  i.start_time = 1.0;
  i.free_stream = {-10.0, 0.0, 0.0};
  i.free_density = 1.2;
  i.ship = "test";
  i.scale = "full";
  i.motion = "static";
  i.half_precision = false;
  i.fine.ratio = 4;
  i.fine.lo = {2, 2, 1};
  i.fine.shape = {6 * 4 + 1, 4 * 4 + 1, 6 * 4 + 1};
  i.fine.seam = {1, 1, 1, 1, 1, 0};
  i.fine.seam_cells = 2;
  return i;
}

// The coarse field: linear in space (trilinear interpolation reproduces it exactly), and in time.
std::array<double, 4> coarse_field(double x, double y, double z, double t) {
  return {-10 + 0.3 * x - 0.2 * y + 0.1 * z + t, 0.5 * x + 0.25 * z, 0.1 * y - 0.5 * t, 1.2 + 0.001 * x};
}
// The fine level resolves more: the coarse field plus a difference of up to kBump.
constexpr double kBump = 1.5;
std::array<double, 4> fine_field(double x, double y, double z, double t) {
  auto v = coarse_field(x, y, z, t);
  v[0] += kBump * std::sin(0.7 * x) * std::cos(0.5 * y);
  v[2] += 0.5 * kBump * std::cos(0.3 * z);
  v[3] += 0.01;
  return v;
}

template <class F>
void fill(const std::array<double, 3>& origin, double h, const std::array<int, 3>& shape, double t, F field, std::vector<float>& u,
          std::vector<float>& rho) {
  const std::size_t n = static_cast<std::size_t>(shape[0]) * shape[1] * shape[2];
  u.resize(3 * n);
  rho.resize(n);
  std::size_t p = 0;
  for (int k = 0; k < shape[2]; ++k)
    for (int j = 0; j < shape[1]; ++j)
      for (int i = 0; i < shape[0]; ++i, ++p) {
        const auto v = field(origin[0] + i * h, origin[1] + j * h, origin[2] + k * h, t);
        for (int d = 0; d < 3; ++d) u[3 * p + d] = static_cast<float>(v[d]);
        rho[p] = static_cast<float>(v[3]);
      }
}

std::string write_nested(const std::string& name, const WakeTableInfo& info, int frames) {
  const std::string path = temp(name);
  WakeTableWriter w(path, info);
  std::array<double, 3> fo{};
  for (int d = 0; d < 3; ++d) fo[d] = info.origin[d] + info.fine.lo[d] * info.spacing;
  for (int f = 0; f < frames; ++f) {
    const double t = info.start_time + f * info.frame_interval;
    std::vector<float> u, rho, fu, frho;
    fill(info.origin, info.spacing, info.shape, t, coarse_field, u, rho);
    fill(fo, info.spacing / info.fine.ratio, info.fine.shape, t, fine_field, fu, frho);
    w.append(u, rho, fu, frho);
  }
  w.close();
  return path;
}

void set_number_attribute(const std::string& path, const char* object, const char* name, const std::vector<double>& v) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t o = H5Oopen(f, object, H5P_DEFAULT);
  const hid_t a = H5Aopen(o, name, H5P_DEFAULT);
  ASSERT_GE(a, 0);
  ASSERT_GE(H5Awrite(a, H5T_NATIVE_DOUBLE, v.data()), 0);
  H5Aclose(a), H5Oclose(o), H5Fclose(f);
}

}  // namespace

// The served grid: the fine spacing over the coarse box. Outside the fine box it is the coarse field
// (here linear: exact), past the seam band the fine field, at the blended faces the coarse field, and
// nowhere a step larger than the two fields' own change plus the levels' difference spread over the
// band (what an LRM face moving through the seam would feel).
TEST(NestedTable, TheSeamIsContinuousAndSpreadOverItsBand) {
  const WakeTableInfo stored = nested_grid();
  const std::string path = write_nested("seam.h5", stored, 2);
  WakeTable table(path);
  const WakeTableInfo& s = table.info();
  const int r = stored.fine.ratio;
  ASSERT_EQ(s.fine.ratio, r);
  EXPECT_DOUBLE_EQ(s.spacing, stored.spacing / r);
  EXPECT_EQ(s.shape[0], (stored.shape[0] - 1) * r + 1);
  EXPECT_EQ(s.shape[2], (stored.shape[2] - 1) * r + 1);
  std::vector<float> u, rho;
  table.read_frame(1, u, rho);
  const double t = stored.start_time + stored.frame_interval, h = s.spacing;
  const std::array<int, 3> f0{stored.fine.lo[0] * r, stored.fine.lo[1] * r, stored.fine.lo[2] * r};
  double worst_outside = 0, worst_inside = 0, worst_face = 0, worst_sea_face = 0;
  long inside = 0, band = 0;
  const auto at = [&](int i, int j, int k) {
    return i + static_cast<std::size_t>(s.shape[0]) * (j + static_cast<std::size_t>(s.shape[1]) * k);
  };
  for (int k = 0; k < s.shape[2]; ++k)
    for (int j = 0; j < s.shape[1]; ++j)
      for (int i = 0; i < s.shape[0]; ++i) {
        const double x = s.origin[0] + i * h, y = s.origin[1] + j * h, z = s.origin[2] + k * h;
        const double w = fine_weight(stored, {i, j, k});
        const std::size_t p = at(i, j, k);
        const auto c = coarse_field(x, y, z, t), f = fine_field(x, y, z, t);
        double dc = 0, df = 0;
        for (int d = 0; d < 3; ++d) {
          dc = std::max(dc, std::abs(u[3 * p + d] - c[d]));
          df = std::max(df, std::abs(u[3 * p + d] - f[d]));
        }
        const bool in_box = i >= f0[0] && j >= f0[1] && k >= f0[2] && i <= f0[0] + stored.fine.shape[0] - 1 &&
                            j <= f0[1] + stored.fine.shape[1] - 1 && k <= f0[2] + stored.fine.shape[2] - 1;
        if (!in_box) {
          EXPECT_EQ(w, 0.0);
          worst_outside = std::max(worst_outside, dc);
        } else if (w >= 1.0) {
          worst_inside = std::max(worst_inside, df);
          ++inside;
        } else {
          ++band;
        }
        if (in_box && (i == f0[0] || j == f0[1] || k == f0[2])) worst_face = std::max(worst_face, dc);
        // the sea's face is not blended: there the fine values are served as they are
        if (in_box && k == f0[2] + stored.fine.shape[2] - 1 && w >= 1.0) worst_sea_face = std::max(worst_sea_face, df);
      }
  EXPECT_GT(inside, 0);
  EXPECT_GT(band, 0);
  EXPECT_LT(worst_outside, 2e-5);  // float rounding of values of order 10
  EXPECT_LT(worst_inside, 1e-6);   // the fine values themselves
  EXPECT_LT(worst_face, 2e-5);     // continuous at the blended faces
  EXPECT_LT(worst_sea_face, 1e-6);
  // the largest step between neighbours along x: the fields' own change over h, plus at most the
  // levels' difference (kBump) spread over the band of seam_cells coarse cells
  double field_step = 0, worst_step = 0;
  for (int k = 0; k < s.shape[2]; ++k)
    for (int j = 0; j < s.shape[1]; ++j)
      for (int i = 0; i + 1 < s.shape[0]; ++i) {
        const double x = s.origin[0] + i * h, y = s.origin[1] + j * h, z = s.origin[2] + k * h;
        const auto f = fine_field(x, y, z, t), g = fine_field(x + h, y, z, t);
        field_step = std::max(field_step, std::abs(g[0] - f[0]));
        worst_step = std::max(worst_step, static_cast<double>(std::abs(u[3 * at(i + 1, j, k)] - u[3 * at(i, j, k)])));
      }
  EXPECT_LE(worst_step, field_step + kBump / (stored.fine.seam_cells * r) + 1e-5);
  // the LRM's feed interpolates the served grid: sampling through the table gives the same values
  std::vector<WakeSample> out;
  // (a point past the band on every side: 11 - 12 fine cells from the x faces, 8 from the y faces)
  const double x = s.origin[0] + (f0[0] + 12) * h + 0.3 * h, y = s.origin[1] + (f0[1] + 8) * h, z = s.origin[2] + (f0[2] + 12) * h;
  table.sample(t, {x, y, z}, out);
  const auto f = fine_field(x, y, z, t);
  EXPECT_NEAR(out[0].u[2], f[2], 2e-3);  // trilinear on the fine grid of a smooth field
}

// A single-level table reads as before (format version 1), and a nested one keeps its stored levels.
TEST(NestedTable, SingleLevelTablesAreServedAsStored) {
  WakeTableInfo single = nested_grid();
  single.fine = WakeTableLevel{};
  const std::string path = temp("single.h5");
  {
    WakeTableWriter w(path, single);
    std::vector<float> u, rho;
    fill(single.origin, single.spacing, single.shape, single.start_time, coarse_field, u, rho);
    w.append(u, rho);
  }
  WakeTableInfo info, stored;
  open_table_file(path, info, &stored);
  EXPECT_EQ(info.fine.ratio, 0);
  EXPECT_EQ(info.shape, single.shape);
  EXPECT_DOUBLE_EQ(info.spacing, single.spacing);
  const std::string nested = write_nested("stored.h5", nested_grid(), 1);
  open_table_file(nested, info, &stored);
  EXPECT_EQ(stored.shape, nested_grid().shape);
  EXPECT_EQ(stored.fine.shape, nested_grid().fine.shape);
  EXPECT_EQ(stored.fine.lo, nested_grid().fine.lo);
  EXPECT_EQ(info.shape[1], (nested_grid().shape[1] - 1) * 4 + 1);
}

// Levels that disagree in time or frame, or a fine level that does not nest, are refused when the
// table is opened, naming what is wrong.
TEST(NestedTable, LevelsThatDisagreeAreRefused) {
  const WakeTableInfo good = nested_grid();
  const auto refused = [](const std::string& path, const std::string& words) {
    try {
      WakeTable t(path);
      ADD_FAILURE() << path << " was accepted";
    } catch (const TableError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  {
    const std::string p = write_nested("time.h5", good, 2);
    set_number_attribute(p, "/fine", "start_time", {good.start_time + 0.25});
    refused(p, "disagree in time");
  }
  {
    const std::string p = write_nested("interval.h5", good, 2);
    set_number_attribute(p, "/fine", "frame_interval", {2 * good.frame_interval});
    refused(p, "disagree in time");
  }
  {
    const std::string p = write_nested("frames.h5", good, 2);
    set_number_attribute(p, "/", "frames", {3.0});  // the coarse level's count past what the fine level holds
    const hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t v = H5Dopen2(f, "/velocity", H5P_DEFAULT), r = H5Dopen2(f, "/density", H5P_DEFAULT);
    const hsize_t dv[5] = {3, 8, 9, 11, 3}, dr[4] = {3, 8, 9, 11};
    H5Dset_extent(v, dv), H5Dset_extent(r, dr);
    H5Dclose(v), H5Dclose(r), H5Fclose(f);
    refused(p, "disagree in time");
  }
  {
    const std::string p = write_nested("origin.h5", good, 1);
    set_number_attribute(p, "/fine", "origin", {good.origin[0] + 1.0, good.origin[1] + 4.0, good.origin[2] + 2.0});
    refused(p, "disagree in frame");
  }
  {
    const std::string p = write_nested("spacing.h5", good, 1);
    set_number_attribute(p, "/fine", "spacing", {good.spacing / 3});
    refused(p, "disagree in frame");
  }
  {
    const std::string p = write_nested("outside.h5", good, 1);
    set_number_attribute(p, "/fine", "lo", {6.0, 2.0, 1.0});  // 6 coarse cells from x = 6 pass the coarse grid's 10
    refused(p, "inside the coarse grid");
  }
  // the writer refuses a fine level that does not nest before it writes anything
  WakeTableInfo bad = good;
  bad.fine.shape[0] = 22;  // not ratio x cells + 1
  fs::remove(temp("bad.h5"));
  EXPECT_THROW(WakeTableWriter(temp("bad.h5"), bad), TableError);
  EXPECT_FALSE(fs::exists(temp("bad.h5")));
}

namespace {

// A small nested NRC run: the 1/50 model at 32 coarse cells per length, a fine region at ratio 2
// started after the coarse domain, the thesis' two deck probes.
PrecomputeOptions small_nested_run(const std::string& name) {
  PrecomputeOptions o = ship_lrm::test::nrc_model_case("static", 32);
  o.domain.fine.ratio = 2;
  o.domain.fine.aft = -0.3;  // over the hangar and the deck: small and cheap (laminar at this resolution)
  o.domain.fine.fore = 0.1;
  o.domain.fine.half_width = 0.13;
  o.domain.fine.top = 0.17;
  o.domain.fine.start = 0.3;  // the coarse domain alone before
  o.startup = 0.5;
  o.duration = 0.2;
  o.frame_interval = 0.1;
  o.stats_interval = 0.01;
  o.probes = {{-0.3, 0.0, -0.07}, {-0.3, 0.06, -0.07}};
  o.half_precision = false;
  o.out = temp(name);
  return o;
}

}  // namespace

// A real nested precompute: the table holds both levels, and across the seam the served field steps
// by no more than the fine level's own flow does between neighbours inside it (the seam is not
// sharper than the flow). The probes sample the fine level at every statistics sample.
TEST(NestedTable, ANestedPrecomputeIsServedWithoutASeam) {
  const PrecomputeOptions o = small_nested_run("nested_run.h5");
  const PrecomputeResult r = precompute_wake(o);
  ASSERT_EQ(r.frames, 3);
  EXPECT_GT(r.fine_cells, 0u);
  EXPECT_NEAR(static_cast<double>(r.probes.time.size()), 20.5, 0.5);  // 0.2 s every 0.01 s (both ends when they fall on steps)
  for (float v : r.probes.u) EXPECT_TRUE(std::isfinite(v));
  EXPECT_GT(r.fine_stats.samples, 0);
  EXPECT_TRUE(fs::exists(r.fine_centre_plane_csv));
  WakeTableInfo info, stored;
  open_table_file(o.out, info, &stored);
  ASSERT_EQ(stored.fine.ratio, 2);
  EXPECT_NEAR(info.spacing, r.dx / 2, 1e-12);
  EXPECT_NEAR(stored.spacing, r.dx, 1e-12);
  WakeTable t(o.out);
  std::vector<float> u, rho;
  t.read_frame(2, u, rho);
  const WakeTableInfo& s = t.info();
  const auto at = [&](int i, int j, int k) {
    return i + static_cast<std::size_t>(s.shape[0]) * (j + static_cast<std::size_t>(s.shape[1]) * k);
  };
  const int rr = stored.fine.ratio;
  const std::array<int, 3> f0{stored.fine.lo[0] * rr, stored.fine.lo[1] * rr, stored.fine.lo[2] * rr};
  double seam = 0, interior = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int k = std::max(0, f0[2] - rr); k <= std::min(s.shape[2] - 1, f0[2] + stored.fine.shape[2] - 1 + rr); ++k)
      for (int j = std::max(0, f0[1] - rr); j <= std::min(s.shape[1] - 1, f0[1] + stored.fine.shape[1] - 1 + rr); ++j)
        for (int i = std::max(0, f0[0] - rr); i <= std::min(s.shape[0] - 1, f0[0] + stored.fine.shape[0] - 1 + rr); ++i) {
          std::array<int, 3> a{i, j, k}, b = a;
          ++b[axis];
          if (b[axis] >= s.shape[axis]) continue;
          const double wa = fine_weight(stored, a), wb = fine_weight(stored, b);
          double step = 0;
          for (int d = 0; d < 3; ++d)
            step = std::max(step, static_cast<double>(std::abs(u[3 * at(b[0], b[1], b[2]) + d] - u[3 * at(a[0], a[1], a[2]) + d])));
          if (wa >= 1.0 && wb >= 1.0)
            interior = std::max(interior, step);
          else if (wa < 1.0 || wb < 1.0)
            seam = std::max(seam, step);
        }
  EXPECT_GT(interior, 0.0);
  EXPECT_LE(seam, interior) << "the seam steps by " << seam << " m/s, the fine flow by at most " << interior << " m/s between neighbours";
}

// A stopped nested run resumes to the same table, both levels and the probes bit for bit; a probe in
// the ship is refused before any step, with nothing written.
TEST(NestedTable, ANestedRunResumesAndRefusesProbesOutsideTheFluid) {
  const PrecomputeOptions whole_o = small_nested_run("nested_whole.h5");
  const PrecomputeResult whole = precompute_wake(whole_o);
  PrecomputeOptions s = small_nested_run("nested_stopped.h5");
  s.stop_at_step = std::lround((s.startup + 0.15) / whole.dt);
  ASSERT_TRUE(precompute_wake(s).interrupted);
  s.stop_at_step = -1;
  const PrecomputeResult second = precompute_wake(s);
  EXPECT_TRUE(second.resumed);
  EXPECT_EQ(second.probes.u, whole.probes.u);
  EXPECT_EQ(second.fine_stats.sum, whole.fine_stats.sum);
  WakeTable a(whole_o.out), b(s.out);
  ASSERT_EQ(a.info().frames, b.info().frames);
  for (int f = 0; f < a.info().frames; ++f) {
    std::vector<float> ua, ra, ub, rb;
    a.read_frame(f, ua, ra);
    b.read_frame(f, ub, rb);
    ASSERT_EQ(ua, ub) << "frame " << f;
  }
  PrecomputeOptions bad = small_nested_run("nested_bad_probe.h5");
  fs::remove(bad.out);
  bad.probes = {{-0.3, 0.0, 0.05}};  // 0.05 m below the deck: in the hull
  EXPECT_THROW(precompute_wake(bad), ship_lrm::ConfigError);
  EXPECT_FALSE(fs::exists(bad.out));
}

// A table that stores a part of the fine region (FineRegionConfig::stored_*): the run is the same,
// the part is served with the region's own values (bit for bit where no seam blends them), the file
// is smaller; a part outside the region or too small to blend is refused before any step.
TEST(NestedTable, AStoredPartServesTheRegionsValuesAndIsSmaller) {
  const PrecomputeOptions whole_o = small_nested_run("nested_all_stored.h5");
  precompute_wake(whole_o);
  PrecomputeOptions part_o = small_nested_run("nested_part_stored.h5");
  part_o.domain.fine.stored_aft = -0.2;  // of the box's -0.3 .. 0.1 ship lengths
  part_o.domain.fine.stored_fore = 0.05;
  part_o.domain.fine.stored_top = 0.14;  // of its 0.17
  precompute_wake(part_o);
  WakeTableInfo whole_info, whole, part_info, part;
  open_table_file(whole_o.out, whole_info, &whole);
  open_table_file(part_o.out, part_info, &part);
  ASSERT_EQ(part.fine.ratio, whole.fine.ratio);
  EXPECT_EQ(part_info.shape, whole_info.shape);  // the same served grid
  EXPECT_GT(part.fine.lo[0], whole.fine.lo[0]);
  EXPECT_LT(part.fine.shape[0], whole.fine.shape[0]);
  EXPECT_LT(part.fine.shape[2], whole.fine.shape[2]);
  EXPECT_EQ(part.fine.shape[1], whole.fine.shape[1]);
  EXPECT_LT(fs::file_size(part_o.out), fs::file_size(whole_o.out));
  WakeTable a(whole_o.out), b(part_o.out);
  std::vector<float> ua, ra, ub, rb;
  a.read_frame(2, ua, ra);
  b.read_frame(2, ub, rb);
  ASSERT_EQ(ua.size(), ub.size());
  const WakeTableInfo& s = b.info();
  std::size_t compared = 0, differ_outside = 0;
  for (int k = 0; k < s.shape[2]; ++k)
    for (int j = 0; j < s.shape[1]; ++j)
      for (int i = 0; i < s.shape[0]; ++i) {
        const std::size_t p = i + static_cast<std::size_t>(s.shape[0]) * (j + static_cast<std::size_t>(s.shape[1]) * k);
        const bool in_part = fine_weight(part, {i, j, k}) >= 1.0;
        bool same = true;
        for (int d = 0; d < 3; ++d) same = same && ua[3 * p + d] == ub[3 * p + d];
        if (in_part) {
          ++compared;
          ASSERT_TRUE(same) << "point " << i << ", " << j << ", " << k;
        } else if (fine_weight(whole, {i, j, k}) >= 1.0 && !same) {
          ++differ_outside;  // the region's values there, the coarse level's in the smaller table
        }
      }
  EXPECT_GT(compared, 100u);
  EXPECT_GT(differ_outside, 0u);

  PrecomputeOptions outside = small_nested_run("nested_part_outside.h5");
  fs::remove(outside.out);
  outside.domain.fine.stored_fore = 0.2;  // past the box's fore face
  EXPECT_THROW(precompute_wake(outside), ship_lrm::ConfigError);
  outside.domain.fine.stored_fore = std::numeric_limits<double>::quiet_NaN();
  outside.domain.fine.stored_aft = 0.05;  // 0.05 .. 0.1: fewer than 4 coarse cells
  EXPECT_THROW(precompute_wake(outside), ship_lrm::ConfigError);
  EXPECT_FALSE(fs::exists(outside.out));
}
