// The flight model's side of a rotor <-> LRM coupling whose fluid runs elsewhere (docs/design.md,
// the ROS FlightModel and LrmSolver nodelets; the batch tool in one process). Every call the flight
// model makes on its inflow model (thesis 6.5, fig. 5.5: rotor state and force harmonics in, inflow
// out) becomes one InflowRequest handed to an InflowLink, which returns the fluid's answer. The
// request also carries where the domain is and the wake table's time, so the fluid side can place
// its walls and faces exactly as the one-process path does; the same request through the ROS
// messages (all float64) and through a direct call therefore gives bit-identical loads.
//
// When the link is lost (the fluid does not answer: its node died, its deadline passed), the model
// serves the Pitt-Peters inflow from then on. Pitt-Peters runs alongside at every call, so its state
// is current when it takes over (as RealTimeInflow's fallback).
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "ship_lrm/lrm/ship_walls.hpp"
#include "ship_lrm/rotor/inflow_model.hpp"
#include "ship_lrm/rotor/pitt_peters.hpp"

namespace ship_lrm::lrm {

struct InflowRequest {
  enum class Kind { Reset, Advance };
  Kind kind = Kind::Advance;
  long sequence = 0;            // 0, 1, 2, ... per link: the answer names the request it answers
  rotor::RotorDiskState state;  // the rotor's state and loads (state.time: flight-model time)
  double dt = 0;                // s, Advance: advance the fluid over [state.time, state.time + dt]
  double table_time = 0;        // s, the wake table's time that belongs to state.time
  DomainPose pose;              // where the domain is at state.time (mean frame)
};

// Thrown by a link whose fluid side is gone; LinkedInflow then falls back to Pitt-Peters.
class LinkLost : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InflowLink {
 public:
  virtual ~InflowLink() = default;
  // The fluid side's inflow for this request; LinkLost when it cannot answer.
  virtual rotor::RotorInflow exchange(const InflowRequest& request) = 0;
};

class LinkedInflow final : public rotor::InflowModel {
 public:
  // placement(state): the domain's pose and the table time for the rotor state (at its time).
  using Placement = std::function<void(const rotor::RotorDiskState& state, DomainPose& pose, double& table_time)>;
  LinkedInflow(std::shared_ptr<InflowLink> link, Placement placement);
  std::string name() const override { return "lrm"; }
  void reset(const rotor::RotorDiskState& state) override;
  void advance(const rotor::RotorDiskState& state, double dt) override;
  rotor::RotorInflow inflow() const override { return served_; }
  bool needs_harmonics() const override { return true; }

  // Safe to read from another thread (the real-time LRM thread calls this model): lost_reason() is
  // written once, before lost() turns true.
  bool lost() const { return lost_.load(std::memory_order_acquire); }
  const std::string& lost_reason() const { return lost_reason_; }
  long fallback_calls() const { return fallback_calls_.load(); }  // calls served by Pitt-Peters

 private:
  void exchange(InflowRequest& request);
  std::shared_ptr<InflowLink> link_;
  Placement placement_;
  rotor::PittPetersInflow fallback_;
  rotor::RotorInflow served_;
  long sequence_ = 0;
  std::atomic<long> fallback_calls_{0};
  std::atomic<bool> lost_{false};
  std::string lost_reason_;
};

}  // namespace ship_lrm::lrm
