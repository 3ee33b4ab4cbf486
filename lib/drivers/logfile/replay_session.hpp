#pragma once
// One pass (or endless passes, with autorewind) over a Player text log, shared
// by every readlog device that reads the same file with the same options: one
// reader thread, as 1.5's readlog manager had, so devices stay in step.
//
// Pacing follows the time each line was logged (token 0, which writelog writes
// in file order): the line logged t seconds after the first one served goes
// out t / speed seconds after replay started. Data lines are published with
// their logged data time (token 5) as the timestamp. When a clock is given it
// is set to each line's logged time as the line goes out; the readlog devices
// of the -r log make it the server's clock (core::ServerClock), so the
// server's own header times follow the log. After the end of the file
// (without autorewind) it keeps running from the last logged time at `speed`.
//
// The thread starts at the first attach() and, as in 1.5, does not pause when
// devices detach: the log plays on like a live robot.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <thread>
#include <vector>

#include "core/clock.hpp"
#include "core/device.hpp"
#include "core/logger.hpp"
#include "drivers/logfile/replay_timer.hpp"
#include "log/log_clock.hpp"
#include "log/text_log_reader.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::drivers {

struct ReplayOptions {
  std::filesystem::path path;
  double speed = 1.0;        // > 0; 2 plays twice as fast
  bool autorewind = false;   // start again at the end of the file
  double start_offset = 0.0;  // seconds after the first logged line; earlier lines are skipped
  // Seconds of log to serve per pass from the start offset; later lines are
  // not served (with autorewind the next pass begins).
  std::optional<double> duration;
  // As fast as the clients read instead of at log pace: a line goes out once
  // every client reading a queued device it feeds has room for it in its
  // share of the device's queue, so nothing is dropped however slow a client
  // is. Devices without a data queue, or without readers, do not hold it
  // back; when no attached device has a reader the replay pauses. The first
  // line waits until no device has been attached for burst_settle, so that a
  // client opening several devices one after the other gets each from the
  // start however slowly its subscriptions come in.
  bool burst = false;
  std::chrono::milliseconds burst_settle{500};
};

// The time of the first sync or data line of the Player text log `path`:
// where a replay starts. Throws std::runtime_error naming the file when it
// cannot be opened, is a CARMEN log (saying what replays one: player-log), or
// has no line to replay; log::LogParseError for a file version it cannot read.
protocol::Timestamp first_replay_time(const std::filesystem::path& path);

class ReplaySession {
 public:
  // Opens the log and reads up to its first sync or data line, so that a
  // missing, unreadable or empty log is refused before serving starts (throws
  // what first_replay_time throws). `clock` may be null; `timer`
  // null means real time.
  ReplaySession(ReplayOptions options, std::shared_ptr<core::ManualClock> clock,
                std::shared_ptr<ReplayTimer> timer, core::Logger& logger);
  ~ReplaySession();
  ReplaySession(const ReplaySession&) = delete;
  ReplaySession& operator=(const ReplaySession&) = delete;

  // `device` gets every logged data line of `logged` from now on.
  void attach(core::Device& device, protocol::DeviceAddress logged);
  // After this returns, nothing more is published on `device`.
  void detach(core::Device& device);

  [[nodiscard]] const ReplayOptions& options() const { return options_; }
  // The clock this session sets to log time; null when it sets none.
  [[nodiscard]] std::shared_ptr<const core::Clock> clock() const { return clock_; }
  [[nodiscard]] protocol::Timestamp first_log_time() const { return first_log_time_; }
  // Lines that could not be read (skipped with a warning).
  [[nodiscard]] std::uint64_t malformed_lines() const { return malformed_lines_; }

 private:
  struct Target {
    core::Device* device;
    protocol::DeviceAddress logged;
  };

  void run(const std::stop_token& stop);
  // One pass over the file; false when stopped. `served` counts lines served.
  bool replay_file(const std::stop_token& stop, std::uint64_t& served);
  void follow_clock_after_end(const std::stop_token& stop);
  void deliver(const log::DataLine& line, const std::stop_token& stop);
  // Burst: false when stopped while no attached device had a reader.
  bool wait_for_any_reader(const std::stop_token& stop);
  // Burst: until burst_settle has passed since the last attach(); false when stopped.
  bool wait_for_attachments_to_settle(const std::stop_token& stop);

  const ReplayOptions options_;
  const std::shared_ptr<core::ManualClock> clock_;
  const std::shared_ptr<ReplayTimer> timer_;
  core::Logger& logger_;
  std::shared_ptr<const log::LogClock> log_clock_;  // replaces the log's unusable times
  protocol::Timestamp first_log_time_;
  protocol::Timestamp last_log_time_;
  std::atomic<std::uint64_t> malformed_lines_{0};
  bool settled_ = false;  // burst: the first line has waited burst_settle (reader thread only)

  std::mutex targets_mutex_;  // held while publishing, so detach() waits for it
  std::vector<Target> targets_;
  bool started_ = false;  // under targets_mutex_
  std::chrono::nanoseconds last_attach_{0};  // timer_ time of the last attach(), under targets_mutex_
  std::jthread thread_;   // last: stops before the rest goes
};

}  // namespace playerkit::drivers
