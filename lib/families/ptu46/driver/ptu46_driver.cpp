// The ptu46 driver: a PTU-46 as a ptz device. The kit's SerialDeviceDriver
// opens the port, wakes this driver when a command or request arrives or
// when the next reading is due, and looks for the unit again when it goes
// quiet; what is here is the unit's protocol (PtuUnit) and its mapping to
// Player's ptz structs (ptu46.md §3).
#include "families/ptu46/driver/ptu46_driver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "families/ptu46/driver/ptu46_options.hpp"
#include "families/ptu46/driver/ptu_unit.hpp"
#include "families/ptu46/protocol/ptu_units.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "interfaces/ptz_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
using ptu46::AxisLimits;
using ptu46::ptu::Axis;
namespace ptu = hardware::ptu46;

// The reference driver's cycle (ptu46.md §2.3): a reading every 100 ms.
constexpr auto kReadingPeriod = 100ms;

std::int16_t wire_degrees(double degrees) {
  return static_cast<std::int16_t>(std::clamp(std::lround(degrees), -32768L, 32767L));
}

std::size_t index_of(Axis axis) { return axis == Axis::pan ? 0 : 1; }

class Ptu46Driver final : public hardware_driver::SerialDeviceDriver, private interfaces::PtzHead {
 public:
  explicit Ptu46Driver(const ptu46::Ptu46Settings& settings)
      : SerialDeviceDriver(settings.port, {.baud = settings.baud}, {}), baud_(settings.baud) {}

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_ptz_request(*this, request);
  }

 private:
  // --- the kit's hooks
  void start_device(links::ByteLink& link, bool /*recovering*/) override {
    unit_ = std::make_unique<ptu46::PtuUnit>(link, [this] { return stopping(); });
    try {
      limits_ = unit_->start();
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is it powered, and does baudrate " + std::to_string(baud_) +
                               " match the unit's?)");
    }
    // A unit just started is in independent control and has been sent nothing.
    velocity_mode_ = false;
    sent_positions_ = {};
    sent_speeds_ = {};
    next_reading_ = Clock::now();
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) override {
    // An exchange the unit leaves unanswered throws: the kit loses the unit.
    if (woke.readable) unsolicited_lines_ += unit_->drop_unsolicited();
    if (auto command = device().take_command()) obey(protocol::decode<protocol::PtzCommand>(command->payload));
    device().service_requests();
    if (Clock::now() >= next_reading_) {
      publish_reading();
      next_reading_ = Clock::now() + kReadingPeriod;
    }
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return next_reading_; }
  void link_closing() noexcept override { unit_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the PTU-46 on " + port(); }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"refused_commands", refused_commands_}, {"unsolicited_lines", unsolicited_lines_}};
  }

  // --- Player -> unit
  // Position control: the targets, clamped to the unit's limits (1.5 refused
  // an out-of-range demand and retried it every cycle), and a speed when one
  // is given. Velocity control: the signed speeds.
  void obey(const protocol::PtzCommand& command) {
    const std::array<int, 2> angles{command.pan, command.tilt};
    const std::array<int, 2> speeds{command.panspeed, command.tiltspeed};
    for (const Axis axis : {Axis::pan, Axis::tilt}) {
      const AxisLimits& limits = limits_.of(axis);
      const std::size_t i = index_of(axis);
      if (!velocity_mode_) {
        const std::int64_t target = std::clamp(ptu::positions_from_degrees(angles[i], limits.degrees_per_position),
                                               limits.min_position, limits.max_position);
        send_if_changed(sent_positions_[i], target, ptu::set_position(axis, target));
        if (speeds[i] == 0) continue;  // 0: travel at the speed already set
      }
      const std::int64_t speed = speed_within_limits(speeds[i], limits);
      send_if_changed(sent_speeds_[i], speed, ptu::set_speed(axis, speed));
    }
  }

  // A speed in positions/s the unit accepts: its magnitude within the
  // unit's lower and upper limits (0 stays 0: stop, in velocity control).
  std::int64_t speed_within_limits(double degrees_per_second, const AxisLimits& limits) const {
    const std::int64_t wanted = ptu::positions_from_degrees(degrees_per_second, limits.degrees_per_position);
    if (wanted == 0 && velocity_mode_) return 0;
    const std::int64_t magnitude = std::clamp(wanted < 0 ? -wanted : wanted, limits.lower_speed, limits.upper_speed);
    return wanted < 0 && velocity_mode_ ? -magnitude : magnitude;
  }

  void send_if_changed(std::optional<std::int64_t>& sent, std::int64_t value, const ptu::Command& command) {
    if (sent == value) return;
    const ptu::Reply reply = unit_->ask(command);
    if (reply.ok()) {
      sent = value;
      return;
    }
    ++refused_commands_;
    device().logger().warning(device().name() + ": the unit refused '" + command.text + "': " + reply.text);
    sent = value;  // not again until the client asks for something else
  }

  // --- unit -> Player
  void publish_reading() {
    protocol::PtzData data;
    data.pan = wire_degrees(read(Axis::pan, ptu::Quantity::position));
    data.tilt = wire_degrees(read(Axis::tilt, ptu::Quantity::position));
    data.panspeed = wire_degrees(read(Axis::pan, ptu::Quantity::speed));
    data.tiltspeed = wire_degrees(read(Axis::tilt, ptu::Quantity::speed));
    device().publish(protocol::encode(data));
  }

  double read(Axis axis, ptu::Quantity quantity) {
    const ptu::Reply reply = unit_->ask(ptu::query(axis, quantity));
    if (!reply.number) throw hardware_driver::DeviceLost("the unit answered '" + ptu::query(axis, quantity).text +
                                                         "' with no number: " + reply.text);
    return ptu::degrees_from_positions(*reply.number, limits_.of(axis).degrees_per_position);
  }

  // --- requests (interfaces::PtzHead), on the driver's thread
  bool set_control_mode(std::uint8_t mode) override {
    if (mode != protocol::kPtzVelocityControl && mode != protocol::kPtzPositionControl) return false;
    if (!unit_ || lost()) return false;
    const bool velocity = mode == protocol::kPtzVelocityControl;
    if (velocity == velocity_mode_) return true;  // 1.5 said NACK: already so is no failure
    const ptu::Reply reply = unit_->ask(
        ptu::set_control_mode(velocity ? ptu::ControlMode::pure_velocity : ptu::ControlMode::independent));
    if (!reply.ok()) return false;
    velocity_mode_ = velocity;
    // The unit holds both axes when the mode changes: send what comes next.
    sent_positions_ = {};
    sent_speeds_ = {};
    return true;
  }

  // The unit's own command text in `config`, its reply line back (1.5 NACKed).
  std::optional<protocol::PtzGenericConfig> generic_config(const protocol::PtzGenericConfig& command) override {
    if (!unit_ || lost() || command.length == 0) return std::nullopt;
    std::string text(command.config.begin(), command.config.begin() + std::min<std::size_t>(command.length, 32));
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r' || text.back() == '\n' || text.back() == '\0')) {
      text.pop_back();
    }
    const ptu::Reply reply = unit_->ask({text});
    std::string line = reply.kind == ptu::Reply::Kind::refused ? ptu::refusal_line(reply.text)
                       : reply.number                        ? ptu::value_line(*reply.number)
                                                             : ptu::done_line();
    protocol::PtzGenericConfig answer;
    answer.subtype = protocol::kPtzGenericConfigReq;
    answer.length = static_cast<std::uint16_t>(std::min<std::size_t>(line.size(), answer.config.size()));
    std::copy_n(line.begin(), answer.length, answer.config.begin());
    return answer;
  }

  const int baud_;
  std::unique_ptr<ptu46::PtuUnit> unit_;
  ptu46::UnitLimits limits_;
  bool velocity_mode_ = false;
  std::array<std::optional<std::int64_t>, 2> sent_positions_{};
  std::array<std::optional<std::int64_t>, 2> sent_speeds_{};
  Clock::time_point next_reading_{};
  std::uint64_t refused_commands_ = 0;
  std::uint64_t unsolicited_lines_ = 0;
};

}  // namespace

core::DriverSpec ptu46_driver_spec() {
  return {
      .name = "ptu46",
      .interfaces = {protocol::kPtzCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<Ptu46Driver>(ptu46::read_ptu46_settings(context.section));
      },
      .limits = {},
      .summary = "Directed Perception PTU-46 pan-tilt unit (ptz)",
      .family = "ptu46",
      .doc = {.manual_section = "7.32",
              .needs_hardware = true,
              .options = {},
              .requests = {"CONTROL_MODE: velocity (CV) or position (CI) control",
                           "GENERIC_CONFIG: one command in the unit's own text; its reply line back"},
              .example = "ptz:0 ( driver \"ptu46\" port \"/dev/ttyS0\" )",
              .schema = ptu46::ptu46_option_schema()},
  };
}

}  // namespace playerkit::drivers
