#include "links/serial_link.hpp"

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "links/fd_io.hpp"
#include "links/links_test_support.hpp"
#include "links/link_error.hpp"

namespace playerkit::links {
namespace serial_link_test {

using namespace test_support;

LinkError open_error(const std::string& path, const SerialSettings& settings = {}) {
  try {
    SerialLink::open(path, settings);
  } catch (const LinkError& error) {
    return error;
  }
  ADD_FAILURE() << path << " opened";
  return LinkError(LinkErrorKind::io_error, path, "opened");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SerialLink, DescribesItself) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {.baud = 38400});
  EXPECT_EQ(link->describe(), pty.path() + " at 38400 8N1");
  EXPECT_EQ(link->path(), pty.path());
  EXPECT_TRUE(link->is_open());
  EXPECT_GE(link->native_handle(), 0);
}

TEST(SerialLink, SecondOpenIsBusyAndNamesUs) {
  PseudoTerminal pty;
  auto first = SerialLink::open(pty.path(), {});
  const LinkError error = open_error(pty.path());
  EXPECT_EQ(error.kind(), LinkErrorKind::busy);
  EXPECT_EQ(error.port(), pty.path());
  const std::string message = error.what();
  EXPECT_TRUE(contains(message, pty.path() + " is busy")) << message;
  EXPECT_TRUE(contains(message, "pid " + std::to_string(::getpid()))) << message;
  EXPECT_TRUE(contains(message, "holds the lock")) << message;
  // Released on close: the next open succeeds.
  first.reset();
  EXPECT_NO_THROW(SerialLink::open(pty.path(), {}));
}

TEST(SerialLink, NonExclusiveOpensShare) {
  PseudoTerminal pty;
  auto first = SerialLink::open(pty.path(), {.exclusive = false});
  EXPECT_NO_THROW(SerialLink::open(pty.path(), {.exclusive = false}));
}

TEST(SerialLink, MissingPortListsSimilarOnes) {
  TemporaryDirectory directory;
  for (const char* name : {"ttyFAKE1", "ttyFAKE10", "ttyFAKE2", "other"}) {
    std::ofstream(directory.path() / name).put('x');
  }
  const std::string missing = (directory.path() / "ttyFAKE0").string();
  const LinkError error = open_error(missing);
  EXPECT_EQ(error.kind(), LinkErrorKind::missing);
  const std::string message = error.what();
  EXPECT_TRUE(contains(message, "no such port " + missing + "; is the adapter plugged in?")) << message;
  const std::string dir = directory.path().string();
  EXPECT_TRUE(contains(message, dir + "/ttyFAKE1, " + dir + "/ttyFAKE2, " + dir + "/ttyFAKE10")) << message;
  EXPECT_FALSE(contains(message, "other")) << message;
}

TEST(SerialLink, MissingPortWithNothingSimilar) {
  TemporaryDirectory directory;
  const LinkError error = open_error((directory.path() / "ttyNONE0").string());
  EXPECT_EQ(error.kind(), LinkErrorKind::missing);
  EXPECT_TRUE(contains(error.what(), "No similar ports exist here.")) << error.what();
}

TEST(SerialLink, RegularFileIsNotATerminal) {
  TemporaryDirectory directory;
  const auto file = directory.path() / "capture.bin";
  std::ofstream(file).put('x');
  const LinkError error = open_error(file.string());
  EXPECT_EQ(error.kind(), LinkErrorKind::not_a_terminal);
  EXPECT_TRUE(contains(error.what(), file.string() + " is not a serial port")) << error.what();
}

TEST(SerialLink, DirectoryIsNotATerminal) {
  TemporaryDirectory directory;
  const LinkError error = open_error(directory.path().string());
  EXPECT_EQ(error.kind(), LinkErrorKind::not_a_terminal);
  EXPECT_TRUE(contains(error.what(), "is a directory, not a serial port")) << error.what();
}

TEST(SerialLink, CharacterDeviceThatIsNoTerminal) {
  const LinkError error = open_error("/dev/null");
  EXPECT_EQ(error.kind(), LinkErrorKind::not_a_terminal);
}

TEST(SerialLink, UnreadableFileIsRefused) {
  if (::geteuid() == 0) GTEST_SKIP() << "root opens mode-000 files; port_diagnosis_test covers the advice text";
  TemporaryDirectory directory;
  const auto file = directory.path() / "ttyLOCKED";
  std::ofstream(file).put('x');
  ::chmod(file.c_str(), 0);
  const LinkError error = open_error(file.string());
  EXPECT_EQ(error.kind(), LinkErrorKind::permission_denied);
  EXPECT_TRUE(contains(error.what(), "permission denied opening " + file.string())) << error.what();
}

TEST(SerialLink, BadSettingsAreRefusedBeforeOpening) {
  PseudoTerminal pty;
  const LinkError error = open_error(pty.path(), {.data_bits = 9});
  EXPECT_EQ(error.kind(), LinkErrorKind::bad_settings);
  // Nothing was taken: the port opens normally afterwards.
  EXPECT_NO_THROW(SerialLink::open(pty.path(), {}));
}

TEST(SerialLink, ReadWaitsForTheDeadlineThenReturnsZero) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {});
  std::uint8_t buffer[8];
  const Deadline deadline = deadline_in(30ms);
  EXPECT_EQ(link->read_some(buffer, deadline), 0u);
  EXPECT_GE(LinkClock::now(), deadline);
  // A deadline already past checks once without waiting.
  EXPECT_EQ(link->read_some(buffer, LinkClock::now() - 1s), 0u);
  const Bytes ready = {1, 2, 3};
  ASSERT_TRUE(pty.write_all(ready, deadline_in(kPatience)));
  EXPECT_EQ(read_exactly(*link, 3), ready);
}

TEST(SerialLink, CountsAndTracesBothDirections) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {});
  std::vector<std::pair<Direction, Bytes>> traced;
  link->set_trace_hook([&](Direction direction, std::span<const std::uint8_t> bytes, LinkClock::time_point) {
    traced.emplace_back(direction, Bytes(bytes.begin(), bytes.end()));
  });
  const Bytes out = {0x02, 0x00, 0x01, 0x00, 0x3A, 0x1E, 0x12};
  link->write_all(out, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(pty, out.size()), out);
  const Bytes in = {0x06};
  ASSERT_TRUE(pty.write_all(in, deadline_in(kPatience)));
  EXPECT_EQ(read_exactly(*link, 1), in);
  ASSERT_EQ(traced.size(), 2u);
  EXPECT_EQ(traced[0], std::make_pair(Direction::out, out));
  EXPECT_EQ(traced[1], std::make_pair(Direction::in, in));
  const auto counters = link->counters().snapshot();
  EXPECT_EQ(counters.bytes_out, out.size());
  EXPECT_EQ(counters.bytes_in, 1u);
  link->set_trace_hook({});
  link->write_all(out, deadline_in(kPatience));
  EXPECT_EQ(traced.size(), 2u);
}

TEST(SerialLink, FlushInputDropsStaleBytes) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {});
  const Bytes stale = {9, 9, 9};
  ASSERT_TRUE(pty.write_all(stale, deadline_in(kPatience)));
  // The bytes must have reached the slave before the flush; a poll says so.
  std::uint8_t none[1];
  ASSERT_EQ(wait_for_fd(link->native_handle(), POLLIN, deadline_in(kPatience)) & POLLIN, POLLIN);
  link->flush_input();
  EXPECT_EQ(link->read_some(none, LinkClock::now()), 0u);
  const Bytes fresh = {7};
  ASSERT_TRUE(pty.write_all(fresh, deadline_in(kPatience)));
  EXPECT_EQ(read_exactly(*link, 1), fresh);
  link->drain();  // nothing queued on a pty; must return
}

TEST(SerialLink, MasterGoneReadsAsDisconnected) {
  auto pty = std::make_unique<PseudoTerminal>();
  auto link = SerialLink::open(pty->path(), {});
  pty.reset();
  std::uint8_t buffer[4];
  try {
    link->read_some(buffer, deadline_in(kPatience));
    FAIL() << "read after the device vanished";
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::disconnected);
    EXPECT_TRUE(contains(error.what(), link->path())) << error.what();
  }
}

TEST(SerialLink, ClosedLinkRefusesAndReopenCounts) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {.baud = 19200});
  link->close();
  link->close();  // idempotent
  EXPECT_FALSE(link->is_open());
  std::uint8_t buffer[1];
  try {
    link->read_some(buffer, LinkClock::now());
    FAIL();
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::closed);
  }
  EXPECT_THROW(link->write_all(buffer, LinkClock::now()), LinkError);
  link->reopen(deadline_in(kPatience));
  EXPECT_TRUE(link->is_open());
  EXPECT_EQ(pty.slave_baud(), 19200);
  EXPECT_EQ(link->counters().snapshot().reconnects, 1u);
  const Bytes after = {0x42};
  link->write_all(after, deadline_in(kPatience));
  EXPECT_EQ(read_exactly(pty, 1), after);
}

TEST(SerialLink, ExclusiveFlagIsClearedForTheNextOpener) {
  PseudoTerminal pty;
  SerialLink::open(pty.path(), {}).reset();
  // Had TIOCEXCL stayed set on the pty, a non-root open would get EBUSY;
  // as root it would pass anyway, so look at the flag itself.
  auto probe = SerialLink::open(pty.path(), {.exclusive = false});
  int exclusive = 0;
  ASSERT_EQ(::ioctl(probe->native_handle(), TIOCGEXCL, &exclusive), 0);
  EXPECT_EQ(exclusive, 0);
}

TEST(SerialLink, ModemLinesAreOptional) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {});
  EXPECT_FALSE(link->set_modem_lines(true, false));  // a pty has none; no error
}

TEST(SerialLink, RefusedSpeedKeepsTheOldOne) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {.baud = 9600});
  EXPECT_THROW(link->set_baud(0), LinkError);
  EXPECT_EQ(link->baud(), 9600);
  EXPECT_EQ(pty.slave_baud(), 9600);
}

}  // namespace serial_link_test
}  // namespace playerkit::links
