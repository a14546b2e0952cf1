// A nested wake table's two levels served as one grid (docs/design.md, "A fine region by one-way
// nesting"). The served grid has the fine level's spacing over the coarse level's box: served point v
// is coarse point v / ratio. Its value is the coarse field interpolated trilinearly there (which,
// outside the fine box, is exactly what the coarse table gives: trilinear interpolation on a refined
// trilinear field reproduces it), and inside the fine box the fine value blended in:
//   u = u_coarse + b (u_fine - u_coarse),  b = min(1, d / (seam_cells ratio)),
// d the served cells to the nearest blended face of the fine box. At a blended face b = 0, so the
// served field is continuous across the seam: an LRM face sweeping through it sees no step, only
// the difference between the levels spread over seam_cells coarse cells (checked by
// NestedTable.TheSeamIsContinuousAndSpreadOverItsBand and on a real nested precompute by
// NestedTable.ANestedPrecomputeIsServedWithoutASeam).
#pragma once
#include <array>
#include <memory>
#include <string>

#include "ship_lrm/wake/wake_table.hpp"

namespace ship_lrm::wake {

// The stored levels of a nested table, read by box: level 0 the coarse grid, level 1 the fine one;
// box [lo, lo + n) of that level's points, velocity 3 per point and density, x fastest.
class LevelSource {
 public:
  virtual ~LevelSource() = default;
  virtual bool read(int level, int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* velocity, float* density) = 0;
  virtual std::string name() const = 0;
};

// TableError naming `name` when the fine level does not nest in the coarse grid (ratio, box, seam).
void check_levels(const WakeTableInfo& stored, const std::string& name);

// The served grid of a stored nested table (its fine level kept in `fine`); a single-level table as it is.
WakeTableInfo served_grid(const WakeTableInfo& stored);

// The weight of the fine level at served point v (0 outside the fine box, 1 past its seam band).
double fine_weight(const WakeTableInfo& stored, const std::array<int, 3>& v);

// The windows of the served grid, composed from the levels.
std::unique_ptr<WindowSource> nested_window_source(std::unique_ptr<LevelSource> levels, const WakeTableInfo& stored);

}  // namespace ship_lrm::wake
