// The nomad driver: the robot behind Nomadic's server as a nomad device.
// The kit's SerialDeviceDriver dials tcp:HOST:PORT at the first subscription,
// wakes this driver for commands and for the next cycle, and reconnects when
// the server goes away; what is here is the cycle (nomad.md §1.3) and the
// mapping to player_nomad_*.
#include <unistd.h>

#include <memory>

#include "families/nomad/driver/nomad_drivers.hpp"
#include "families/nomad/driver/nomad_mapping.hpp"
#include "families/nomad/driver/nomad_options.hpp"
#include "families/nomad/driver/nomad_session.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "links/link_error.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;

// The reference looped without a pause, as fast as the server answered
// (nomad.md §5.5); a cycle every 50 ms is the robot's pace and spares a CPU.
// A new command starts a cycle at once.
constexpr auto kCyclePeriod = 50ms;

class NomadDriver final : public hardware_driver::SerialDeviceDriver {
 public:
  explicit NomadDriver(const nomad::NomadSettings& settings)
      : SerialDeviceDriver(settings.link, {}, {}), host_(settings.host) {}

 private:
  void start_device(links::ByteLink& link, bool recovering) override {
    session_ = std::make_unique<nomad::NomadSession>(link, [this] { return stopping(); });
    try {
      // Zeroing again after a lost connection would throw the odometry away.
      session_->start(static_cast<std::int32_t>(getpid()), !recovering);
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is Nserver or robotd running on " + host_ + "?)");
    }
    next_cycle_ = Clock::now();
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& /*woke*/) override {
    device().service_requests();  // none known: NACK, as 1.5
    if (take_new_command()) next_cycle_ = Clock::now();
    if (Clock::now() < next_cycle_) return;
    next_cycle_ = Clock::now() + kCyclePeriod;
    try {
      session_->send_velocity(velocity_.translation, velocity_.steering, velocity_.turret);
      // One that came while VM was answered goes out before the state is
      // asked, not a whole cycle later.
      if (take_new_command()) session_->send_velocity(velocity_.translation, velocity_.steering, velocity_.turret);
      device().publish(protocol::encode(nomad::nomad_data(session_->read_state())));
    } catch (const links::ExchangeError&) {
      throw;
    } catch (const links::LinkError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw hardware_driver::DeviceLost(e.what());
    }
  }

  bool take_new_command() {
    auto command = device().take_command();
    if (!command) return false;
    velocity_ = nomad::velocity_words(protocol::decode<protocol::NomadCommand>(command->payload));
    return true;
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return next_cycle_; }

  void stop_device(links::ByteLink& /*link*/) noexcept override {
    // 1.5 left the robot running on its last command until CONF_TM's 5 s.
    try {
      if (session_) session_->stop_motion();
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": could not stop the robot: " + e.what());
    }
  }

  void link_closing() noexcept override { session_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the Nomad server at " + port(); }

  const std::string host_;
  std::unique_ptr<nomad::NomadSession> session_;
  nomad::VelocityWords velocity_{};
  Clock::time_point next_cycle_{};
};

}  // namespace

core::DriverSpec nomad_driver_spec() {
  return {
      .name = "nomad",
      .interfaces = {protocol::kNomadCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<NomadDriver>(nomad::read_nomad_settings(context.section, nomad::machine_name()));
      },
      .limits = {},
      .summary = "Nomadic Nomad 200 through Nomadic's server over TCP (nomad)",
      .family = "nomad",
      .doc = {.manual_section = "7.29",
              .needs_hardware = true,
              .options = {},
              .requests = {"none: every request NACK, as 1.5"},
              .example = "nomad:0 ( driver \"nomad\" host \"robot.local\" )",
              .schema = nomad::nomad_option_schema()},
  };
}

}  // namespace playerkit::drivers
