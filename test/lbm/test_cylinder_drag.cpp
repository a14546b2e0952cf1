// 9. Published 3-D bluff-body benchmark: Schaefer & Turek 1996 case 3D-1Z (steady flow around a
// cylinder in a square channel, Re = 20); reference c_D = 6.18533 (Bayraktar, Mierka & Turek
// 2012). Quick variant: 10 cells per diameter (the full variant, 20 cells, is
// `ship_lrm validate cylinder --resolution 20`).
#include <gtest/gtest.h>

#include "ship_lrm/lbm/cylinder_benchmark.hpp"

using namespace ship_lrm::lbm;

TEST(BluffBody, SchaeferTurek3D1ZDragWithin5Percent) {
  const auto r = run_cylinder_benchmark(10, Backend::Cpu, 60000, 1e-3);
  RecordProperty("drag_coefficient", std::to_string(r.drag_coefficient));
  std::printf("c_D = %.4f (reference %.5f), c_L = %.4f, %ld steps, %.0f s\n", r.drag_coefficient, kSchaeferTurek3D1ZDrag,
              r.lift_coefficient, r.steps, r.seconds);
  EXPECT_LT(r.relative_change, 1e-3) << "not converged";
  EXPECT_NEAR(r.drag_coefficient / kSchaeferTurek3D1ZDrag, 1.0, 0.05);
}
