#pragma once
// `readlog` (manual §7.36): serves the data of a Player text log as devices.
//
//   player-serve -r run.log [-f 2] robot.cfg      robot.cfg: laser:0 ( driver "readlog" )
//
// Every readlog device replays the logged device of its own interface and the
// `index` option (default: its own index) from the log named by -r or by its
// `filename` option; `speed` (default -f, else 1), `autorewind` (0/1) and
// `start` (seconds into the log) shape the replay. Devices reading the same
// file with the same options share one reader (replay_session.hpp); the
// devices of the reader for the -r file claim the server's clock
// (core::ServerClock) with the log's time. Every configuration request is
// answered NACK. See README.md for the differences from 1.5.

#include <filesystem>
#include <memory>
#include <optional>

#include "core/clock.hpp"
#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "drivers/logfile/replay_session.hpp"
#include "drivers/logfile/replay_timer.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::drivers {

class ReadlogDriver final : public core::Driver {
 public:
  ReadlogDriver(std::shared_ptr<ReplaySession> session, protocol::DeviceAddress logged);

  void setup() override;
  void shutdown() override;

  [[nodiscard]] const ReplaySession& session() const { return *session_; }
  [[nodiscard]] protocol::DeviceAddress logged() const { return logged_; }

 private:
  std::shared_ptr<ReplaySession> session_;
  protocol::DeviceAddress logged_;
};

// What the command line gives every readlog device.
struct ReadlogSettings {
  std::optional<std::filesystem::path> log;  // -r
  double speed = 1.0;                        // -f
  // Null: real time. Tests pass one they control.
  std::shared_ptr<ReplayTimer> timer;
  // Samples each device keeps for clients that fall behind (0: the latest
  // only, as in 1.5). `player-log replay` queues, so a client reading at its
  // own pace still gets every scan.
  std::size_t data_queue = 0;
  // ReplayOptions::duration and ::burst for every device (burst needs a
  // queue: 64 samples if data_queue is 0).
  std::optional<double> duration;
  bool burst = false;
};

// Without settings (no -r) a readlog device needs a `filename` option.
core::DriverSpec readlog_driver_spec(ReadlogSettings settings = {});

}  // namespace playerkit::drivers
