// The cmucam2 drivers: each device a view onto the camera's shared
// Cmucam2Connection, whose I/O thread publishes its data, takes its
// commands and answers its requests (as p2os's devices do).
#include "families/cmucam2/driver/cmucam2_driver.hpp"

#include <memory>

#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "families/cmucam2/driver/cmucam2_connection.hpp"
#include "families/cmucam2/driver/cmucam2_options.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using cmucam2::Cmucam2Connection;
using cmucam2::Cmucam2Role;

class Cmucam2DeviceDriver final : public core::Driver {
 public:
  Cmucam2DeviceDriver(Cmucam2Role role, std::shared_ptr<Cmucam2Connection> connection)
      : role_(role), connection_(std::move(connection)) {}
  ~Cmucam2DeviceDriver() override {
    if (use_) {
      connection_->remove_device(device());
      use_ = {};
    }
  }

  void setup() override {
    core::SharedConnection::Use use = connection_->attach();  // the first device opens the line
    connection_->add_device(role_, device());
    use_ = std::move(use);
  }
  void shutdown() override {
    if (!use_) return;
    connection_->remove_device(device());
    use_ = {};  // the last one leaves the camera idle and closes the line
  }
  [[nodiscard]] bool runs_own_thread() const override { return true; }
  [[nodiscard]] bool setup_may_block() const override { return true; }
  core::RequestResult handle_request(const core::Request& request) override {
    return connection_->handle_request(role_, request);
  }
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override { return connection_->counters(); }
  bool set_byte_trace(core::ByteTrace trace) override {
    connection_->set_byte_trace(std::move(trace));
    return true;
  }

 private:
  const Cmucam2Role role_;
  const std::shared_ptr<Cmucam2Connection> connection_;
  core::SharedConnection::Use use_;
};

core::DriverFactory factory_for(std::string driver) {
  return [driver](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    const Cmucam2Role role =
        context.key.address.interface == protocol::kPtzCode ? Cmucam2Role::ptz : Cmucam2Role::blobfinder;
    cmucam2::Cmucam2Settings settings = cmucam2::read_cmucam2_settings(context.section, driver);
    auto connection = context.connections.get<Cmucam2Connection>(cmucam2::connection_key(settings), [&] {
      return std::make_shared<Cmucam2Connection>(std::move(settings), context.logger);
    });
    return std::make_unique<Cmucam2DeviceDriver>(role, std::move(connection));
  };
}

}  // namespace

std::vector<core::DriverSpec> cmucam2_driver_specs() {
  const std::vector<std::string> requests{
      "blobfinder SET_COLOR: the bounds of color0 from now on (0 to 255, each min <= max); others NACK",
      "ptz CONTROL_MODE: position (servo targets) or velocity (servos stepped at the signed speeds)",
      "ptz GENERIC_CONFIG: NACK"};
  core::DriverSpec camera{
      .name = "cmucam2",
      .interfaces = {protocol::kBlobfinderCode, protocol::kPtzCode},
      .access = protocol::Access::kAll,
      .factory = factory_for("cmucam2"),
      .limits = {},
      .summary = "CMUcam2 colour tracker (blobfinder) and its servos (ptz) on one serial line",
      .family = "cmucam2",
      .doc = {.manual_section = "7.5",
              .needs_hardware = true,
              .options = {},
              .requests = requests,
              .example = "blobfinder:0 ( driver \"cmucam2\" devicepath \"/dev/ttyS1\" num_blobs 1 "
                         "color0 [200 240 16 60 16 60] )",
              .schema = cmucam2::cmucam2_option_schema()},
  };
  core::DriverSpec servos = camera;
  servos.name = "cmucam2_ptz";
  servos.interfaces = {protocol::kPtzCode};
  servos.factory = factory_for("cmucam2_ptz");
  servos.summary = "The servos of a CMUcam2 as ptz (the camera's `cmucam2` on the same port shares the line)";
  servos.doc.example = "ptz:0 ( driver \"cmucam2_ptz\" devicepath \"/dev/ttyS1\" )";
  return {camera, servos};
}

}  // namespace playerkit::drivers
