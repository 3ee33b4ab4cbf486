#include "families/khepera/driver/khepera_device_driver.hpp"

#include <utility>

namespace playerkit::drivers::khepera {

KheperaDeviceDriver::KheperaDeviceDriver(std::shared_ptr<KheperaConnection> connection, Options options)
    : connection_(std::move(connection)), options_(std::move(options)) {}

KheperaDeviceDriver::~KheperaDeviceDriver() {
  // Covers a driver destroyed without shutdown(): the connection must never
  // keep a dangling device.
  if (use_) {
    connection_->remove_device(device());
    use_ = {};
  }
}

KheperaRole KheperaDeviceDriver::role() const {
  return std::holds_alternative<KheperaPositionOptions>(options_) ? KheperaRole::position : KheperaRole::ir;
}

void KheperaDeviceDriver::setup() {
  core::SharedConnection::Use use = connection_->attach();  // the first one opens the robot
  if (const auto* position = std::get_if<KheperaPositionOptions>(&options_)) {
    connection_->add_position(device(), *position);  // throws while the robot is away
  } else {
    connection_->add_ir(device(), std::get<KheperaIrOptions>(options_));
  }
  use_ = std::move(use);
}

void KheperaDeviceDriver::shutdown() {
  if (!use_) return;
  connection_->remove_device(device());
  use_ = {};  // the last one stops the robot and closes the line
}

core::RequestResult KheperaDeviceDriver::handle_request(const core::Request& request) {
  return connection_->handle_request(role(), request);
}

std::vector<core::DriverCounter> KheperaDeviceDriver::counters() const { return connection_->counters(); }

bool KheperaDeviceDriver::set_byte_trace(core::ByteTrace trace) {
  connection_->set_byte_trace(std::move(trace));
  return true;
}

}  // namespace playerkit::drivers::khepera
