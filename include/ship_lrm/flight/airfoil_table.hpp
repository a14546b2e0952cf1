// Section polar over angle of attack (-180..180 deg) and Mach number: bilinear table lookup.
#pragma once

#include <string>
#include <vector>

namespace ship_lrm::flight {

struct SectionCoefficients {
  double cl, cd, cm;
};

class AirfoilTable {
 public:
  AirfoilTable() = default;
  // alpha_deg ascending, equally spaced, covering [-180, 180]; mach ascending; tables [mach][alpha].
  AirfoilTable(std::string name, std::vector<double> alpha_deg, std::vector<double> mach, std::vector<std::vector<double>> cl,
               std::vector<std::vector<double>> cd, std::vector<std::vector<double>> cm);

  // alpha in radians (any value: wrapped to (-pi, pi]); Mach clamped to the table's range.
  SectionCoefficients lookup(double alpha, double mach) const;
  const std::string& name() const { return name_; }
  bool empty() const { return alpha_count_ == 0; }

 private:
  std::string name_;
  double alpha_first_ = 0, alpha_step_inv_ = 0;  // radians
  int alpha_count_ = 0;
  std::vector<double> mach_;
  std::vector<double> data_;  // [mach][alpha][3]
};

// Reads a polar YAML (keys name, alpha_deg, mach, cl, cd, cm); throws ParameterError.
AirfoilTable load_airfoil_table(const std::string& path);

}  // namespace ship_lrm::flight
