#pragma once
// The driver of one khepera device: a view onto the robot's
// KheperaConnection, held from setup() to shutdown(); the connection's I/O
// thread publishes its data, takes its commands and answers its requests.

#include <memory>
#include <variant>

#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "families/khepera/driver/khepera_connection.hpp"

namespace playerkit::drivers::khepera {

class KheperaDeviceDriver final : public core::Driver {
 public:
  using Options = std::variant<KheperaPositionOptions, KheperaIrOptions>;

  KheperaDeviceDriver(std::shared_ptr<KheperaConnection> connection, Options options);
  ~KheperaDeviceDriver() override;

  void setup() override;
  void shutdown() override;
  [[nodiscard]] bool runs_own_thread() const override { return true; }
  // The first device opens the robot: the port and its first answer.
  [[nodiscard]] bool setup_may_block() const override { return true; }
  core::RequestResult handle_request(const core::Request& request) override;
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override;
  bool set_byte_trace(core::ByteTrace trace) override;

  [[nodiscard]] KheperaConnection& connection() const { return *connection_; }

 private:
  [[nodiscard]] KheperaRole role() const;

  const std::shared_ptr<KheperaConnection> connection_;
  const Options options_;
  core::SharedConnection::Use use_;
};

}  // namespace playerkit::drivers::khepera
