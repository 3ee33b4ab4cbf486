#pragma once
// One CMUcam2 on one serial line, shared by its blobfinder and its ptz
// device (hardware_driver::RobotConnection, as p2os's devices share a
// robot). The first device set up opens the line, stops any stream and
// selects poll mode; then the I/O thread, in serve():
//
//  * answers both devices' requests and takes the ptz commands: SV for each
//    servo whose position changes, straight to the target at speed 0 (the
//    servo's own speed), stepped toward it at a given speed otherwise;
//  * with a blobfinder attached, one TC per configured colour, as fast as
//    the camera gives frames, then one blobfinder message;
//  * with a ptz attached, GS of both servos, one ptz message.
//
// A camera silent for kAttempts exchanges is lost and looked for again.

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "core/device.hpp"
#include "core/exchange.hpp"
#include "core/logger.hpp"
#include "families/cmucam2/driver/cmucam2_options.hpp"
#include "families/cmucam2/driver/cmucam_camera.hpp"
#include "hardware_driver/robot_connection.hpp"
#include "interfaces/ptz_requests.hpp"

namespace playerkit::drivers::cmucam2 {

enum class Cmucam2Role { blobfinder, ptz };

// "cmucam2 /dev/ttyS1": both devices of one camera find one connection.
[[nodiscard]] std::string connection_key(const Cmucam2Settings& settings);

class Cmucam2Connection final : public hardware_driver::RobotConnection, private interfaces::PtzHead {
 public:
  Cmucam2Connection(Cmucam2Settings settings, core::Logger& logger);
  ~Cmucam2Connection() override;

  // From a device's setup(), holding a Use. Throws core::DriverError while
  // the camera is not answering.
  void add_device(Cmucam2Role role, core::Device& device);
  void remove_device(core::Device& device);
  // On the I/O thread (through Device::service_requests).
  core::RequestResult handle_request(Cmucam2Role role, const core::Request& request);

  [[nodiscard]] const Cmucam2Settings& settings() const { return settings_; }

  // The servos: 0 pan, 1 tilt.
  static constexpr int kCentre = 128;
  static constexpr std::int16_t kFieldOfView = 48;  // degrees across, the CMUcam2's lens

 private:
  struct View {
    Cmucam2Role role;
    core::Device* device;
  };
  struct Axis {
    int target = kCentre;               // where the client wants it, servo positions
    double speed = 0;                   // degrees/s; 0: straight there
    double set_point = kCentre;         // where the driver has it, stepping at `speed`
    std::optional<int> sent;            // the last SV this session
    bool commanded = false;             // a client has moved it: until then the servo is left alone
  };

  void connect(links::ByteLink& link) override;
  bool reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) override;
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override;
  [[nodiscard]] Clock::time_point next_deadline() const override;
  void serve_while_away() override;
  void robot_lost() override;
  void stop_motion(links::ByteLink& link) noexcept override;
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override;

  void start_session(links::ByteLink& link);
  void take_commands();
  void move_servos(Clock::time_point now);
  void publish_blobs();
  void publish_servos();
  [[nodiscard]] bool has(Cmucam2Role role) const;
  [[nodiscard]] int position_of(double degrees) const;
  [[nodiscard]] double degrees_of(double position) const;

  // interfaces::PtzHead
  bool set_control_mode(std::uint8_t mode) override;
  core::RequestResult set_color(const core::Request& request);

  const Cmucam2Settings settings_;
  mutable std::mutex views_mutex_;
  std::vector<View> views_;

  std::atomic<std::uint64_t> packets_{0};
  std::atomic<std::uint64_t> refused_{0};

  // The I/O thread's.
  std::vector<cam::ColorBounds> colors_;  // the configured ones; SET_COLOR replaces the first
  std::unique_ptr<CmucamCamera> camera_;
  std::array<Axis, 2> axes_{};
  bool velocity_control_ = false;
  Clock::time_point last_step_{};
  Clock::time_point next_cycle_{};
};

}  // namespace playerkit::drivers::cmucam2
