#pragma once
// Helpers for the readlog/writelog tests: small logs written with lib/log's
// writer, a scratch directory, and a replay timer the test moves by hand.

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "drivers/logfile/replay_timer.hpp"
#include "log/text_log_reader.hpp"
#include "log/text_log_writer.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "protocol/messages/position.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {

using ::playerkit::testing::ScratchDirectory;

inline std::vector<std::uint8_t> position_payload(std::int32_t x_mm) {
  protocol::PositionData data;
  data.xpos = x_mm;
  data.ypos = -x_mm / 2;
  data.yaw = 90;
  return protocol::encode(data);
}

inline protocol::Message data_message(protocol::DeviceAddress address, std::vector<std::uint8_t> payload,
                                      protocol::Timestamp logged, protocol::Timestamp data_time) {
  protocol::Message message;
  message.header = protocol::make_header(protocol::MessageType::kData, address, logged, data_time);
  message.payload = std::move(payload);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

// One logged position sample: logged at `logged`, data time 0.1 s earlier.
struct LoggedSample {
  std::uint16_t index;
  protocol::Timestamp logged;
  std::int32_t x_mm;
};

inline protocol::Timestamp data_time_of(protocol::Timestamp logged) {
  return {logged.usec >= 100000 ? logged.sec : logged.sec - 1, (logged.usec + 900000) % 1000000};
}

inline void write_position_log(const std::filesystem::path& path, const std::vector<LoggedSample>& samples) {
  std::ofstream out(path);
  out << log::log_file_header();
  for (const LoggedSample& sample : samples) {
    out << log::format_data_line(data_message({protocol::kPositionCode, sample.index},
                                              position_payload(sample.x_mm), sample.logged,
                                              data_time_of(sample.logged)),
                                 "testhost", 6665);
  }
}

// Every data line of a log file, in order.
inline std::vector<log::DataLine> read_data_lines(const std::filesystem::path& path) {
  std::ifstream in(path);
  log::TextLogReader reader(in, path.string());
  std::vector<log::DataLine> lines;
  for (int guard = 0; guard < 100000; ++guard) {
    const auto line = reader.next();
    if (!line) break;
    if (const auto* data = std::get_if<log::DataLine>(&*line)) lines.push_back(*data);
  }
  return lines;
}

// Time moves only when the test says so; the test can see what the replay
// waits for, so it knows the replay is held there.
class ManualReplayTimer final : public ReplayTimer {
 public:
  [[nodiscard]] std::chrono::nanoseconds now() const override {
    std::lock_guard lock(mutex_);
    return now_;
  }
  bool wait_until(std::chrono::nanoseconds deadline, const std::stop_token& stop) override {
    std::unique_lock lock(mutex_);
    waiting_for_ = deadline;
    const bool reached = moved_.wait(lock, stop, [&] { return now_ >= deadline; });
    waiting_for_.reset();
    return reached;
  }
  void set(std::chrono::nanoseconds time) {
    std::lock_guard lock(mutex_);
    now_ = time;
    moved_.notify_all();
  }
  [[nodiscard]] std::optional<std::chrono::nanoseconds> waiting_for() const {
    std::lock_guard lock(mutex_);
    return waiting_for_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable_any moved_;
  std::chrono::nanoseconds now_{0};
  std::optional<std::chrono::nanoseconds> waiting_for_;
};

}  // namespace playerkit::drivers::testing
