#pragma once
// The driver of one reb device: a view onto the robot's RebConnection,
// held from setup() to shutdown(); the connection's I/O thread publishes
// its data, takes its commands and answers its requests.

#include <memory>
#include <vector>

#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "families/reb/driver/reb_connection.hpp"

namespace playerkit::drivers::reb {

class RebDeviceDriver final : public core::Driver {
 public:
  RebDeviceDriver(RebRole role, std::shared_ptr<RebConnection> connection, bool heading_control = false);
  ~RebDeviceDriver() override;

  void setup() override;
  void shutdown() override;
  [[nodiscard]] bool runs_own_thread() const override { return true; }
  [[nodiscard]] bool setup_may_block() const override { return true; }
  core::RequestResult handle_request(const core::Request& request) override;
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override;
  bool set_byte_trace(core::ByteTrace trace) override;

  [[nodiscard]] RebConnection& connection() const { return *connection_; }

 private:
  const RebRole role_;
  const std::shared_ptr<RebConnection> connection_;
  const bool heading_control_;
  core::SharedConnection::Use use_;
};

}  // namespace playerkit::drivers::reb
