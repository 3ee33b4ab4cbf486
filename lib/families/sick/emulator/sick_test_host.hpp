#pragma once
// For the tests: the host end of a serial line to an emulated SICK laser,
// on a simulated clock. It writes requests at its own line speed, flushes
// its input before each (as the Player drivers do), and reads telegrams the
// way a driver's framed reader would (SickFrameFormat skips the ACK).

#include "families/sick/emulator/sick_laser_emulator.hpp"
#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/scan.hpp"
#include "families/sick/protocol/telegram.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

namespace playerkit::emulators::testing {

namespace sick = hardware::sick;
using namespace std::chrono_literals;

// A telegram as the host received it, with the time it was written.
struct Received {
  Duration at{};
  std::vector<std::uint8_t> bytes;
};

class TestHost {
 public:
  explicit TestHost(SickLaserEmulator& device, int baud = 9600) : device_(device), baud_(baud) {}

  Duration now() const { return now_; }
  void set_baud(int baud) { baud_ = baud; }

  // Flushes the input, then writes the request's telegram in one write().
  void send(const sick::Request& request) {
    line_.clear();
    write(sick::encode_request(request));
  }
  void write(const std::vector<std::uint8_t>& bytes) {
    device_.receive(bytes, now_, baud_);
    collect();
  }

  // Lets `span` pass, waking the device at each of its deadlines as a runner
  // does. Bounded: a device asking to be woken more than 100000 times a
  // simulated second fails the test.
  void wait(Duration span) {
    const Duration until = now_ + span;
    for (int steps = 0;; ++steps) {
      const Duration deadline = device_.next_deadline();
      if (deadline > until) break;
      if (steps > 100'000) {
        ADD_FAILURE() << "device deadlines do not advance";
        break;
      }
      now_ = std::max(now_, deadline);
      device_.advance(now_);
      collect();
    }
    now_ = until;
    device_.advance(now_);
    collect();
  }

  // The next whole reply telegram on the line, unframed; nullopt if none.
  std::optional<sick::Reply> next_reply() {
    const auto telegram = next_telegram();
    if (!telegram) return std::nullopt;
    return sick::unframe_reply(telegram->bytes);
  }

  // Sends a request and returns its answer, which must come at once.
  sick::Reply ask(const sick::Request& request) {
    send(request);
    auto reply = next_reply();
    if (!reply) {
      ADD_FAILURE() << "no answer to " << sick::describe(request);
      return {};
    }
    return *reply;
  }

  // Every whole telegram received so far, in order, consumed.
  std::vector<Received> drain() {
    std::vector<Received> all;
    while (auto telegram = next_telegram()) all.push_back(std::move(*telegram));
    return all;
  }

  // Whatever the device wrote, as written (ACK bytes included).
  const std::vector<std::pair<Duration, Telegram>>& writes() const { return writes_; }
  bool silent_since(std::size_t write_count) const { return writes_.size() == write_count; }

 private:
  void collect() {
    for (Telegram& telegram : device_.take_output()) {
      for (const std::uint8_t byte : telegram.bytes) line_.push_back({now_, byte});
      writes_.emplace_back(now_, std::move(telegram));
    }
  }

  std::optional<Received> next_telegram() {
    static const auto format = sick::SickFrameFormat::replies();
    std::vector<std::uint8_t> bytes;
    for (const auto& [at, byte] : line_) bytes.push_back(byte);
    std::size_t used = 0;
    std::optional<Received> found;
    while (used < bytes.size() && !found) {
      const auto scan = format.scan(std::span(bytes).subspan(used));
      if (scan.kind == framing::FrameScan::Kind::need_more) break;
      if (scan.kind == framing::FrameScan::Kind::frame) {
        found = Received{line_[used].first,
                         {bytes.begin() + static_cast<std::ptrdiff_t>(used),
                          bytes.begin() + static_cast<std::ptrdiff_t>(used + scan.length)}};
      } else if (scan.kind == framing::FrameScan::Kind::bad_checksum) {
        ADD_FAILURE() << "the device sent a telegram with a bad CRC";
      }
      used += scan.length;
    }
    line_.erase(line_.begin(), line_.begin() + static_cast<std::ptrdiff_t>(used));
    return found;
  }

  SickLaserEmulator& device_;
  int baud_;
  Duration now_{};
  std::vector<std::pair<Duration, std::uint8_t>> line_;
  std::vector<std::pair<Duration, Telegram>> writes_;
};

inline std::vector<sick::Scan> scans_of(const std::vector<Received>& telegrams) {
  std::vector<sick::Scan> scans;
  for (const Received& telegram : telegrams) {
    scans.push_back(sick::parse_scan(sick::unframe_reply(telegram.bytes)));
  }
  return scans;
}

}  // namespace playerkit::emulators::testing
