#pragma once
// For the sick driver tests: an emulated laser in a hand-made room, on the
// driver harness (drivers/driver_harness_test_support.hpp: a real
// pseudo-terminal or a loopback TCP port, a device built from config text as
// the server builds it, bounded waits for scans and replies).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/sick/driver/sick_laser_driver.hpp"
#include "families/sick/emulator/sick_lms200_emulator.hpp"
#include "families/sick/emulator/sick_pls_emulator.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::sick_driver_test_support {

using namespace std::chrono_literals;
namespace sick = hardware::sick;
using hardware::sick::Model;

// A 4 m x 3 m room of 5 cm cells whose border cells are wall: the inner
// faces are at x = 0.05 and 3.95, y = 0.05 and 2.95.
inline constexpr double kCell = 0.05;
inline constexpr int kColumns = 80;
inline constexpr int kRows = 60;
inline constexpr double kWest = kCell;
inline constexpr double kEast = kCell * (kColumns - 1);
inline constexpr double kSouth = kCell;
inline constexpr double kNorth = kCell * (kRows - 1);
// Off centre, so that a scan read backwards differs from the true one.
inline const geometry::Pose2 kLaserPose{1.0, 1.4, 0.0};

inline grid::OccupancyGrid box_room() {
  grid::OccupancyGrid room(kColumns, kRows, kCell, Eigen::Vector2d::Zero(), grid::CellState::free);
  for (int c = 0; c < kColumns; ++c) {
    room.set(c, 0, grid::CellState::occupied);
    room.set(c, kRows - 1, grid::CellState::occupied);
  }
  for (int r = 0; r < kRows; ++r) {
    room.set(0, r, grid::CellState::occupied);
    room.set(kColumns - 1, r, grid::CellState::occupied);
  }
  return room;
}

// Metres from the laser to the wall along `angle` (world frame), by hand.
inline double room_range(double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  double range = std::numeric_limits<double>::infinity();
  if (c > 1e-12) range = std::min(range, (kEast - kLaserPose.x) / c);
  if (c < -1e-12) range = std::min(range, (kWest - kLaserPose.x) / c);
  if (s > 1e-12) range = std::min(range, (kNorth - kLaserPose.y) / s);
  if (s < -1e-12) range = std::min(range, (kSouth - kLaserPose.y) / s);
  return range;
}

// The angle of beam i of a scan, in radians.
inline double beam_angle(const protocol::LaserData& scan, std::size_t i) {
  return (scan.min_angle + static_cast<double>(i) * scan.resolution) * std::numbers::pi / 18000.0;
}

// Wraps the emulated laser so a test can make it refuse the next variant
// (BB 00), as a real LMS refuses a variant it does not have.
class RefusingLaser final : public emulators::DeviceEmulator {
 public:
  explicit RefusingLaser(std::unique_ptr<emulators::SickLaserEmulator> inner) : inner_(std::move(inner)) {}

  emulators::SickLaserEmulator& inner() { return *inner_; }
  void refuse_next_variant() { refuse_next_variant_ = true; }

  void receive(std::span<const std::uint8_t> bytes, emulators::Duration now, int host_baud) override {
    inner_->receive(bytes, now, host_baud);
  }
  void advance(emulators::Duration now) override { inner_->advance(now); }
  [[nodiscard]] emulators::Duration next_deadline() const override { return inner_->next_deadline(); }
  std::vector<emulators::Telegram> take_output() override {
    auto output = inner_->take_output();
    for (auto& telegram : output) {
      const bool variant_reply = telegram.has_checksum && telegram.bytes.size() > 4 &&
                                 telegram.bytes[4] == sick::kVariantReply;
      if (variant_reply && refuse_next_variant_) {
        refuse_next_variant_ = false;
        telegram.bytes = sick::encode_reply(sick::VariantReply{false, {180, 50}});
      }
    }
    return output;
  }
  void host_disconnected(emulators::Duration now) override { inner_->host_disconnected(now); }
  [[nodiscard]] int baud() const override { return inner_->baud(); }
  [[nodiscard]] std::string describe() const override { return inner_->describe(); }

 private:
  std::unique_ptr<emulators::SickLaserEmulator> inner_;
  bool refuse_next_variant_ = false;
};

using ::playerkit::testing::ScratchDirectory;

struct RigOptions {
  Model model = Model::lms200;
  // Where the laser starts: 38400 spares the tests the 9600 fallback.
  int power_up_baud = 38400;
  emulators::FaultPlan faults{};
  bool tcp = false;
  std::vector<emulators::SickReflector> reflectors{};
  std::optional<std::filesystem::path> symlink{};
};

inline std::unique_ptr<RefusingLaser> make_laser(const RigOptions& options) {
  const grid::OccupancyGrid room = box_room();  // read once by the emulator
  emulators::SickEmulatorOptions laser;
  laser.map = &room;
  laser.pose = kLaserPose;
  laser.reflectors = options.reflectors;
  laser.power_up_baud = options.power_up_baud;
  std::unique_ptr<emulators::SickLaserEmulator> inner;
  if (options.model == Model::lms200) {
    inner = std::make_unique<emulators::SickLms200Emulator>(laser);
  } else {
    inner = std::make_unique<emulators::SickPlsEmulator>(laser);
  }
  return std::make_unique<RefusingLaser>(std::move(inner));
}

// The emulated laser on the harness's line, and a laser:0 device of the
// driver on it (the harness's ConfiguredDevices).
class LaserRig {
 public:
  explicit LaserRig(RigOptions options = {})
      : options_(std::move(options)),
        line_([this] { return make_laser(options_); },
              {.tcp = options_.tcp, .symlink = options_.symlink, .faults = options_.faults}) {}
  LaserRig(const LaserRig&) = delete;
  LaserRig& operator=(const LaserRig&) = delete;

  [[nodiscard]] std::string driver_name() const {
    return options_.model == Model::lms200 ? "sicklms200" : "sickpls";
  }
  // Where the laser is plugged in (kept while it is unplugged).
  [[nodiscard]] const std::string& port() const { return line_.port(); }

  // The laser unplugged (its line closed) and, unless `back` is false, a
  // fresh one (powered up anew, faults and all) plugged in on the same
  // symlink: a USB adapter pulled and put back.
  void replug(bool back = true) { line_.replug(back); }

  // Declares laser:0 on the emulator's line with `options` (short reply
  // timeouts and retries by default, so that failures are quick).
  void load(const std::string& options = "", const std::string& timing = "reply_timeout 0.3 retry_interval 0.2") {
    load_on(port(), options + " " + timing);
  }
  void load_on(const std::string& port, const std::string& options) {
    devices_.load("laser:0 ( driver \"" + driver_name() + "\" port \"$PORT\" " + options + " )\n", port);
  }

  core::Device& laser() { return devices_.device(protocol::kLaserCode); }
  sick_laser::SickLaserDriver& driver() { return dynamic_cast<sick_laser::SickLaserDriver&>(laser().driver()); }

  // The next scan published from now on, or nullopt when none comes in `limit`.
  std::optional<protocol::LaserData> next_scan(std::chrono::milliseconds limit = 5s) {
    return drivers::testing::next_data<protocol::LaserData>(laser(), limit);
  }

  // Queues a request as client 1 and waits for its reply.
  std::optional<core::Reply> request(std::vector<std::uint8_t> payload, std::chrono::milliseconds limit = 5s) {
    laser().enqueue_request(drivers::testing::make_request(protocol::kLaserCode, std::move(payload)));
    return drivers::testing::next_reply(laser(), limit);
  }

  template <class Action>
  auto with_laser(Action&& action) {
    return line_.with([&](RefusingLaser& laser) { return action(laser); });
  }
  emulators::EmulatorRunner& runner() { return line_.runner(); }

  std::vector<std::string> log_lines() { return devices_.log.lines(); }
  // The first log line containing every fragment, or empty if none comes
  // within `wait`.
  std::string logged(std::initializer_list<std::string_view> fragments,
                     std::chrono::milliseconds wait = std::chrono::seconds(5)) {
    return devices_.log.first_with(fragments, wait);
  }
  std::string all_log() { return devices_.log.all(); }

 private:
  RigOptions options_;
  drivers::testing::EmulatedLine<RefusingLaser> line_;
  // Last: devices shut down (their drivers still talking to the laser)
  // before the emulator goes.
  drivers::testing::ConfiguredDevices devices_;

 public:
  drivers::testing::BuiltinDevices& builtin = devices_.builtin;
};

using drivers::testing::counter;

inline std::vector<std::uint8_t> config_request(std::int16_t min_angle, std::int16_t max_angle,
                                                std::uint16_t resolution, std::uint16_t range_res,
                                                std::uint8_t intensity) {
  protocol::LaserConfig config{protocol::kLaserSetConfig, min_angle, max_angle, resolution, range_res, intensity};
  return protocol::encode(config);
}

}  // namespace playerkit::drivers::sick_driver_test_support
