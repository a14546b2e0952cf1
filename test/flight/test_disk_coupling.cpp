// Rotor disk on the lattice (thesis 6.5): area fractions, force imposition and inflow extraction.
#include <gtest/gtest.h>

#include <cmath>

#include "ship_lrm/lbm/column_series.hpp"
#include "ship_lrm/rotor/disk_coupling.hpp"

using namespace ship_lrm::rotor;
using ship_lrm::Vec3;

TEST(DiskCoupling, ClippedAreaOfSquaresAndTriangles) {
  const std::vector<std::array<double, 2>> tri = {{0, 0}, {2, 0}, {0, 2}};
  EXPECT_NEAR(clipped_area(tri, 0, 1, 0, 1), 1.0, 1e-14);    // unit square fully inside
  EXPECT_NEAR(clipped_area(tri, 1, 2, 0, 1), 0.5, 1e-14);    // half of it
  EXPECT_NEAR(clipped_area(tri, 3, 4, 3, 4), 0.0, 1e-14);    // outside
  EXPECT_NEAR(clipped_area(tri, -5, 5, -5, 5), 2.0, 1e-14);  // the whole triangle
}

class DiskSizes : public ::testing::TestWithParam<double> {};

TEST_P(DiskSizes, FractionsAddUpToThePolygonArea) {
  const double radius = GetParam();  // in cells: N = 32 and 64 per 4R give R = 7.75 and 15.75
  const int n = static_cast<int>(2 * radius) + 6;
  const double c = 0.5 * (n - 1);
  const DiskCoupling disk(n, n, c, c, radius, 360);
  const double polygon = 0.5 * 360 * radius * radius * std::sin(2 * M_PI / 360);
  EXPECT_NEAR(disk.area(), polygon, 1e-9 * polygon);
  EXPECT_NEAR(disk.area(), M_PI * radius * radius, 1e-4 * M_PI * radius * radius);
  for (const auto& cell : disk.cells()) {
    EXPECT_GT(cell.fraction, 0);
    EXPECT_LE(cell.fraction, 1 + 1e-12);
  }
}

TEST_P(DiskSizes, ImposedForceSumsToTheMeanAndExtractionInvertsTheHarmonics) {
  const double radius = GetParam();
  const int n = static_cast<int>(2 * radius) + 6;
  const double c = 0.5 * (n - 1) + 0.3;  // off-centre: the grid is not symmetric about the disk
  const DiskCoupling disk(n, n, c, c - 0.2, radius, 360);
  RotorForceHarmonics h;
  h.cos[0] = Vec3(100, -50, -24525);
  h.cos[1] = Vec3(10, 20, 3000);
  h.sin[1] = Vec3(-5, 0, 1500);
  h.cos[4] = Vec3(0, 0, 800);
  Vec3 total = Vec3::Zero();
  for (const Vec3& f : disk.cell_forces(h)) total += f;
  // the harmonics k >= 1 integrate to (nearly) zero over the disk; the mean comes through
  EXPECT_LT((total - h.cos[0]).norm(), 2e-3 * h.cos[0].norm()) << total.transpose();
  // a velocity field of exactly the extracted form is recovered exactly
  const Vec3 mean(-20, 1, 11.6), sine(0.5, 0, 2.0), cosine(0, -0.3, 4.0);
  const auto field = [&](size_t k) {
    const double dx = disk.cells()[k].i - c, dy = disk.cells()[k].j - (c - 0.2);
    const double r = std::hypot(dx, dy) / radius, psi = std::atan2(dy, -dx);
    return Vec3(mean + sine * (r * std::sin(psi)) + cosine * (r * std::cos(psi)));
  };
  const RotorInflow in = disk.extract(field);
  EXPECT_LT((in.mean - mean).norm(), 1e-9);
  EXPECT_LT((in.sine - sine).norm(), 1e-9);
  EXPECT_LT((in.cosine - cosine).norm(), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Radii, DiskSizes, ::testing::Values(7.75, 15.75, 31.75));

TEST(DiskCoupling, AzimuthConvention) {
  // psi is measured from aft (-x) towards starboard (+y): the cell ahead of the hub is psi = 180 deg,
  // the one to starboard 90 deg.
  const DiskCoupling disk(41, 41, 20, 20, 10.0);
  for (const auto& c : disk.cells()) {
    if (c.i == 30 && c.j == 20) EXPECT_NEAR(std::abs(c.psi), M_PI, 1e-12);
    if (c.i == 20 && c.j == 30) EXPECT_NEAR(c.psi, M_PI / 2, 1e-12);
    if (c.i == 10 && c.j == 20) EXPECT_NEAR(c.psi, 0, 1e-12);
  }
  EXPECT_THROW(DiskCoupling(20, 20, 10, 10, 12.0), std::invalid_argument);  // does not fit
}

TEST(DiskCoupling, CellForcesAreTheHarmonicSeriesAtEachCell) {
  // thesis 6.5: the force of a cell is F(psi) eps / A with F(psi) = c_0 + sum_k (c_k cos k psi +
  // s_k sin k psi), k = 1..9, here summed directly at each cell's azimuth with every harmonic set
  const DiskCoupling disk(36, 36, 17.5, 17.3, 15.75, 360);
  RotorForceHarmonics h;
  h.cos[0] = Vec3(120, -40, -24525);
  for (int k = 1; k <= kHarmonicOrder; ++k) {
    h.cos[k] = Vec3(3.0 * k, -2.0 * k, 900.0 / k);
    h.sin[k] = Vec3(-1.5 * k, 4.0, -600.0 / k);
  }
  const std::vector<Vec3> f = disk.cell_forces(h);
  // what the lattice sums (Solver::set_cell_force_columns): float columns and coefficients
  const double scale = -2.5e-9;  // the coupled step's newtons per cell to lattice force density (N = 64)
  const std::vector<float> columns = disk.force_columns();
  std::vector<float> coefficients;
  disk.force_coefficients(h, scale, coefficients);
  const std::size_t n = disk.cells().size();
  ASSERT_EQ(f.size(), n);
  ASSERT_EQ(columns.size(), DiskCoupling::kForceColumns * n);
  ASSERT_EQ(coefficients.size(), 3u * DiskCoupling::kForceColumns);
  std::vector<float> sums(3 * n);
  ship_lrm::lbm::column_series(columns.data(), n, 0, n, DiskCoupling::kForceColumns, coefficients.data(), sums.data(), n);
  double worst = 0, worst_scaled = 0;
  for (size_t c = 0; c < f.size(); ++c) {
    const DiskCell& cell = disk.cells()[c];
    Vec3 F = h.cos[0];
    for (int k = 1; k <= kHarmonicOrder; ++k) F += h.cos[k] * std::cos(k * cell.psi) + h.sin[k] * std::sin(k * cell.psi);
    const Vec3 expected = F * (cell.fraction / disk.area());
    worst = std::max(worst, (f[c] - expected).norm() / expected.norm());
    for (int d = 0; d < 3; ++d)
      worst_scaled = std::max(worst_scaled, std::abs(sums[d * n + c] - scale * expected[d]) / std::abs(scale * expected.norm()));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_scaled, 2e-6);  // float's rounding of 19 columns and their sum
}
