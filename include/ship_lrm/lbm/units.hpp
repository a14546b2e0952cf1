// Physical <-> lattice unit conversion (thesis 6.1.2 and tables 6.2-6.4; like OpenLB's
// UnitConverter, Krause et al. 2021). A domain is characterised by a reference length l_ref
// resolved by N lattice nodes (N - 1 cells across l_ref, the thesis' convention: it reproduces
// the LRM time step of 1.80352 ms at N = 64), a physical reference velocity mapped to the lattice
// reference velocity (0.3 / sqrt(3) in the thesis), the kinematic viscosity and the density.
#pragma once

namespace ship_lrm::lbm {

struct UnitReference {
  double length = 1.0;                            // l_ref [m]
  int nodes = 64;                                 // N: lattice nodes across l_ref
  double velocity = 1.0;                          // u_ref [m/s]
  double viscosity = 1.5e-5;                      // nu [m^2/s]
  double density = 1.225;                         // rho [kg/m^3]
  double lattice_velocity = 0.17320508075688773;  // u_ref in lattice units (0.3 / sqrt(3))
};

class UnitConverter {
 public:
  // Throws ConfigError for non-positive values or a lattice velocity above the Mach limit.
  explicit UnitConverter(const UnitReference& ref);

  const UnitReference& reference() const { return ref_; }
  double dx() const { return dx_; }  // [m]
  double dt() const { return dt_; }  // [s]
  double lattice_viscosity() const { return ref_.viscosity * dt_ / (dx_ * dx_); }
  double relaxation_time() const { return 3.0 * lattice_viscosity() + 0.5; }
  double to_lattice_velocity(double u) const { return u * dt_ / dx_; }
  double to_physical_velocity(double u) const { return u * dx_ / dt_; }
  double to_lattice_length(double l) const { return l / dx_; }
  double to_lattice_time(double t) const { return t / dt_; }
  // Force density [N/m^3] -> lattice force density.
  double to_lattice_force_density(double f) const { return f * dt_ * dt_ / (ref_.density * dx_); }
  // Lattice density -> physical pressure deviation p - p_ref [Pa] (p = cs^2 rho).
  double to_physical_pressure(double rho_lattice) const { return (rho_lattice - 1.0) / 3.0 * ref_.density * dx_ * dx_ / (dt_ * dt_); }
  double mach_number() const;  // lattice reference velocity / c_s

 private:
  UnitReference ref_;
  double dx_ = 0, dt_ = 0;
};

}  // namespace ship_lrm::lbm
