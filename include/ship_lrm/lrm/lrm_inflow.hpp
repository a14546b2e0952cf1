// The LRM domain as the flight model's inflow model (thesis 5.2, 6.5, fig. 5.5): every coupling step
// the rotor's aerodynamic force harmonics go into the domain, the domain advances to the flight
// model's time, and the inflow over the disk comes back. Drop-in replacement for Pitt-Peters
// behind rotor::InflowModel.
//
// Frame: the domain is fixed to the rotor's mr frame, so it translates and rotates with the
// rotorcraft (LrmDomain::Motion). Its faces get the air velocity relative to the moving grid
// (-hub_velocity - omega x r). The frame's angular acceleration and the hub's acceleration come from
// differences between coupling steps. The inflow read back is relative to the rotating mr frame, as
// the interface asks.
#pragma once

#include <memory>

#include "ship_lrm/lrm/domain.hpp"
#include "ship_lrm/rotor/inflow_model.hpp"

namespace ship_lrm::lrm {

// Wall-clock seconds spent in each part of the coupling steps (advance() only, not the warm-up),
// for the benchmark's breakdown: what a faster LBM kernel cannot remove.
struct CouplingTimes {
  double motion = 0;  // domain motion: face velocities and frame forces to the solver
  double forces = 0;  // rotor force harmonics to the disk cells' forces
  double lbm = 0;     // the LBM steps (the device synchronised with set_time_parts(true), else their launch only)
  double inflow = 0;  // disk velocities back and their harmonics (else with the wait for the LBM steps)
};

class LrmInflow final : public rotor::InflowModel {
 public:
  // warm_up: simulated seconds run at the first reset() so the wake develops.
  explicit LrmInflow(const LrmConfig& cfg, double warm_up = 3.0);
  std::string name() const override { return "lrm"; }
  // First call: start the flow with this state's stream and loads and run the warm-up. Later calls
  // keep the developed flow (its wake is the state to keep) and only take the new loads.
  void reset(const rotor::RotorDiskState& state) override;
  void advance(const rotor::RotorDiskState& state, double dt) override;
  rotor::RotorInflow inflow() const override { return inflow_; }
  bool needs_harmonics() const override { return true; }

  // LBM steps an advance(state, dt) would run now (0 before the first reset), before the catch-up limit.
  long steps_due(double dt) const;
  // Real time only: an advance runs at most `steps` LBM steps (0: no limit, the default). A longer one
  // (the LRM thread has fallen behind the wall clock) drops the rest of its backlog: the domain's clock
  // jumps to the flight model's time with the flow as it is, and the dropped steps are counted.
  // Otherwise a slow LRM gets ever longer jobs, runs ever further behind, and its walls and faces jump.
  void set_catch_up_limit(long steps) { catch_up_limit_ = steps > 0 ? steps : 0; }
  long catch_up_limit() const { return catch_up_limit_; }
  // Moves the flight-model time on by dt without stepping the flow (the dropped part of a backlog).
  void skip(double dt);
  long dropped_steps() const { return dropped_steps_; }

  LrmDomain& domain() { return domain_; }
  long lbm_steps() { return domain_.solver().steps_done(); }
  const CouplingTimes& times() const { return times_; }
  // Wait for the device after the LBM steps, so that times() tells the LBM steps from the inflow's
  // read-back. Off by default: the read-back waits for them anyway, and on a GPU the extra
  // synchronisation is a round trip per coupling step (the benchmark measures both ways).
  void set_time_parts(bool on) { time_parts_ = on; }

 private:
  void take(const rotor::RotorDiskState& s, CouplingTimes* times = nullptr);
  CouplingTimes times_;
  LrmDomain domain_;
  double warm_up_;
  bool started_ = false;
  double time_ = 0;  // flight-model time reached by the inflow model
  long catch_up_limit_ = 0, dropped_steps_ = 0;
  bool time_parts_ = false;
  rotor::RotorInflow inflow_;
  // previous coupling step's kinematics, for the accelerations
  bool have_previous_ = false;
  double previous_time_ = 0;
  Vec3 previous_velocity_ = Vec3::Zero(), previous_rate_ = Vec3::Zero();
};

}  // namespace ship_lrm::lrm
