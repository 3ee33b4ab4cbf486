#include "links/pseudo_terminal.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "links/link_error.hpp"
#include "links/links_test_support.hpp"
#include "links/serial_link.hpp"

namespace playerkit::links {
namespace pseudo_terminal_test {

using namespace test_support;

// Waits (bounded) for the host to open or close; true when it happened.
bool await_host(PseudoTerminal& pty, bool connected) {
  const Deadline deadline = deadline_in(kPatience);
  std::uint8_t sink[64];
  while (pty.host_connected() != connected && LinkClock::now() < deadline) pty.read_some(sink, deadline);
  return pty.host_connected() == connected;
}

TEST(PseudoTerminal, SlaveExistsAndStartsRaw) {
  PseudoTerminal pty;
  EXPECT_TRUE(std::filesystem::exists(pty.slave_path()));
  EXPECT_EQ(pty.path(), pty.slave_path());
  EXPECT_GE(pty.master_fd(), 0);
  EXPECT_TRUE(pty.slave_line().raw);
  EXPECT_FALSE(pty.host_connected());
}

TEST(PseudoTerminal, SymlinkLivesAsLongAsThePty) {
  TemporaryDirectory directory;
  const auto link = directory.path() / "ttyEMU0";
  std::string slave;
  {
    PseudoTerminal pty(link);
    slave = pty.slave_path();
    EXPECT_EQ(pty.path(), link.string());
    EXPECT_EQ(std::filesystem::read_symlink(link), slave);
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(PseudoTerminal, StaleSymlinkIsReplacedButAFileIsNot) {
  TemporaryDirectory directory;
  const auto link = directory.path() / "ttyEMU0";
  std::filesystem::create_symlink("/dev/pts/does-not-exist", link);
  {
    PseudoTerminal pty(link);
    EXPECT_EQ(std::filesystem::read_symlink(link), pty.slave_path());
  }
  const auto file = directory.path() / "precious";
  { std::ofstream(file) << "keep me"; }
  try {
    PseudoTerminal pty(file);
    FAIL() << "replaced a regular file";
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::busy);
    EXPECT_NE(std::string(error.what()).find("not a symlink"), std::string::npos);
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(file));
}

TEST(PseudoTerminal, BothWaysThroughTheSlave) {
  PseudoTerminal pty;
  auto host = SerialLink::open(pty.path(), {.baud = 38400});
  const Bytes request = {0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00};
  host->write_all(request, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(pty, request.size()), request);
  const Bytes reply = {0x02, 0x80, 0x03, 0x00, 0xA0, 0x00, 0x10, 0x16, 0x0A};
  ASSERT_TRUE(pty.write_all(reply, deadline_in(kPatience)));
  EXPECT_EQ(read_exactly(*host, reply.size()), reply);
}

TEST(PseudoTerminal, BytesWrittenWhileNobodyListensWaitForTheNextOpener) {
  PseudoTerminal pty;
  const Bytes early = {0x06, 0x02, 0x80};
  ASSERT_TRUE(pty.write_all(early, deadline_in(kPatience)));
  auto host = SerialLink::open(pty.path(), {.flush_on_open = false});
  EXPECT_EQ(read_exactly(*host, early.size()), early);
}

TEST(PseudoTerminal, SeesTheHostOpenCloseAndReopen) {
  PseudoTerminal pty;
  std::uint8_t buffer[16];
  for (int session = 0; session < 3; ++session) {
    auto host = SerialLink::open(pty.path(), {});
    ASSERT_TRUE(await_host(pty, true)) << "session " << session;
    const Bytes hello = {static_cast<std::uint8_t>(session)};
    host->write_all(hello, deadline_in(kPatience));
    EXPECT_EQ(read_exactly(pty, 1), hello);
    host.reset();
    ASSERT_TRUE(await_host(pty, false)) << "session " << session;
    // Closed: the master is hung up, and a read waits (it does not spin)
    // until the deadline without reporting anything.
    const auto quiet = pty.read_some(buffer, deadline_in(20ms));
    EXPECT_EQ(quiet.count, 0u);
    EXPECT_FALSE(quiet.host_opened);
    // Writing meanwhile keeps the pty usable.
    EXPECT_TRUE(pty.write_all(hello, deadline_in(kPatience)));
  }
}

TEST(PseudoTerminal, ReportsTheCloseOnceWithTheLastBytes) {
  PseudoTerminal pty;
  const int host = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  ASSERT_TRUE(await_host(pty, true));
  ASSERT_EQ(::write(host, "bye", 3), 3);
  ::close(host);
  std::uint8_t buffer[16];
  std::size_t total = 0;
  int closes = 0;
  const Deadline deadline = deadline_in(kPatience);
  while ((total < 3 || closes == 0) && LinkClock::now() < deadline) {
    const auto got = pty.read_some(buffer, deadline);
    total += got.count;
    closes += got.host_closed ? 1 : 0;
  }
  EXPECT_EQ(total, 3u);
  EXPECT_EQ(closes, 1);
  EXPECT_EQ(pty.read_some(buffer, deadline_in(10ms)).host_closed, false);
}

TEST(PseudoTerminal, AHostThatClosesAndReopensBetweenTwoReadsIsANewSession) {
  PseudoTerminal pty;
  int host = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  ASSERT_TRUE(await_host(pty, true));
  ::close(host);
  host = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  ASSERT_EQ(::write(host, "hi", 2), 2);
  std::uint8_t buffer[16];
  const auto got = pty.read_some(buffer, deadline_in(kPatience));
  EXPECT_TRUE(got.host_closed);
  EXPECT_TRUE(got.host_opened);
  EXPECT_TRUE(got.host_reopened);  // the close came first
  EXPECT_EQ(got.count, 2u);
  EXPECT_TRUE(pty.host_connected());
  // Open, then closed again before anyone read: not a reopen any more.
  ::close(host);
  host = ::open(pty.slave_path().c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  ::close(host);
  std::size_t closes = 0, reopens = 0;
  const Deadline deadline = deadline_in(kPatience);
  while (pty.host_connected() && LinkClock::now() < deadline) {
    const auto next = pty.read_some(buffer, deadline);
    closes += next.host_closed ? 1 : 0;
    reopens += next.host_reopened ? 1 : 0;
  }
  EXPECT_FALSE(pty.host_connected());
  EXPECT_EQ(closes, 1u);
  EXPECT_EQ(reopens, 0u);
}

TEST(PseudoTerminal, ReadTimesOutAtTheDeadline) {
  PseudoTerminal pty;
  auto host = SerialLink::open(pty.path(), {});
  ASSERT_TRUE(await_host(pty, true));
  std::uint8_t buffer[4];
  const Deadline deadline = deadline_in(30ms);
  const auto got = pty.read_some(buffer, deadline);
  EXPECT_EQ(got.count, 0u);
  EXPECT_GE(LinkClock::now(), deadline);
}

TEST(PseudoTerminal, SlaveBaudFollowsTheHost) {
  PseudoTerminal pty;
  auto host = SerialLink::open(pty.path(), {.baud = 9600});
  EXPECT_EQ(pty.slave_baud(), 9600);
  host->set_baud(38400);
  EXPECT_EQ(pty.slave_baud(), 38400);
  // 500000 is a B-constant on Linux; 250000 is not and goes through BOTHER.
  host->set_baud(500000);
  EXPECT_EQ(pty.slave_baud(), 500000);
  host->set_baud(250000);
  EXPECT_EQ(pty.slave_baud(), 250000);
  EXPECT_TRUE(pty.slave_line().custom_speed);
  EXPECT_EQ(host->baud(), 250000);
  EXPECT_EQ(host->describe(), pty.path() + " at 250000 8N1");
}

TEST(PseudoTerminal, StopBitsAndFlowControlAreVisibleOnTheMaster) {
  PseudoTerminal pty;
  {
    auto pls = SerialLink::open(pty.path(), with_framing("8E1", {.baud = 38400}));
    const TerminalLine line = pty.slave_line();
    EXPECT_EQ(line.output_baud, 38400);
    EXPECT_EQ(line.input_baud, 38400);
    EXPECT_EQ(line.stop_bits, 1);
    EXPECT_EQ(line.flow_control, FlowControl::none);
    EXPECT_TRUE(line.raw);
  }
  SerialSettings settings = with_framing("7O2", {.baud = 4800});
  settings.flow_control = FlowControl::hardware;
  auto reb = SerialLink::open(pty.path(), settings);
  const TerminalLine line = pty.slave_line();
  EXPECT_EQ(line.stop_bits, 2);
  EXPECT_EQ(line.flow_control, FlowControl::hardware);
  EXPECT_EQ(line.output_baud, 4800);
  // Linux's pty driver rewrites every termios change to CS8 without PARENB
  // (pty_set_termios), so data bits and parity never reach the master: an
  // emulator cannot check them. Should a kernel ever pass them through, this
  // fails and the README's note on parity must change.
  EXPECT_EQ(line.data_bits, 8);
  EXPECT_EQ(line.parity, Parity::none);
  EXPECT_EQ(reb->describe(), pty.path() + " at 4800 7O2 rtscts");
}

}  // namespace pseudo_terminal_test
}  // namespace playerkit::links
