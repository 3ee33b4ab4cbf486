#pragma once
// The driver of one rflex device: a view onto the robot's RflexConnection,
// holding a share of it from setup() to shutdown(); the connection's I/O
// thread publishes its data, takes its commands and answers its requests.

#include <memory>
#include <utility>

#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "families/rflex/driver/rflex_connection.hpp"
#include "families/rflex/driver/rflex_role.hpp"

namespace playerkit::drivers::rflex {

class RflexDeviceDriver final : public core::Driver {
 public:
  RflexDeviceDriver(RflexRole role, std::shared_ptr<RflexConnection> connection)
      : role_(role), connection_(std::move(connection)) {}
  ~RflexDeviceDriver() override {
    if (use_) {
      connection_->remove_device(device());
      use_ = {};
    }
  }

  void setup() override {
    core::SharedConnection::Use use = connection_->attach();  // the first one opens the robot
    connection_->add_device(role_, device());
    use_ = std::move(use);
  }
  void shutdown() override {
    if (!use_) return;
    connection_->remove_device(device());
    use_ = {};  // the last one stops the robot and closes the line
  }
  [[nodiscard]] bool runs_own_thread() const override { return true; }
  // The first device of a robot opens it and waits for its controller.
  [[nodiscard]] bool setup_may_block() const override { return true; }
  core::RequestResult handle_request(const core::Request& request) override {
    return connection_->handle_request(role_, request);
  }
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override { return connection_->counters(); }
  bool set_byte_trace(core::ByteTrace trace) override {
    connection_->set_byte_trace(std::move(trace));
    return true;
  }

  [[nodiscard]] RflexConnection& connection() const { return *connection_; }

 private:
  const RflexRole role_;
  const std::shared_ptr<RflexConnection> connection_;
  core::SharedConnection::Use use_;
};

}  // namespace playerkit::drivers::rflex
