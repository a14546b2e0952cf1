// Harmonic representation of the rotor's aerodynamic force over azimuth (thesis 6.5): each blade's
// force is recorded at N_psi = 72 azimuth samples per revolution as the blades pass them; the
// coefficients follow from
//   cos_k = (2 / N_psi) sum_blades sum_j F_i(psi_j) cos(k psi_j),  sin_k likewise with sin, k >= 1
//   cos_0 = (1 / N_psi) sum_blades sum_j F_i(psi_j)   (the mean total force; the thesis' factor 2 is for k >= 1)
#pragma once

#include <array>
#include <vector>

#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::rotor {

class AzimuthForceRecord {
 public:
  explicit AzimuthForceRecord(int blades = 4);
  // Record blade `blade`'s force at geometric azimuth psi (rad, any value). Samples skipped since
  // that blade's previous deposit are filled by linear interpolation.
  void deposit(int blade, double psi, const Vec3& force);
  // Fill every sample of every blade with the same force distribution (start-up / steady state).
  void fill(const std::vector<Vec3>& per_blade_force);
  RotorForceHarmonics harmonics() const;
  int blades() const { return static_cast<int>(samples_.size()); }

 private:
  std::vector<std::array<Vec3, kAzimuthSamples>> samples_;
  std::vector<int> last_bin_;
  std::vector<Vec3> last_force_;
};

}  // namespace ship_lrm::rotor
