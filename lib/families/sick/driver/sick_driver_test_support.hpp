#pragma once
// For the sick driver tests: an emulated laser on a real pseudo-terminal
// (or a loopback TCP port) in a hand-made room, a device built from config
// text as the server builds it, and bounded waits for scans and replies.

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "families/sick/driver/sick_laser_driver.hpp"
#include "drivers/test_support.hpp"
#include "emulators/runner/emulator_runner.hpp"
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

inline std::unique_ptr<emulators::DeviceEmulator> make_laser(const RigOptions& options) {
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

inline emulators::Endpoint endpoint_of(const RigOptions& options) {
  if (options.tcp) return emulators::TcpEndpoint{};
  return emulators::PtyEndpoint{options.symlink};
}

// The emulated laser, and a laser:0 device of the driver on its line.
class LaserRig {
 public:
  explicit LaserRig(RigOptions options = {})
      : options_(std::move(options)),
        runner_(std::make_unique<emulators::EmulatorRunner>(make_laser(options_), endpoint_of(options_),
                                                            options_.faults)),
        port_(runner_->device_path()) {
    builtin.logger.set_sink([this](core::LogLevel, std::string_view line) {
      std::lock_guard lock(log_mutex_);
      log_.emplace_back(line);
    });
  }
  LaserRig(const LaserRig&) = delete;
  LaserRig& operator=(const LaserRig&) = delete;

  [[nodiscard]] std::string driver_name() const {
    return options_.model == Model::lms200 ? "sicklms200" : "sickpls";
  }
  // Where the laser is plugged in (kept while it is unplugged).
  [[nodiscard]] const std::string& port() const { return port_; }

  // The laser unplugged (its line closed) and, unless `back` is false, a
  // fresh one (powered up anew, faults and all) plugged in on the same
  // symlink: a USB adapter pulled and put back.
  void replug(bool back = true) {
    runner_.reset();
    if (back) {
      runner_ = std::make_unique<emulators::EmulatorRunner>(make_laser(options_), endpoint_of(options_),
                                                            options_.faults);
      port_ = runner_->device_path();
    }
  }

  // Declares laser:0 on the emulator's line with `options` (short reply
  // timeouts and retries by default, so that failures are quick).
  void load(const std::string& options = "", const std::string& timing = "reply_timeout 0.3 retry_interval 0.2") {
    load_on(port(), options + " " + timing);
  }
  void load_on(const std::string& port, const std::string& options) {
    builtin.load("laser:0 ( driver \"" + driver_name() + "\" port \"" + port + "\" " + options + " )\n");
  }

  core::Device& laser() { return builtin.device(protocol::kLaserCode); }
  sick_laser::SickLaserDriver& driver() { return dynamic_cast<sick_laser::SickLaserDriver&>(laser().driver()); }

  // The next scan published from now on, or nullopt when none comes in `limit`.
  std::optional<protocol::LaserData> next_scan(std::chrono::milliseconds limit = 5s) {
    const std::uint64_t seen = laser().latest_data()->sequence;
    if (!drivers::testing::eventually([&] { return laser().latest_data()->sequence > seen; }, limit)) {
      return std::nullopt;
    }
    return protocol::decode<protocol::LaserData>(laser().latest_data()->payload);
  }

  // Queues a request as client 1 and waits for its reply.
  std::optional<core::Reply> request(std::vector<std::uint8_t> payload, std::chrono::milliseconds limit = 5s) {
    laser().enqueue_request(drivers::testing::make_request(protocol::kLaserCode, std::move(payload)));
    std::vector<core::Reply> replies;
    drivers::testing::eventually(
        [&] {
          for (auto& reply : laser().take_replies()) replies.push_back(std::move(reply));
          return !replies.empty();
        },
        limit);
    if (replies.empty()) return std::nullopt;
    return replies.front();
  }

  template <class Action>
  auto with_laser(Action&& action) {
    return runner_->with_emulator<RefusingLaser>([&](RefusingLaser& laser) { return action(laser); });
  }
  emulators::EmulatorRunner& runner() { return *runner_; }

  std::vector<std::string> log_lines() {
    std::lock_guard lock(log_mutex_);
    return log_;
  }
  // The first log line containing every fragment, or empty if none comes
  // within `wait`: a driver changes its state (unavailable, available) and
  // then logs it, so a test that saw the change may ask a moment early.
  std::string logged(std::initializer_list<std::string_view> fragments,
                     std::chrono::milliseconds wait = std::chrono::seconds(5)) {
    const auto deadline = std::chrono::steady_clock::now() + wait;
    for (;;) {
      for (const std::string& line : log_lines()) {
        bool all = true;
        for (std::string_view fragment : fragments) all = all && line.find(fragment) != std::string::npos;
        if (all) return line;
      }
      if (std::chrono::steady_clock::now() >= deadline) return {};
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  std::string all_log() {
    std::string text;
    for (const auto& line : log_lines()) text += line + "\n";
    return text;
  }

 private:
  RigOptions options_;
  std::unique_ptr<emulators::EmulatorRunner> runner_;
  std::string port_;
  std::mutex log_mutex_;
  std::vector<std::string> log_;

 public:
  // Last: devices shut down (their drivers still talking to the laser)
  // before the emulator goes.
  drivers::testing::BuiltinDevices builtin;
};

inline std::uint64_t counter(const core::Driver& driver, std::string_view name) {
  for (const auto& c : driver.counters()) {
    if (c.name == name) return c.value;
  }
  ADD_FAILURE() << "no counter " << name;
  return 0;
}

inline std::vector<std::uint8_t> config_request(std::int16_t min_angle, std::int16_t max_angle,
                                                std::uint16_t resolution, std::uint16_t range_res,
                                                std::uint8_t intensity) {
  protocol::LaserConfig config{protocol::kLaserSetConfig, min_angle, max_angle, resolution, range_res, intensity};
  return protocol::encode(config);
}

}  // namespace playerkit::drivers::sick_driver_test_support
