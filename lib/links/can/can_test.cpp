// slcan text (the Lawicel protocol) and CAN frames over a link: codec golden
// lines, the adapter handshake and frames both ways over a pseudo-terminal,
// and SocketCAN where a vcan interface exists.
#include <gtest/gtest.h>

#include <poll.h>
#include <unistd.h>

#include <string>
#include <thread>

#include "links/can/can_bus.hpp"
#include "links/can/slcan.hpp"
#include "links/can/socketcan_link.hpp"
#include "links/exchange.hpp"
#include "links/open_link.hpp"
#include "links/pseudo_terminal.hpp"

namespace playerkit::links::can {
namespace {

using namespace std::chrono_literals;

framing::CanFrame standard(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  framing::CanFrame frame{.id = id, .extended = false, .remote = false, .dlc = static_cast<std::uint8_t>(bytes.size()), .data = {}};
  std::copy(bytes.begin(), bytes.end(), frame.data.begin());
  return frame;
}

TEST(Slcan, FramesAreLawicelLines) {
  EXPECT_EQ(slcan_frame_line(standard(0x413, {0x00, 0xA4, 0x00, 0x4E, 0, 0, 0, 0})), "t413800A4004E00000000\r");
  EXPECT_EQ(slcan_frame_line(standard(0x7FF, {})), "t7FF0\r");
  framing::CanFrame extended{.id = 0x1ABCDEF0, .extended = true, .remote = false, .dlc = 1, .data = {0x5A}};
  EXPECT_EQ(slcan_frame_line(extended), "T1ABCDEF015A\r");
  framing::CanFrame remote{.id = 0x123, .extended = false, .remote = true, .dlc = 2, .data = {}};
  EXPECT_EQ(slcan_frame_line(remote), "r1232\r");
}

TEST(Slcan, LinesParseBackAndMalformedOnesAreRefused) {
  EXPECT_EQ(parse_slcan_frame("t413800A4004E00000000"), standard(0x413, {0x00, 0xA4, 0x00, 0x4E, 0, 0, 0, 0}));
  EXPECT_EQ(parse_slcan_frame("t4002abcd"), standard(0x400, {0xAB, 0xCD}));
  EXPECT_EQ(parse_slcan_frame("t4002ABCD1234"), standard(0x400, {0xAB, 0xCD}));  // with a timestamp
  EXPECT_EQ(parse_slcan_frame("T1ABCDEF015A")->id, 0x1ABCDEF0u);
  EXPECT_FALSE(parse_slcan_frame("").has_value());
  EXPECT_FALSE(parse_slcan_frame("t4009").has_value());        // length above 8
  EXPECT_FALSE(parse_slcan_frame("t40020011223").has_value());  // odd digits
  EXPECT_FALSE(parse_slcan_frame("t4G0").has_value());
  EXPECT_FALSE(parse_slcan_frame("O").has_value());
  EXPECT_FALSE(parse_slcan_frame("T2FFFFFFF0").has_value());  // beyond 29 bits
}

TEST(Slcan, BitRatesAreTheNineCodes) {
  EXPECT_EQ(slcan_bitrate_command(500000), "S6\r");
  EXPECT_EQ(slcan_bitrate_command(10000), "S0\r");
  EXPECT_EQ(slcan_bitrate_command(1000000), "S8\r");
  EXPECT_FALSE(slcan_bitrate_command(333333).has_value());
  EXPECT_EQ(slcan_bitrate_of('6'), 500000);
  EXPECT_FALSE(slcan_bitrate_of('9').has_value());
}

TEST(Slcan, FormatCutsLinesAndBells) {
  const SlcanFormat format;
  const std::string text = "\at4000\r";
  const std::span bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  EXPECT_EQ(format.scan(bytes).kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(format.scan(bytes).length, 1u);
  EXPECT_EQ(format.scan(bytes.subspan(1)).length, 6u);
  EXPECT_EQ(format.scan(bytes.subspan(1, 3)).kind, framing::FrameScan::Kind::need_more);
  const std::string runaway(40, 'x');
  EXPECT_EQ(format.scan(std::span(reinterpret_cast<const std::uint8_t*>(runaway.data()), runaway.size())).kind,
            framing::FrameScan::Kind::skip);
}

// An adapter on the far side of a pty: acknowledges S, O and C, refuses
// anything else with a BEL, and sends one frame once open.
class FakeAdapter {
 public:
  explicit FakeAdapter(PseudoTerminal& pty) : pty_(pty) {}
  // Reads commands until `want` has been seen, answering each.
  std::string serve_until(const std::string& want, std::chrono::milliseconds limit) {
    const auto give_up = std::chrono::steady_clock::now() + limit;
    std::string seen;
    while (seen.find(want) == std::string::npos && std::chrono::steady_clock::now() < give_up) {
      pollfd poll_fd{.fd = pty_.master_fd(), .events = POLLIN, .revents = 0};
      if (::poll(&poll_fd, 1, 50) <= 0) continue;
      char buffer[64];
      const ssize_t got = ::read(pty_.master_fd(), buffer, sizeof buffer);
      if (got <= 0) continue;
      for (ssize_t index = 0; index < got; ++index) {
        typed_.push_back(buffer[index]);
        if (buffer[index] != '\r') continue;
        const std::string command = typed_;
        typed_.clear();
        seen += command;
        std::string reply;
        if (command == "\r") {
          reply = "";
        } else if (command == "S6\r" || command == "O\r" || command == "C\r" || command.front() == 't') {
          reply = "\r";
        } else {
          reply = "\a";
        }
        if (command == "O\r") reply += "t4011" "7F\r";
        if (!reply.empty()) (void)::write(pty_.master_fd(), reply.data(), reply.size());
      }
    }
    return seen;
  }

 private:
  PseudoTerminal& pty_;
  std::string typed_;
};

TEST(CanBusOverSlcan, OpensTheChannelThenCarriesFramesBothWays) {
  PseudoTerminal pty;
  FakeAdapter adapter(pty);
  auto link = open_link(pty.slave_path(), {.baud = 115200});
  CanBus bus(*link, CanTransport::slcan);
  std::string seen;
  std::thread answering([&] { seen = adapter.serve_until("t4132", 5s); });
  bus.start(500000, 2s);
  const auto frame = bus.receive(deadline_in(2s));
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(*frame, standard(0x401, {0x7F}));
  bus.send(standard(0x413, {0x12, 0x34}), deadline_in(1s));
  answering.join();
  EXPECT_NE(seen.find("C\rS6\rO\r"), std::string::npos) << seen;
  EXPECT_NE(seen.find("t41321234\r"), std::string::npos) << seen;
}

TEST(CanBusOverSlcan, AnUnknownBitRateIsRefusedBeforeAnythingIsSent) {
  PseudoTerminal pty;
  auto link = open_link(pty.slave_path(), {.baud = 115200});
  CanBus bus(*link, CanTransport::slcan);
  EXPECT_THROW(bus.start(123456, 100ms), ExchangeError);
}

TEST(CanBusOverSlcan, ASilentLineFailsTheHandshakeAtItsDeadline) {
  PseudoTerminal pty;
  auto link = open_link(pty.slave_path(), {.baud = 115200});
  CanBus bus(*link, CanTransport::slcan);
  const auto began = std::chrono::steady_clock::now();
  EXPECT_THROW(bus.start(500000, 200ms), ExchangeError);
  EXPECT_LT(std::chrono::steady_clock::now() - began, 3s);
}

TEST(SocketCan, AMissingInterfaceIsNamed) {
  const std::string reason = socketcan_unavailable_reason("nosuchcan7");
  EXPECT_NE(reason.find("nosuchcan7"), std::string::npos) << reason;
}

TEST(SocketCan, FramesGoBetweenTwoSocketsOnVcan0) {
  const std::string reason = socketcan_unavailable_reason("vcan0");
  if (!reason.empty()) GTEST_SKIP() << "no vcan0 here (" << reason << "); SocketCAN is tested where one exists";
  SocketCanLink sender("vcan0", {});
  SocketCanLink receiver("vcan0", {{0x400, 0x7F8}});
  CanBus out(sender, CanTransport::socketcan);
  CanBus in(receiver, CanTransport::socketcan);
  out.send(standard(0x413, {1, 2}), deadline_in(1s));  // filtered out
  out.send(standard(0x402, {3, 4, 5}), deadline_in(1s));
  const auto frame = in.receive(deadline_in(2s));
  ASSERT_TRUE(frame.has_value());
  EXPECT_EQ(*frame, standard(0x402, {3, 4, 5}));
}

}  // namespace
}  // namespace playerkit::links::can
