// A wake table served by the WakeServer nodelet (see served_wake_table.hpp).
#include "ship_lrm/ros/served_wake_table.hpp"

#include <ros/service.h>

#include <algorithm>
#include <mutex>

#include "ship_lrm/WakeWindow.h"

namespace ship_lrm::ros_layer {
namespace {

class ServiceWindowSource final : public wake::WindowSource {
 public:
  ServiceWindowSource(std::string service, std::string path) : service_(std::move(service)), path_(std::move(path)) {}
  // Called by the table (and its read-ahead thread): one call at a time, each a service round trip.
  bool read(int frame, const std::array<int, 3>& lo, const std::array<int, 3>& n, float* velocity, float* density) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    ship_lrm::WakeWindow w;
    w.request.frame = frame;
    for (int d = 0; d < 3; ++d) {
      w.request.lo[d] = lo[d];
      w.request.n[d] = n[d];
    }
    const std::size_t points = static_cast<std::size_t>(n[0]) * n[1] * n[2];
    // (at once when the server is up; a server that is starting or restarting gets a few seconds)
    if (!ros::service::waitForService(service_, ros::Duration(10.0))) {
      last_error_ = "the service " + service_ + " is not there";
      return false;
    }
    if (!ros::service::call(service_, w)) {
      last_error_ = "the service " + service_ + " did not answer";
      return false;
    }
    if (!w.response.ok || w.response.velocity.size() != 3 * points || w.response.density.size() != points) {
      last_error_ = w.response.ok ? "the answer has the wrong size" : w.response.message;
      return false;
    }
    std::copy(w.response.velocity.begin(), w.response.velocity.end(), velocity);
    std::copy(w.response.density.begin(), w.response.density.end(), density);
    return true;
  }
  std::string name() const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return "wake table '" + path_ + "' served on " + service_ + (last_error_.empty() ? "" : " (" + last_error_ + ")");
  }

 private:
  std::string service_, path_, last_error_;
  mutable std::mutex mutex_;
};

}  // namespace

std::shared_ptr<wake::WakeTable> served_wake_table(const ship_lrm::WakeInfo& m, const ros::NodeHandle& nh, const std::string& service) {
  wake::WakeTableInfo info;
  info.origin = {m.origin.x, m.origin.y, m.origin.z};
  info.spacing = m.spacing;
  info.shape = {m.shape[0], m.shape[1], m.shape[2]};
  info.frame_interval = m.frame_interval;
  info.start_time = m.start_time;
  info.frames = m.frames;
  info.free_stream = {m.free_stream.x, m.free_stream.y, m.free_stream.z};
  info.free_density = m.free_density;
  info.ship = m.ship;
  info.scale = m.scale;
  info.motion = m.motion;
  info.half_precision = false;  // (what the file stores; the windows arrive as float32 either way)
  return std::make_shared<wake::WakeTable>(info, std::make_unique<ServiceWindowSource>(nh.resolveName(service), m.path));
}

}  // namespace ship_lrm::ros_layer
