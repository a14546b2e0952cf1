// The flight model's end of a linked rotor <-> LRM coupling (inflow_link.hpp; fault check:
// a fluid side that stops answering makes the flight model fall back to Pitt-Peters, no crash).
#include <gtest/gtest.h>

#include "lrm_test_config.hpp"
#include "ship_lrm/lrm/inflow_link.hpp"

using namespace ship_lrm;
using ship_lrm::Vec3;

namespace {

rotor::RotorDiskState state_at(int k, double dt) { return lrm::test::disk_state_at(k, dt); }

// Answers `answers` requests with an inflow that encodes the request, then is gone.
class FailingLink final : public lrm::InflowLink {
 public:
  explicit FailingLink(int answers) : answers_(answers) {}
  rotor::RotorInflow exchange(const lrm::InflowRequest& r) override {
    requests.push_back(r);
    if (static_cast<int>(requests.size()) > answers_) throw lrm::LinkLost("the LRM solver did not answer within 1 s");
    rotor::RotorInflow in;
    in.mean = Vec3(r.state.time, r.dt, r.table_time);
    in.sine = r.pose.hub;
    return in;
  }
  std::vector<lrm::InflowRequest> requests;

 private:
  int answers_;
};

}  // namespace

TEST(InflowLink, RequestsCarryThePlacementAndAnswersAreServedUntilTheLinkIsLost) {
  const double dt = 0.01;
  auto link = std::make_shared<FailingLink>(4);  // the reset and 3 advances
  lrm::LinkedInflow linked(link, [](const rotor::RotorDiskState& s, lrm::DomainPose& pose, double& table_t) {
    const double t = s.time;
    pose.hub = Vec3(100 * t, 0, -8);
    table_t = 3.0 + t;
  });
  rotor::PittPetersInflow pp;  // the reference for the fallback, fed the same states
  linked.reset(state_at(0, dt));
  pp.reset(state_at(0, dt));
  EXPECT_EQ(linked.inflow().mean, Vec3(0, 0, 3.0));
  for (int k = 0; k < 10; ++k) {
    linked.advance(state_at(k, dt), dt);
    pp.advance(state_at(k, dt), dt);
    if (k < 3) {
      EXPECT_FALSE(linked.lost());
      EXPECT_EQ(linked.inflow().mean, Vec3(k * dt, dt, 3.0 + k * dt)) << "step " << k;
      EXPECT_EQ(linked.inflow().sine, Vec3(100 * k * dt, 0, -8)) << "step " << k;
    } else {
      ASSERT_TRUE(linked.lost());
      EXPECT_NE(linked.lost_reason().find("did not answer"), std::string::npos);
      // Pitt-Peters ran alongside from the start: its current inflow, not a restarted one
      EXPECT_EQ(linked.inflow().mean, pp.inflow().mean) << "step " << k;
      EXPECT_EQ(linked.inflow().cosine, pp.inflow().cosine) << "step " << k;
    }
  }
  EXPECT_EQ(linked.fallback_calls(), 7);
  // a lost link is not asked again; the requests it got were numbered in order
  ASSERT_EQ(link->requests.size(), 5u);
  for (std::size_t i = 0; i < link->requests.size(); ++i) EXPECT_EQ(link->requests[i].sequence, static_cast<long>(i));
  EXPECT_EQ(link->requests[0].kind, lrm::InflowRequest::Kind::Reset);
  EXPECT_EQ(link->requests[1].kind, lrm::InflowRequest::Kind::Advance);
}
