#include "families/p2os/driver/p2os_device_driver.hpp"

#include <utility>

namespace playerkit::drivers::p2os {

P2osDeviceDriver::P2osDeviceDriver(P2osRole role, std::shared_ptr<P2osConnection> connection,
                                   MotorLimits limits)
    : role_(role), connection_(std::move(connection)), limits_(limits) {}

P2osDeviceDriver::~P2osDeviceDriver() {
  // The device shuts its driver down first; this covers a driver destroyed
  // without it, so the connection never keeps a dangling device.
  if (use_) {
    connection_->remove_device(device());
    use_ = {};
  }
}

void P2osDeviceDriver::setup() {
  core::SharedConnection::Use use = connection_->attach();  // the first one opens the robot
  connection_->add_device(role_, device(), limits_);        // throws while the robot is away
  use_ = std::move(use);
}

void P2osDeviceDriver::shutdown() {
  if (!use_) return;
  connection_->remove_device(device());
  use_ = {};  // the last one stops the robot and closes the line
}

core::RequestResult P2osDeviceDriver::handle_request(const core::Request& request) {
  return connection_->handle_request(role_, request);
}

std::vector<core::DriverCounter> P2osDeviceDriver::counters() const { return connection_->counters(); }

bool P2osDeviceDriver::set_byte_trace(core::ByteTrace trace) {
  connection_->set_byte_trace(std::move(trace));
  return true;
}

}  // namespace playerkit::drivers::p2os
