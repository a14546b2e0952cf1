// The fluid side of the ship approach (see approach_fluid.hpp).
#include "ship_lrm/lrm/approach_fluid.hpp"

#include "ship_lrm/lrm/walls.hpp"

namespace ship_lrm::lrm {

ApproachFluid::ApproachFluid(const ApproachConfig& cfg, const flight::HelicopterParameters& params, std::shared_ptr<wake::WakeTable> table)
    : table_(table ? std::move(table) : open_approach_table(cfg)),
      lrm_(approach_lrm_config(cfg, params, table_->info()), 0.0)  // the start-up is part of the run (thesis 9.1)
{
  if (cfg.fuselage) lrm_.domain().add_wall(std::make_shared<Fuselage>());
  if (cfg.ship_walls) {
    const ApproachShip ship = approach_ship(cfg, table_->info());
    walls_ = std::make_unique<ShipInDomain>(ship.geometry, ship.motion);
  }
  if (cfg.wake) feed_ = std::make_unique<WakeFaceFeed>(table_);
}

void ApproachFluid::place(double table_time, const DomainPose& pose) {
  if (placed_ && table_time == placed_time_) return;
  if (walls_) walls_->apply(lrm_.domain(), table_time, pose);
  if (feed_ && feed_->apply(lrm_.domain(), table_time, pose)) ++face_refreshes_;
  placed_ = true;
  placed_time_ = table_time;
}

rotor::RotorInflow ApproachFluid::serve(const InflowRequest& request) {
  place(request.table_time, request.pose);
  if (request.kind == InflowRequest::Kind::Reset)
    lrm_.reset(request.state);
  else
    lrm_.advance(request.state, request.dt);
  return lrm_.inflow();
}

}  // namespace ship_lrm::lrm
