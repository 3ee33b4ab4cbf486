// The sonyevid30 driver: a Sony EVI-D30 as a ptz device. The kit's
// SerialDeviceDriver opens the port, wakes this driver when a command or
// request arrives, when the camera sends something, or when the next reading
// is due, and looks for the camera again when it goes quiet; what is here is
// VISCA (ViscaCamera) and the mapping to Player's ptz structs
// (sonyevid30.md §3).
#include "families/sonyevid30/driver/sonyevid30_driver.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "families/sonyevid30/driver/sonyevid30_options.hpp"
#include "families/sonyevid30/driver/visca_camera.hpp"
#include "families/sonyevid30/protocol/evid30_units.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "interfaces/ptz_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
using sonyevid30::Function;
namespace visca = hardware::sonyevid30;

// The reference driver's cycle (sonyevid30.md §2.3): a reading every 100 ms.
constexpr auto kReadingPeriod = 100ms;
// Movement mode stops an axis this close to its demand (the wire's whole degrees).
constexpr double kCloseEnough = 0.5;

std::int16_t wire_degrees(double degrees) {
  return static_cast<std::int16_t>(std::clamp(std::lround(degrees), -32768L, 32767L));
}

bool is_pan_tilt(const visca::Reply& reply) { return visca::pan_tilt_answer(reply).has_value(); }
bool is_zoom(const visca::Reply& reply) { return visca::zoom_answer(reply).has_value(); }

class Sonyevid30Driver final : public hardware_driver::SerialDeviceDriver, private interfaces::PtzHead {
 public:
  explicit Sonyevid30Driver(const sonyevid30::Sonyevid30Settings& settings)
      : SerialDeviceDriver(settings.port, {.baud = 9600}, {}), settings_(settings) {}

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_ptz_request(*this, request);
  }

 private:
  // --- the kit's hooks
  void start_device(links::ByteLink& link, bool /*recovering*/) override {
    camera_ = std::make_unique<sonyevid30::ViscaCamera>(
        link, [this] { return stopping(); }, [this](const std::string& line) { warn(line); });
    try {
      // 1.5's start-up: a pan/tilt inquiry answered within a second.
      read_position();
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is it a VISCA camera at address 1, powered, at 9600 baud?)");
    }
    // Nothing is moved until a client asks (1.5 drove the camera home at once).
    sent_pan_tilt_.reset();
    sent_zoom_.reset();
    sent_drive_.reset();
    next_reading_ = Clock::now();
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) override {
    // An exchange the camera leaves unanswered throws: the kit loses the camera.
    if (woke.readable) camera_->take_pending();
    if (auto command = device().take_command()) obey(protocol::decode<protocol::PtzCommand>(command->payload));
    device().service_requests();
    if (Clock::now() >= next_reading_) {
      publish_reading();
      if (settings_.movement && demand_) steer();
      next_reading_ = Clock::now() + kReadingPeriod;
    }
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return next_reading_; }

  // Home, as 1.5 left the camera: straight ahead, zoomed out.
  void stop_device(links::ByteLink& /*link*/) noexcept override {
    if (!camera_) return;
    try {
      camera_->command(visca::absolute_pan_tilt(0, 0), "absolute pan/tilt", Function::pan_tilt);
      camera_->command(visca::zoom_direct(0), "zoom direct", Function::zoom);
    } catch (const std::exception& e) {
      warn(std::string("could not send the camera home: ") + e.what());
    }
  }

  void link_closing() noexcept override { camera_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the EVI-D30 camera on " + port(); }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"refused_commands", refused_commands_},
            {"completions", camera_ ? camera_->completions() : 0},
            {"cancelled_commands", camera_ ? camera_->cancelled() : 0},
            {"late_errors", camera_ ? camera_->late_errors() : 0}};
  }

  void warn(const std::string& line) { device().logger().warning(device().name() + ": " + line); }

  // --- Player -> camera
  void obey(const protocol::PtzCommand& command) {
    demand_ = command;
    if (!settings_.movement) {
      const visca::PanTiltUnits target{visca::pan_units(command.pan), visca::tilt_units(command.tilt)};
      if (!sent_pan_tilt_ || sent_pan_tilt_->pan != target.pan || sent_pan_tilt_->tilt != target.tilt) {
        sent_pan_tilt_ = target;  // not again until the client asks for something else, refused or not
        send(visca::absolute_pan_tilt(target.pan, target.tilt), "absolute pan/tilt", Function::pan_tilt);
      }
    }
    const int zoom = visca::zoom_units(command.zoom, settings_.fov);
    if (sent_zoom_ != zoom) {
      sent_zoom_ = zoom;
      send(visca::zoom_direct(zoom), "zoom direct", Function::zoom);
    }
  }

  void send(const visca::Bytes& packet, const std::string& name, Function function) {
    try {
      camera_->command(packet, name, function);
    } catch (const links::ExchangeError& e) {
      if (e.kind() != links::ExchangeError::Kind::refused) throw;
      ++refused_commands_;
      warn(e.what());
    }
  }

  // Movement mode: each axis driven toward its demand at a speed that
  // shrinks with the distance left (1.5 drove at top speed and never
  // stopped), stopped when within half a degree.
  void steer() {
    struct Axis {
      visca::Drive drive = visca::Drive::stop;
      int speed = 1;
    };
    auto axis = [](double error_degrees, int top_speed) {
      if (std::fabs(error_degrees) < kCloseEnough) return Axis{};
      return Axis{error_degrees > 0 ? visca::Drive::forward : visca::Drive::backward,
                  std::clamp(static_cast<int>(std::lround(std::fabs(error_degrees))), 1, top_speed)};
    };
    // Forward is left (Player's pan growing) and up.
    const Axis pan = axis(demand_->pan - visca::pan_degrees(position_.pan), visca::kPanSpeedMax);
    const Axis tilt = axis(demand_->tilt - visca::tilt_degrees(position_.tilt), visca::kTiltSpeedMax);
    const visca::Bytes packet = visca::drive_pan_tilt(pan.drive, tilt.drive, pan.speed, tilt.speed);
    if (sent_drive_ == packet) return;
    sent_drive_ = packet;
    send(packet, "pan/tilt drive", Function::pan_tilt);
  }

  // --- camera -> Player
  void read_position() {
    const auto answer = camera_->inquire(visca::pan_tilt_inquiry(), "pan/tilt position inquiry", is_pan_tilt);
    position_ = *visca::pan_tilt_answer(visca::parse_reply(answer));
  }

  void publish_reading() {
    read_position();
    const auto answer = camera_->inquire(visca::zoom_inquiry(), "zoom position inquiry", is_zoom);
    const int zoom = *visca::zoom_answer(visca::parse_reply(answer));
    protocol::PtzData data;
    data.pan = wire_degrees(visca::pan_degrees(position_.pan));
    data.tilt = wire_degrees(visca::tilt_degrees(position_.tilt));
    data.zoom = wire_degrees(visca::fov_degrees(zoom, settings_.fov));
    // The camera reports no speeds: 0 (1.5 sent uninitialised bytes).
    device().publish(protocol::encode(data));
  }

  // --- requests (interfaces::PtzHead), on the driver's thread
  // Position control is the only one (1.5 never answered this request).
  bool set_control_mode(std::uint8_t mode) override { return mode == protocol::kPtzPositionControl; }

  // `config` is a VISCA message without its header and terminator: a
  // command (01 ...) answered with its ACK packet, or an inquiry (09 ...)
  // with its answer packet. An error packet, silence or anything else: NACK.
  std::optional<protocol::PtzGenericConfig> generic_config(const protocol::PtzGenericConfig& request) override {
    if (!camera_ || lost() || request.length == 0 || request.length > visca::kLongestMessage) return std::nullopt;
    const std::span message(request.config.data(), request.length);
    const visca::Bytes packet = visca::to_camera(message);
    visca::Bytes reply;
    try {
      if (message[0] == 0x01) {
        reply = visca::ack(camera_->command(packet, "client command " + visca::hex(packet), Function::other));
      } else if (message[0] == 0x09) {
        reply = camera_->inquire(packet, "client inquiry " + visca::hex(packet), [](const visca::Reply&) { return true; });
      } else {
        warn("GENERIC_CONFIG: " + visca::hex(message) + " is neither a command (01 ...) nor an inquiry (09 ...)");
        return std::nullopt;
      }
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) return std::nullopt;
      warn(std::string("GENERIC_CONFIG: ") + e.what());
      return std::nullopt;
    }
    protocol::PtzGenericConfig answer;
    answer.subtype = protocol::kPtzGenericConfigReq;
    answer.length = static_cast<std::uint16_t>(std::min(reply.size(), answer.config.size()));
    std::copy_n(reply.begin(), answer.length, answer.config.begin());
    return answer;
  }

  const sonyevid30::Sonyevid30Settings settings_;
  std::unique_ptr<sonyevid30::ViscaCamera> camera_;
  visca::PanTiltUnits position_;
  std::optional<protocol::PtzCommand> demand_;
  std::optional<visca::PanTiltUnits> sent_pan_tilt_;
  std::optional<int> sent_zoom_;
  std::optional<visca::Bytes> sent_drive_;
  Clock::time_point next_reading_{};
  std::uint64_t refused_commands_ = 0;
};

}  // namespace

core::DriverSpec sonyevid30_driver_spec() {
  return {
      .name = "sonyevid30",
      .interfaces = {protocol::kPtzCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<Sonyevid30Driver>(sonyevid30::read_sonyevid30_settings(context.section));
      },
      .limits = {},
      .summary = "Sony EVI-D30 pan-tilt-zoom camera, VISCA over RS-232 (ptz)",
      .family = "sonyevid30",
      .doc = {.manual_section = "7.41",
              .needs_hardware = true,
              .options = {},
              .requests = {"GENERIC_CONFIG: a VISCA command (01 ...) or inquiry (09 ...) without header and "
                           "terminator; its ACK or answer packet back",
                           "CONTROL_MODE: position control only (velocity is NACKed)"},
              .example = "ptz:0 ( driver \"sonyevid30\" port \"/dev/ttyS2\" fov [3 30] )",
              .schema = sonyevid30::sonyevid30_option_schema()},
  };
}

}  // namespace playerkit::drivers
