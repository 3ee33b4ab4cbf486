#pragma once
// The driver of one p2os device: a view onto the robot's P2osConnection.
// It holds a share of the connection from setup() to shutdown(); the
// connection's I/O thread publishes its data, takes its commands and
// answers its requests (hence runs_own_thread()).

#include <memory>

#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "families/p2os/driver/motor_commands.hpp"
#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/driver/p2os_role.hpp"

namespace playerkit::drivers::p2os {

class P2osDeviceDriver final : public core::Driver {
 public:
  P2osDeviceDriver(P2osRole role, std::shared_ptr<P2osConnection> connection, MotorLimits limits = {});
  ~P2osDeviceDriver() override;

  void setup() override;
  void shutdown() override;
  [[nodiscard]] bool runs_own_thread() const override { return true; }
  // The first device of a robot opens it: port, SYNC handshake, up to seconds.
  [[nodiscard]] bool setup_may_block() const override { return true; }
  core::RequestResult handle_request(const core::Request& request) override;
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override;
  bool set_byte_trace(core::ByteTrace trace) override;

  [[nodiscard]] P2osRole role() const { return role_; }
  [[nodiscard]] const MotorLimits& limits() const { return limits_; }
  [[nodiscard]] P2osConnection& connection() const { return *connection_; }

 private:
  const P2osRole role_;
  const std::shared_ptr<P2osConnection> connection_;
  const MotorLimits limits_;
  core::SharedConnection::Use use_;
};

}  // namespace playerkit::drivers::p2os
