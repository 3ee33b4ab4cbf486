// The amtecpowercube driver: the wrist as a ptz device. The kit's
// SerialDeviceDriver opens the port, wakes this driver when a command or
// request arrives or a reading is due, and starts the wrist again when it
// goes quiet or a module reports an error; what is here is the wrist's
// start-up (PowercubeWrist) and the mapping to Player's ptz structs
// (amtecpowercube.md §3).
#include "families/amtecpowercube/driver/amtecpowercube_driver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "families/amtecpowercube/driver/powercube_options.hpp"
#include "families/amtecpowercube/driver/powercube_wrist.hpp"
#include "families/amtecpowercube/protocol/powercube_units.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "interfaces/ptz_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
using amtecpowercube::module_name;
namespace pc = hardware::powercube;

// 1.5's cycle was 20 ms of sleep plus six exchanges; readings every 50 ms
// leave the line room for commands.
constexpr auto kReadingPeriod = 50ms;
constexpr std::array<pc::Module, 2> kModules{pc::Module::pan, pc::Module::tilt};

// What was last sent to a module, so a command repeated is not sent again.
struct Demand {
  double value = 0;  // degrees or deg/s, module convention
  double speed = 0;  // deg/s of a position move
  bool operator==(const Demand&) const = default;
};

class AmtecPowercubeDriver final : public hardware_driver::SerialDeviceDriver, private interfaces::PtzHead {
 public:
  explicit AmtecPowercubeDriver(const amtecpowercube::PowercubeSettings& settings)
      : SerialDeviceDriver(settings.port, {.baud = 38400}, {}), settings_(settings) {}

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_ptz_request(*this, request);
  }

 private:
  // --- the kit's hooks
  void start_device(links::ByteLink& link, bool recovering) override {
    wrist_ = std::make_unique<amtecpowercube::PowercubeWrist>(link, [this] { return stopping(); });
    try {
      reach_ = wrist_->start();
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is it powered, at 38400 baud?)");
    }
    // A new subscription starts in position control; a wrist found again keeps the client's mode.
    if (!recovering) velocity_mode_ = false;
    sent_ = {};
    positions_ = {};  // homed
    next_reading_ = Clock::now();
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& /*woke*/) override {
    if (auto command = device().take_command()) obey(protocol::decode<protocol::PtzCommand>(command->payload));
    device().service_requests();
    if (Clock::now() >= next_reading_) {
      publish_reading();
      next_reading_ = Clock::now() + kReadingPeriod;
    }
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return next_reading_; }

  // The modules braked, and homed again when `home` asks for it (1.5 waited forever for that).
  void stop_device(links::ByteLink& /*link*/) noexcept override {
    if (!wrist_) return;
    try {
      for (const pc::Module module : kModules) wrist_->halt(module);
      if (settings_.home_at_shutdown) {
        for (const pc::Module module : kModules) wrist_->home(module);
      }
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": leaving the wrist: " + e.what());
    }
  }

  void link_closing() noexcept override { wrist_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the PowerCube wrist on " + port(); }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"moves", moves_}, {"module_errors", module_errors_}};
  }

  // --- Player -> modules. The pan module counts clockwise, Player counter-clockwise.
  void obey(const protocol::PtzCommand& command) {
    const std::array<double, 2> angles{-static_cast<double>(command.pan), static_cast<double>(command.tilt)};
    const std::array<double, 2> speeds{-static_cast<double>(command.panspeed), static_cast<double>(command.tiltspeed)};
    for (std::size_t i = 0; i < kModules.size(); ++i) {
      if (velocity_mode_) {
        const Demand demand{std::clamp(speeds[i], -settings_.speed, settings_.speed), 0};
        if (sent_[i] == demand) continue;
        wrist_->velocity(kModules[i], static_cast<float>(pc::radians(demand.value)));
        sent_[i] = demand;
      } else {
        // A speed given with the target times the move (1.5 ignored it), never
        // above `speed`; the target is kept within the module's reach.
        const double speed = speeds[i] == 0 ? settings_.speed : std::min(std::fabs(speeds[i]), settings_.speed);
        const Demand demand{reach_[i].clamp(angles[i]), speed};
        if (sent_[i] == demand) continue;
        const double from = pc::degrees(positions_[i]);
        wrist_->step(kModules[i], static_cast<float>(pc::radians(demand.value)),
                     pc::step_milliseconds(demand.value - from, speed));
        sent_[i] = demand;
      }
      ++moves_;
    }
  }

  // --- modules -> Player
  void publish_reading() {
    std::array<double, 2> velocities{};
    for (std::size_t i = 0; i < kModules.size(); ++i) {
      positions_[i] = wrist_->read_float(kModules[i], pc::Parameter::position);
      velocities[i] = wrist_->read_float(kModules[i], pc::Parameter::velocity);
    }
    protocol::PtzData data;
    data.pan = pc::wire_degrees(pc::player_pan_degrees(positions_[0]));
    data.tilt = pc::wire_degrees(pc::degrees(positions_[1]));
    data.zoom = 0;
    data.panspeed = pc::wire_degrees(-pc::degrees(velocities[0]));
    data.tiltspeed = pc::wire_degrees(pc::degrees(velocities[1]));
    device().publish(protocol::encode(data));
    for (const pc::Module module : kModules) {
      if ((wrist_->read_state(module) & pc::state_bit::error) != 0) {
        ++module_errors_;
        // Starting again resets and homes it (1.5's thread ended here, and the data stopped).
        throw hardware_driver::DeviceLost(std::string("the ") + module_name(module) + " reports an error");
      }
    }
  }

  // --- requests (interfaces::PtzHead), on the driver's thread
  bool set_control_mode(std::uint8_t mode) override {
    if (mode != protocol::kPtzVelocityControl && mode != protocol::kPtzPositionControl) return false;
    if (!wrist_ || lost()) return false;
    const bool velocity = mode == protocol::kPtzVelocityControl;
    if (velocity == velocity_mode_) return true;
    // Both modules stopped where they are; 1.5 zeroed its command, which
    // drove a wrist switched to position control back to 0, 0.
    for (const pc::Module module : kModules) wrist_->velocity(module, 0.0F);
    velocity_mode_ = velocity;
    sent_ = {};
    return true;
  }

  const amtecpowercube::PowercubeSettings settings_;
  std::unique_ptr<amtecpowercube::PowercubeWrist> wrist_;
  bool velocity_mode_ = false;
  std::array<amtecpowercube::ModuleReach, 2> reach_{};
  std::array<std::optional<Demand>, 2> sent_{};
  std::array<double, 2> positions_{};  // radians, module convention, as last read
  Clock::time_point next_reading_{};
  std::uint64_t moves_ = 0;
  std::uint64_t module_errors_ = 0;
};

}  // namespace

core::DriverSpec amtecpowercube_driver_spec() {
  return {
      .name = "amtecpowercube",
      .interfaces = {protocol::kPtzCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<AmtecPowercubeDriver>(amtecpowercube::read_powercube_settings(context.section));
      },
      .limits = {},
      .summary = "Amtec PowerCube pan-tilt wrist (ptz)",
      .family = "amtecpowercube",
      .doc = {.manual_section = "7.4",
              .needs_hardware = true,
              .options = {},
              .requests = {"CONTROL_MODE: velocity or position control (both modules stop where they are)"},
              .example = "ptz:0 ( driver \"amtecpowercube\" port \"/dev/ttyS0\" home 1 speed 40 )",
              .schema = amtecpowercube::powercube_option_schema()},
  };
}

}  // namespace playerkit::drivers
