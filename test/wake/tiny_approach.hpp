// The approach tests' set-up: the tiny wake table (full-scale NatoGD at rest, 20.58 m/s, 2 s of
// frames; `ship_lrm wake --preset tiny`), made once per test process, and an approach on it.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "ship_lrm/lrm/approach_config.hpp"
#include "ship_lrm/lrm/approach_fluid.hpp"
#include "ship_lrm/wake/wake_precompute.hpp"
#include "temp_path.hpp"

namespace ship_lrm::test {

inline const std::string& tiny_table() {
  static const std::string path = [] {
    wake::PrecomputeOptions o = wake::preset("tiny");
    o.out = temp_path("ship_lrm_test_approach", "tiny.h5");
    o.domain.backend = lbm::Backend::Cpu;
    wake::precompute_wake(o);
    return o.out;
  }();
  return path;
}

// An approach on the tiny table: no start-up, the LRM at N = 16 on the CPU.
inline lrm::ApproachConfig tiny_approach(const std::string& inflow, double duration) {
  lrm::ApproachConfig c;
  c.table = tiny_table();
  c.inflow = inflow;
  c.duration = duration;
  c.startup = 0.0;
  c.lrm.nodes = 16;
  c.lrm.backend = lbm::Backend::Cpu;
  return c;
}

// Forwards every request to a fluid side in this process and keeps them.
class RecordingLink final : public lrm::InflowLink {
 public:
  explicit RecordingLink(std::shared_ptr<lrm::ApproachFluid> fluid) : fluid_(std::move(fluid)) {}
  rotor::RotorInflow exchange(const lrm::InflowRequest& r) override {
    requests.push_back(r);
    return fluid_->serve(r);
  }
  std::vector<lrm::InflowRequest> requests;

 private:
  std::shared_ptr<lrm::ApproachFluid> fluid_;
};

}  // namespace ship_lrm::test
