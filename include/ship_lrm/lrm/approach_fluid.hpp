// The fluid side of the ship approach (thesis 9.1; what the LrmSolver nodelet runs):
// the LRM domain fixed to the rotor, fed at its faces by the wake table, holding the fuselage, the
// moving ship and the sea as walls. It answers the flight side's InflowRequests (inflow_link.hpp):
// before it takes a request's loads it places walls and faces for the request's table time and
// domain pose, once per time; the one-process path places them eagerly at the same times, so the
// domain sees the same operations in the same order either way.
#pragma once
#include <atomic>
#include <memory>

#include "ship_lrm/lrm/approach_config.hpp"
#include "ship_lrm/lrm/inflow_link.hpp"
#include "ship_lrm/lrm/lrm_inflow.hpp"
#include "ship_lrm/lrm/ship_walls.hpp"
#include "ship_lrm/lrm/wake_feed.hpp"

namespace ship_lrm::lrm {

class ApproachFluid {
 public:
  // table: the approach's table when the caller holds it open already; else it is opened here.
  ApproachFluid(const ApproachConfig& cfg, const flight::HelicopterParameters& params, std::shared_ptr<wake::WakeTable> table = nullptr);
  // Walls and faces for table time t and the domain's pose (no-op when already placed for t).
  void place(double table_time, const DomainPose& pose);
  // Places for the request, then resets or advances the LRM with its loads; the inflow over the disk.
  // A request that covers several LBM steps (a real-time job that had fallen behind the wall clock
  // and now catches up) runs them one at a time: walls and faces are placed at each step's time,
  // with the pose, the table time and the rotor's motion interpolated between the previous request
  // and this one, so that a moving ship is re-voxelised as often as in simulated time.
  rotor::RotorInflow serve(const InflowRequest& request);

  // Real time: at most this many LBM steps per request, the rest of a backlog dropped (LrmInflow).
  void set_catch_up_limit(long steps) { lrm_.set_catch_up_limit(steps); }
  long dropped_steps() const { return lrm_.dropped_steps(); }

  LrmDomain& domain() { return lrm_.domain(); }
  std::size_t voxelisations() const { return walls_ ? walls_->voxelisations() : 0; }
  std::size_t face_refreshes() const { return face_refreshes_; }

  // The LRM's wall cells, the ship's voxelisations, the face refreshes and the changes of the wall
  // cells (those next to the faces restart the flow; LrmDomain::update_walls) with the wall-clock
  // time spent placing walls, as of the last request served, readable from any thread (in real time
  // the LRM thread serves while the flight side reports; it must not touch the domain).
  struct Counts {
    std::size_t wall_cells = 0, voxelisations = 0, face_refreshes = 0, wall_changes = 0, face_restarts = 0;
    double wall_seconds = 0;
  };
  Counts counts() const;

 private:
  std::shared_ptr<wake::WakeTable> table_;
  LrmInflow lrm_;
  std::unique_ptr<ShipInDomain> walls_;
  std::unique_ptr<WakeFaceFeed> feed_;
  bool rotor_forces_on_fluid_ = true;                                 // ApproachConfig::rotor_forces_on_fluid
  rotor::RotorDiskState loads(const rotor::RotorDiskState& s) const;  // s, without its loads where they stay off the fluid
  bool placed_ = false;
  double placed_time_ = 0;
  DomainPose placed_pose_;
  rotor::RotorDiskState last_state_;  // the previous request's
  std::size_t face_refreshes_ = 0;
  std::atomic<std::size_t> served_wall_cells_{0}, served_voxelisations_{0}, served_face_refreshes_{0};  // counts()
  std::atomic<std::size_t> served_wall_changes_{0}, served_face_restarts_{0};
  std::atomic<double> served_wall_seconds_{0};
};

// A link that calls a fluid side in the same process (the batch path).
class DirectLink final : public InflowLink {
 public:
  explicit DirectLink(std::shared_ptr<ApproachFluid> fluid) : fluid_(std::move(fluid)) {}
  rotor::RotorInflow exchange(const InflowRequest& request) override { return fluid_->serve(request); }

 private:
  std::shared_ptr<ApproachFluid> fluid_;
};

}  // namespace ship_lrm::lrm
