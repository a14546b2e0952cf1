// The flight model's side of a linked rotor <-> LRM coupling (see inflow_link.hpp).
#include "ship_lrm/lrm/inflow_link.hpp"

namespace ship_lrm::lrm {

LinkedInflow::LinkedInflow(std::shared_ptr<InflowLink> link, Placement placement)
    : link_(std::move(link)), placement_(std::move(placement)) {
  if (!link_ || !placement_) throw std::invalid_argument("LinkedInflow: a link and a placement are needed");
}

void LinkedInflow::exchange(InflowRequest& request) {
  if (!lost_) {
    request.sequence = sequence_++;
    placement_(request.state, request.pose, request.table_time);
    try {
      served_ = link_->exchange(request);
      return;
    } catch (const LinkLost& e) {
      lost_reason_ = e.what();
      lost_.store(true, std::memory_order_release);
    }
  }
  ++fallback_calls_;
  served_ = fallback_.inflow();
}

void LinkedInflow::reset(const rotor::RotorDiskState& state) {
  fallback_.reset(state);
  InflowRequest r;
  r.kind = InflowRequest::Kind::Reset;
  r.state = state;
  exchange(r);
}

void LinkedInflow::advance(const rotor::RotorDiskState& state, double dt) {
  fallback_.advance(state, dt);  // always current, whatever the fluid side does
  InflowRequest r;
  r.kind = InflowRequest::Kind::Advance;
  r.state = state;
  r.dt = dt;
  exchange(r);
}

}  // namespace ship_lrm::lrm
