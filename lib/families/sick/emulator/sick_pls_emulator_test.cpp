// The PLS emulator: the Player 1.5 sickpls start-up (sickpls.md §2.1), its
// password, centimetre scans without flags, its pacing, and the requests it
// does not answer.

#include "families/sick/emulator/sick_pls_emulator.hpp"

#include "families/sick/emulator/sick_test_host.hpp"
#include "families/sick/emulator/sick_test_room.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace playerkit::emulators {
namespace sick_pls_emulator_test {

using namespace std::chrono_literals;
using testing::TestHost;
using hardware::sick::testing::bytes;
namespace sick = hardware::sick;

TEST(SickPlsEmulator, ReferenceStartUpAndReconfiguration) {
  const grid::OccupancyGrid room = testing::box_room();
  const geometry::Pose2 pose{1.0, 1.2, 0.0};
  SickPlsEmulator device({.map = &room, .pose = pose});
  TestHost host(device);

  // 38400 first: T7 unheard by a PLS at 9600; the driver waits 1000 ms.
  host.set_baud(38400);
  host.send(sick::StreamAllRequest{});
  host.wait(1000ms);
  EXPECT_TRUE(host.writes().empty());

  // Then 9600: T7 answered, the stream follows.
  host.set_baud(9600);
  EXPECT_EQ(host.ask(sick::StreamAllRequest{}), (sick::Reply{0xA0, {0x00}, 0x10}));
  host.wait(3s);
  const auto scans = testing::scans_of(host.drain());
  ASSERT_GE(scans.size(), 3u);
  for (const sick::Scan& scan : scans) {
    EXPECT_FALSE(scan.subrange);
    EXPECT_EQ(scan.unit, sick::Unit::centimetre);  // count word bits 14-15 = 00
    ASSERT_EQ(scan.values.size(), 361u);
    for (std::size_t i = 0; i < 361; ++i) {
      const double angle = -std::numbers::pi / 2 + static_cast<double>(i) * std::numbers::pi / 360;
      EXPECT_NEAR(sick::distance_of(scan.values[i]),
                  100.0 * testing::room_range(pose.translation(), angle), 1.0)
          << "value " << i;
      EXPECT_EQ(sick::flags_of(scan.values[i]), 0);
    }
  }

  // After an accepted SET_CONFIG at resolution 100: T1, then T8 1..181.
  EXPECT_EQ(host.ask(sick::InstallationModeRequest{"SICK_PLS"}), (sick::Reply{0xA0, {0x00}, 0x10}));
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::installation);
  EXPECT_EQ(host.ask(sick::StreamSubrangeRequest{{1, 181}}).code, 0xA0);
  host.wait(2s);
  const auto part = testing::scans_of(host.drain());
  ASSERT_FALSE(part.empty());
  EXPECT_EQ(part.front().subrange, (sick::Subrange{1, 181}));
  ASSERT_EQ(part.front().values.size(), 181u);
  for (std::size_t i = 0; i < 181; ++i) EXPECT_EQ(part.front().values[i], scans.front().values[i]);
}

TEST(SickPlsEmulator, PasswordIsSickPls) {
  SickPlsEmulator device;
  TestHost host(device);
  host.send(sick::InstallationModeRequest{"SICK_PLS"});
  EXPECT_EQ(host.writes().back().second.bytes, bytes("02 80 03 00 A0 00 10 16 0A"));
  EXPECT_EQ(sick::parse_mode_reply(host.ask(sick::InstallationModeRequest{"SICK_LMS"})).result,
            sick::ModeResult::wrong_password);
}

TEST(SickPlsEmulator, RefusesWhatOnlyTheLms200Answers) {
  SickPlsEmulator device;
  TestHost host(device);
  host.ask(sick::InstallationModeRequest{"SICK_PLS"});
  const sick::Request lms_only[] = {sick::GetTypeRequest{}, sick::SetVariantRequest{{180, 50}},
                                    sick::GetConfigRequest{}, sick::SetConfigRequest{}};
  for (const sick::Request& request : lms_only) {
    host.send(request);
    EXPECT_EQ(host.writes().back().second.bytes, bytes("02 80 03 00 92 00 10 DE 6E"))
        << sick::describe(request);
  }
  // One variant: 361 values, no more.
  EXPECT_EQ(host.ask(sick::StreamSubrangeRequest{{1, 401}}).code, 0x92);
  EXPECT_EQ(host.ask(sick::StreamSubrangeRequest{{1, 361}}).code, 0xA0);
}

TEST(SickPlsEmulator, SwitchesRateAfterAnswering) {
  SickPlsEmulator device;
  TestHost host(device);
  EXPECT_EQ(host.ask(sick::BaudRateRequest{38400}).code, 0xA0);
  EXPECT_EQ(device.baud(), 38400);
  host.set_baud(38400);
  EXPECT_EQ(host.ask(sick::BaudRateRequest{500000}).code, 0xA0);
  host.set_baud(500000);
  EXPECT_EQ(host.ask(sick::BaudRateRequest{9600}).code, 0xA0);
  EXPECT_EQ(device.baud(), 9600);
}

TEST(SickPlsEmulator, ReflectorsGiveNoFlags) {
  SickPlsEmulator device({.reflectors = {{{1.0, -0.5}, {1.0, 0.5}, 7}}});
  TestHost host(device);
  host.ask(sick::StreamAllRequest{});
  host.wait(2s);
  const auto scans = testing::scans_of(host.drain());
  ASSERT_FALSE(scans.empty());
  EXPECT_EQ(scans.front().values[180], 100);  // 1 m in cm, bits 13-15 clear
  EXPECT_EQ(scans.front().values[0], 8191);   // nothing: 81.91 m
  EXPECT_DOUBLE_EQ(device.max_range_m(), 81.91);
}

TEST(SickPlsEmulator, PacedByAnEvenParityLineAndA40MsMirror) {
  SickPlsEmulator device({.power_up_baud = 38400});
  TestHost host(device, 38400);
  host.ask(sick::StreamAllRequest{});
  // 732 bytes of 11 bits (8E1) at 38400: 209.7 ms.
  EXPECT_EQ(device.scan_period(), Duration(209'687'500));
  host.wait(2s);
  auto telegrams = host.drain();
  ASSERT_GE(telegrams.size(), 2u);
  for (std::size_t i = 1; i < telegrams.size(); ++i) {
    EXPECT_GE(telegrams[i].at - telegrams[i - 1].at, Duration(209'687'500));
  }
  // At 500000 the line would carry 62 a second; the mirror gives 25.
  EXPECT_EQ(host.ask(sick::BaudRateRequest{500000}).code, 0xA0);
  host.set_baud(500000);
  host.ask(sick::StreamAllRequest{});
  EXPECT_EQ(device.scan_period(), Duration(40'000'000));
  host.wait(1s);
  telegrams = host.drain();
  EXPECT_GE(telegrams.size(), 24u);
  EXPECT_LE(telegrams.size(), 25u);
}

TEST(SickPlsEmulator, DescribesItself) {
  SickPlsEmulator device;
  EXPECT_EQ(device.describe(), "SICK PLS, 9600 baud, idle, 180 deg at 50/100 deg");
}

}  // namespace sick_pls_emulator_test
}  // namespace playerkit::emulators
