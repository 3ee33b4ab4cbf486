#include "core/server_clock.hpp"

#include <gtest/gtest.h>

#include <ctime>
#include <memory>
#include <string>

namespace playerkit::core {
namespace server_clock_test {

TEST(ServerClockTest, ReadsTheWallClockUntilClaimed) {
  const ServerClock clock;
  const auto before = static_cast<std::uint32_t>(std::time(nullptr));
  const Timestamp now = clock.now();
  EXPECT_GE(now.sec, before);
  EXPECT_LE(now.sec, before + 2);
  EXPECT_FALSE(clock.claimed());
  EXPECT_EQ(clock.claimant(), "");
}

TEST(ServerClockTest, ReadsItsFallbackUntilClaimed) {
  ManualClock fallback({42, 7});
  const ServerClock clock(fallback);
  EXPECT_EQ(clock.now(), (Timestamp{42, 7}));
  fallback.advance_microseconds(3);
  EXPECT_EQ(clock.now(), (Timestamp{42, 10}));
}

TEST(ServerClockTest, FollowsTheClaimedClock) {
  ServerClock clock;
  auto simulation = std::make_shared<ManualClock>(Timestamp{0, 0});
  clock.claim(simulation, "position:0@6665 (position)");
  EXPECT_TRUE(clock.claimed());
  EXPECT_EQ(clock.claimant(), "position:0@6665 (position)");
  EXPECT_EQ(clock.now(), (Timestamp{0, 0}));
  simulation->advance_microseconds(100'000);
  EXPECT_EQ(clock.now(), (Timestamp{0, 100'000}));
}

TEST(ServerClockTest, TheSameClockMayBeClaimedByEveryDeviceOfItsFamily) {
  ServerClock clock;
  auto simulation = std::make_shared<ManualClock>(Timestamp{5, 0});
  clock.claim(simulation, "position:0@6665 (position)");
  EXPECT_NO_THROW(clock.claim(simulation, "laser:0@6665 (laser)"));
  EXPECT_EQ(clock.claimant(), "position:0@6665 (position)");  // the first keeps the name
  EXPECT_EQ(clock.now(), (Timestamp{5, 0}));
}

TEST(ServerClockTest, ASecondClockIsRefusedNamingBothDevices) {
  ServerClock clock;
  auto log = std::make_shared<ManualClock>(Timestamp{1000, 0});
  auto simulation = std::make_shared<ManualClock>(Timestamp{0, 0});
  clock.claim(log, "laser:0@6665 (readlog)");
  try {
    clock.claim(simulation, "position:0@6666 (position)");
    FAIL() << "a second clock was accepted";
  } catch (const ClockClaimError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("laser:0@6665 (readlog)"), std::string::npos) << message;
    EXPECT_NE(message.find("position:0@6666 (position)"), std::string::npos) << message;
  }
  EXPECT_EQ(clock.now(), (Timestamp{1000, 0}));  // the first claim stands
}

TEST(ServerClockTest, ANullClockIsRefused) {
  ServerClock clock;
  EXPECT_THROW(clock.claim(nullptr, "laser:0@6665 (readlog)"), ClockClaimError);
  EXPECT_FALSE(clock.claimed());
}

TEST(ServerClockTest, KeepsTheClaimedClockAlive) {
  ServerClock clock;
  {
    auto simulation = std::make_shared<ManualClock>(Timestamp{9, 0});
    clock.claim(simulation, "position:0@6665 (position)");
  }
  EXPECT_EQ(clock.now(), (Timestamp{9, 0}));
}

}  // namespace server_clock_test
}  // namespace playerkit::core
