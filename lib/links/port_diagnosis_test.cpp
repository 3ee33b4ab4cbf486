#include "links/port_diagnosis.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "links/links_test_support.hpp"
#include "links/serial_link.hpp"

namespace playerkit::links {
namespace port_diagnosis_test {

using namespace test_support;

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PortDiagnosis, ModeText) {
  EXPECT_EQ(mode_text(0660), "crw-rw----");
  EXPECT_EQ(mode_text(0600), "crw-------");
  EXPECT_EQ(mode_text(0755, '-'), "-rwxr-xr-x");
}

TEST(PortDiagnosis, AdviceToJoinTheGroup) {
  const DeviceAccess access{.user = "alice", .group = "dialout", .mode = 0660};
  EXPECT_EQ(permission_advice("/dev/ttyUSB0", access),
            "/dev/ttyUSB0 belongs to group dialout (crw-rw----), which alice is not in: join it with "
            "`sudo usermod -aG dialout alice`, then log out and back in");
}

TEST(PortDiagnosis, AdviceWhenTheSessionPredatesJoining) {
  const DeviceAccess access{.user = "alice", .group = "dialout", .mode = 0660, .user_listed_in_group = true};
  const std::string advice = permission_advice("/dev/ttyACM0", access);
  EXPECT_TRUE(contains(advice, "alice is in dialout but this session started before joining")) << advice;
  EXPECT_TRUE(contains(advice, "`newgrp dialout`")) << advice;
}

TEST(PortDiagnosis, AdviceWhenOnlyTheOwnerMayOpen) {
  const DeviceAccess access{.user = "alice", .group = "root", .mode = 0600};
  const std::string advice = permission_advice("/dev/ttyS0", access);
  EXPECT_TRUE(contains(advice, "only by its owner (crw-------, group root)")) << advice;
  EXPECT_TRUE(contains(advice, "KERNEL==\"ttyS0\", GROUP=\"dialout\", MODE=\"0660\"")) << advice;
}

TEST(PortDiagnosis, AdviceWhenInTheGroupYetDenied) {
  const DeviceAccess access{
      .user = "alice", .group = "dialout", .mode = 0660, .user_listed_in_group = true, .process_has_group = true};
  EXPECT_TRUE(contains(permission_advice("/dev/ttyUSB0", access), "ACL"));
}

TEST(PortDiagnosis, SimilarPortsBesideTheMissingOne) {
  TemporaryDirectory directory;
  for (const char* name : {"ttyUSB10", "ttyUSB2", "ttyUSB1", "ttyS0", "notes"}) {
    std::ofstream(directory.path() / name).put('x');
  }
  const std::string dir = directory.path().string();
  EXPECT_EQ(similar_ports(dir + "/ttyUSB0"),
            (std::vector<std::string>{dir + "/ttyUSB1", dir + "/ttyUSB2", dir + "/ttyUSB10"}));
  EXPECT_EQ(similar_ports(dir + "/ttyUSB1"), (std::vector<std::string>{dir + "/ttyUSB2", dir + "/ttyUSB10"}));
  EXPECT_TRUE(similar_ports(dir + "/ttyACM0").empty());
}

TEST(PortDiagnosis, Missing) {
  TemporaryDirectory directory;
  std::ofstream(directory.path() / "ttyUSB1").put('x');
  const std::string missing = (directory.path() / "ttyUSB0").string();
  const PortDiagnosis diagnosis = describe_open_problem(missing);
  EXPECT_FALSE(diagnosis.exists);
  EXPECT_EQ(diagnosis.problem, LinkErrorKind::missing);
  EXPECT_EQ(diagnosis.similar, (std::vector<std::string>{(directory.path() / "ttyUSB1").string()}));
  EXPECT_TRUE(contains(diagnosis.summary, "no such port " + missing)) << diagnosis.summary;
  EXPECT_TRUE(contains(to_string(diagnosis), "  exists: no\n")) << to_string(diagnosis);
}

TEST(PortDiagnosis, DanglingSymlinkSaysWhereItPoints) {
  TemporaryDirectory directory;
  const auto link = directory.path() / "laser";
  std::filesystem::create_symlink(directory.path() / "ttyUSB7", link);
  const PortDiagnosis diagnosis = describe_open_problem(link.string());
  EXPECT_EQ(diagnosis.problem, LinkErrorKind::missing);
  EXPECT_TRUE(contains(diagnosis.summary, "is a symlink to " + (directory.path() / "ttyUSB7").string()))
      << diagnosis.summary;
}

TEST(PortDiagnosis, NotADevice) {
  TemporaryDirectory directory;
  const auto file = directory.path() / "ttyUSB0";
  std::ofstream(file).put('x');
  PortDiagnosis diagnosis = describe_open_problem(file.string());
  EXPECT_TRUE(diagnosis.exists);
  EXPECT_FALSE(diagnosis.character_device);
  EXPECT_EQ(diagnosis.problem, LinkErrorKind::not_a_terminal);
  EXPECT_EQ(diagnosis.summary, file.string() + " is a regular file, not a serial port");

  const auto fifo = directory.path() / "ttyFIFO";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  diagnosis = describe_open_problem(fifo.string());
  EXPECT_EQ(diagnosis.problem, LinkErrorKind::not_a_terminal);
  EXPECT_TRUE(contains(diagnosis.summary, "a named pipe")) << diagnosis.summary;

  diagnosis = describe_open_problem("/dev/null");
  EXPECT_TRUE(diagnosis.character_device);
  EXPECT_FALSE(diagnosis.terminal_device);
  EXPECT_EQ(diagnosis.problem, LinkErrorKind::not_a_terminal);
}

TEST(PortDiagnosis, UsablePty) {
  PseudoTerminal pty;
  const PortDiagnosis diagnosis = describe_open_problem(pty.path());
  EXPECT_TRUE(diagnosis.exists);
  EXPECT_TRUE(diagnosis.character_device);
  EXPECT_TRUE(diagnosis.terminal_device);
  EXPECT_TRUE(diagnosis.readable);
  EXPECT_TRUE(diagnosis.writable);
  EXPECT_EQ(diagnosis.problem, std::nullopt);
  EXPECT_TRUE(diagnosis.holders.empty());
  ASSERT_TRUE(diagnosis.access.has_value());
  EXPECT_TRUE(contains(diagnosis.summary, "looks usable")) << diagnosis.summary;
  // Diagnosing never opens the port: the emulator sees no host.
  std::uint8_t buffer[1];
  EXPECT_FALSE(pty.read_some(buffer, LinkClock::now()).host_opened);
}

TEST(PortDiagnosis, BusyPortNamesTheHolder) {
  PseudoTerminal pty;
  auto holder = SerialLink::open(pty.path(), {});
  const PortDiagnosis diagnosis = describe_open_problem(pty.path());
  EXPECT_EQ(diagnosis.problem, LinkErrorKind::busy);
  ASSERT_EQ(diagnosis.holders.size(), 1u);
  EXPECT_EQ(diagnosis.holders[0].pid, ::getpid());
  EXPECT_TRUE(diagnosis.holders[0].holds_lock);
  EXPECT_FALSE(diagnosis.holders[0].command.empty());
  EXPECT_TRUE(contains(diagnosis.summary, "held by pid " + std::to_string(::getpid()))) << diagnosis.summary;
  EXPECT_TRUE(contains(to_string(diagnosis), "held by: pid ")) << to_string(diagnosis);
}

TEST(PortDiagnosis, OpenWithoutLockIsReportedButNotBusy) {
  PseudoTerminal pty;
  auto sharer = SerialLink::open(pty.path(), {.exclusive = false});
  const PortDiagnosis diagnosis = describe_open_problem(pty.path());
  EXPECT_EQ(diagnosis.problem, std::nullopt);
  ASSERT_EQ(diagnosis.holders.size(), 1u);
  EXPECT_FALSE(diagnosis.holders[0].holds_lock);
  EXPECT_TRUE(contains(diagnosis.summary, "already open in pid " + std::to_string(::getpid())))
      << diagnosis.summary;
}

TEST(PortDiagnosis, UnreadableDevice) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may open anything; the advice text is tested directly above";
  TemporaryDirectory directory;
  const auto file = directory.path() / "locked";
  std::ofstream(file).put('x');
  ::chmod(file.c_str(), 0);
  const PortDiagnosis diagnosis = describe_open_problem(file.string());
  EXPECT_FALSE(diagnosis.readable);
  EXPECT_FALSE(diagnosis.writable);
}

TEST(PortDiagnosis, HoldersText) {
  EXPECT_EQ(to_string(std::vector<PortHolder>{{.pid = 12, .command = "player", .holds_lock = true},
                                              {.pid = 99, .command = "minicom", .holds_lock = false},
                                              {.pid = 7, .command = "", .holds_lock = false}}),
            "pid 12 (player, holds the lock), pid 99 (minicom), pid 7");
}

}  // namespace port_diagnosis_test
}  // namespace playerkit::links
