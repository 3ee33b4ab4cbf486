#include "families/reb/driver/reb_device_driver.hpp"

namespace playerkit::drivers::reb {

RebDeviceDriver::RebDeviceDriver(RebRole role, std::shared_ptr<RebConnection> connection, bool heading_control)
    : role_(role), connection_(std::move(connection)), heading_control_(heading_control) {}

RebDeviceDriver::~RebDeviceDriver() {
  // A driver destroyed without its shutdown must not leave a dangling device.
  if (use_) {
    connection_->remove_device(device());
    use_ = {};
  }
}

void RebDeviceDriver::setup() {
  core::SharedConnection::Use use = connection_->attach();  // the first one opens the board
  connection_->add_device(role_, device(), heading_control_);
  use_ = std::move(use);
}

void RebDeviceDriver::shutdown() {
  if (!use_) return;
  connection_->remove_device(device());
  use_ = {};  // the last one stops the motors and closes the line
}

core::RequestResult RebDeviceDriver::handle_request(const core::Request& request) {
  return connection_->handle_request(role_, request);
}

std::vector<core::DriverCounter> RebDeviceDriver::counters() const { return connection_->counters(); }

bool RebDeviceDriver::set_byte_trace(core::ByteTrace trace) {
  connection_->set_byte_trace(std::move(trace));
  return true;
}

}  // namespace playerkit::drivers::reb
