#pragma once
// For the tests of lib/families/p2os/emulator: a scripted host with a simulated
// clock, and the host-side odometry the 1.5 driver computes from SIPs,
// written here independently of the emulator.

#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/frame_format.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "families/p2os/protocol/sip.hpp"
#include "families/p2os/protocol/sync.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace playerkit::emulators::testing {

namespace hw = hardware::p2os;
using namespace std::chrono_literals;

using Frames = std::vector<std::vector<std::uint8_t>>;

using hardware::p2os::testing::hex;

// A host on the other end of the line: writes frames at the current
// simulated time, lets time pass, and keeps every packet the robot sent.
class Host {
 public:
  explicit Host(P2osRobotEmulator& robot) : robot_(robot) {}

  Duration now() const { return now_; }

  void send(const hw::Command& command, int baud = 0) { write(hw::command_frame(command), baud); }
  void send(std::uint8_t number) { send(hw::Command::plain(number)); }
  void send(std::uint8_t number, int value) { send(hw::Command::with_integer(number, value)); }

  void write(const std::vector<std::uint8_t>& bytes, int baud = 0) {
    robot_.receive(bytes, now_, baud);
    collect();
  }

  // Lets `span` pass, waking at the robot's deadlines as a runner would.
  void wait(Duration span) {
    const Duration end = now_ + span;
    for (int guard = 0; guard < 10'000'000 && now_ < end; ++guard) {
      now_ = std::min(end, std::max(robot_.next_deadline(), now_ + 1ms));
      robot_.advance(now_);
      collect();
    }
  }

  // Every frame received so far, oldest first; clears the list.
  std::vector<std::vector<std::uint8_t>> take_frames() {
    std::vector<std::vector<std::uint8_t>> out;
    out.swap(frames_);
    return out;
  }

  // The payloads of the frames received so far; clears the list.
  std::vector<std::vector<std::uint8_t>> take_packets() {
    std::vector<std::vector<std::uint8_t>> packets;
    for (const auto& frame : take_frames()) {
      const auto payload = hw::frame_payload(frame);
      packets.emplace_back(payload.begin(), payload.end());
    }
    return packets;
  }

  // The SIPs among the packets received so far; clears all packets.
  std::vector<hw::StandardSip> take_sips() {
    std::vector<hw::StandardSip> sips;
    for (const auto& packet : take_packets()) {
      if (hw::is_standard_sip(packet.at(0))) sips.push_back(hw::decode_sip(packet));
    }
    return sips;
  }

  // SYNC0, SYNC1, SYNC2 with the reference's pauses; returns the SYNC2 reply.
  hw::Sync2Reply synchronise() {
    send(hw::command::sync0);
    wait(400ms);
    send(hw::command::sync1);
    wait(200ms);
    send(hw::command::sync2);
    wait(200ms);
    auto packets = take_packets();
    EXPECT_EQ(packets.size(), 3u);
    if (packets.size() != 3u) return {};
    return hw::decode_sync2_reply(packets[2]);
  }

  // Sends `command` every 100 ms for `span`, as the 1.5 driver sends its
  // motor command every cycle.
  void keep_sending(const hw::Command& command, Duration span) {
    const Duration end = now_ + span;
    for (int guard = 0; guard < 1'000'000 && now_ < end; ++guard) {
      send(command);
      wait(std::min<Duration>(100ms, end - now_));
    }
  }

  // Handshake and OPEN; leaves nothing in the packet list.
  void connect() {
    synchronise();
    send(hw::command::open);
    EXPECT_TRUE(robot_.connected());
    take_frames();
  }

 private:
  void collect() {
    for (Telegram& telegram : robot_.take_output()) {
      // One packet per write, always with a correct checksum.
      EXPECT_TRUE(telegram.has_checksum);
      EXPECT_EQ(format_.scan(telegram.bytes).kind, framing::FrameScan::Kind::frame);
      EXPECT_EQ(format_.scan(telegram.bytes).length, telegram.bytes.size());
      frames_.push_back(std::move(telegram.bytes));
    }
  }

  P2osRobotEmulator& robot_;
  Duration now_{0};
  hw::P2osFrameFormat format_;
  std::vector<std::vector<std::uint8_t>> frames_;
};

// The shortest signed difference between two 12-bit counter readings.
inline int wrapped_difference(std::uint16_t now, std::uint16_t before) {
  int difference = (now & 0x0FFF) - (before & 0x0FFF);
  if (difference > 2048) difference -= 4096;
  if (difference < -2048) difference += 4096;
  return difference;
}

// Odometry as a host integrates it from SIPs: position in mm from the
// 12-bit XPOS/YPOS steps (starting at 0 with the first SIP), heading from
// THPOS directly.
struct SipOdometry {
  explicit SipOdometry(const hw::RobotParams& row) : params(row) {}

  void add(const hw::StandardSip& sip) {
    if (count > 0) {
      const int dx = wrapped_difference(sip.x_position, last_x);
      const int dy = wrapped_difference(sip.y_position, last_y);
      // The 1.5 driver drops a step over 100 mm; a faithful robot never sends one.
      EXPECT_LE(std::abs(dx * params.dist_conv_factor), 100.0);
      EXPECT_LE(std::abs(dy * params.dist_conv_factor), 100.0);
      x += dx * params.dist_conv_factor;
      y += dy * params.dist_conv_factor;
    }
    last_x = sip.x_position;
    last_y = sip.y_position;
    heading = sip.heading * params.angle_conv_factor;
    ++count;
  }

  const hw::RobotParams& params;
  double x = 0.0;        // mm
  double y = 0.0;        // mm
  double heading = 0.0;  // rad, 0 ... 2π
  int count = 0;
  std::uint16_t last_x = 0, last_y = 0;
};

// Angle difference in (-π, π].
inline double angle_between(double a, double b) {
  return std::remainder(a - b, 2.0 * 3.14159265358979323846);
}

}  // namespace playerkit::emulators::testing
