#include "families/flockofbirds/emulator/flock_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace playerkit::emulators {
namespace flock_emulator_test {

using namespace std::chrono_literals;
namespace fob = hardware::flockofbirds;
using Bytes = std::vector<std::uint8_t>;

// A host on the bird's line, on a simulated clock.
struct Host {
  explicit Host(FlockEmulatorOptions options = {}) : bird(std::move(options)) {}

  // The telegrams the bird sent for `bytes`, one entry per write.
  std::vector<Bytes> send(const Bytes& bytes, int baud = 115200) {
    bird.receive(bytes, now, baud);
    return take();
  }
  std::vector<Bytes> take() {
    std::vector<Bytes> writes;
    for (Telegram& telegram : bird.take_output()) {
      EXPECT_FALSE(telegram.has_checksum);
      writes.push_back(std::move(telegram.bytes));
    }
    return writes;
  }
  // Time passes as the runner lets it: to each deadline in turn.
  std::vector<Bytes> wait(Duration duration) {
    const Duration until = now + duration;
    while (bird.next_deadline() <= until) {
      now = bird.next_deadline();
      bird.advance(now);
    }
    now = until;
    bird.advance(now);
    return take();
  }

  FlockEmulator bird;
  Duration now{0};
};

fob::BirdPose decoded(const Bytes& record, fob::PositionScaling scaling = fob::PositionScaling::inches_36) {
  const auto words = fob::decode_record(record);
  EXPECT_TRUE(words);
  return words ? fob::pose_from_words(*words, scaling) : fob::BirdPose{};
}

FlockEmulatorOptions standing_still(const fob::BirdPose& pose) {
  FlockEmulatorOptions options;
  options.trajectory = BirdTrajectory::parse("0 " + std::to_string(pose.x_mm) + " " + std::to_string(pose.y_mm) + " " +
                                                 std::to_string(pose.z_mm) + " " + std::to_string(pose.azimuth_deg) +
                                                 " " + std::to_string(pose.elevation_deg) + " " +
                                                 std::to_string(pose.roll_deg) + "\n",
                                             false);
  return options;
}

// flockofbirds.md §2.2: Y, B, O 3, @, then B at shutdown.
TEST(FlockEmulator, ThePlayerStartUpAndShutdown) {
  const fob::BirdPose sheet{.x_mm = 304.8, .y_mm = -152.4, .z_mm = 76.2, .azimuth_deg = 90, .elevation_deg = -45, .roll_deg = 10};
  Host host(standing_still(sheet));
  EXPECT_TRUE(host.send({0x59}).empty());  // Y: no reply
  const auto point = host.send({0x42});
  ASSERT_EQ(point.size(), 1u);  // one record in one write
  EXPECT_EQ(point[0], (Bytes{0xAA, 0x15, 0x2A, 0x75, 0x2A, 0x05, 0x00, 0x20, 0x00, 0x70, 0x47, 0x03}));
  EXPECT_TRUE(host.send({0x4F}).empty());  // the parameter byte still to come
  EXPECT_EQ(host.send({0x03}), std::vector<Bytes>{(Bytes{0x00, 0x00})});
  const auto first = host.send({0x40});
  ASSERT_EQ(first.size(), 1u);
  EXPECT_TRUE(host.bird.streaming());
  const auto stream = host.wait(1s);
  EXPECT_EQ(stream.size(), 100u);  // 100 Hz, one write each
  for (const Bytes& record : stream) EXPECT_EQ(record.size(), fob::kRecordSize);
  EXPECT_EQ(host.send({0x42}).size(), 1u);  // B ends the stream with one record
  EXPECT_FALSE(host.bird.streaming());
  EXPECT_TRUE(host.wait(1s).empty());
}

TEST(FlockEmulator, SeventyTwoInchScalingAnsweredAndChanged) {
  FlockEmulatorOptions options = standing_still({.x_mm = 1200, .y_mm = 0, .z_mm = 0, .azimuth_deg = 0, .elevation_deg = 0, .roll_deg = 0});
  options.scaling = fob::PositionScaling::inches_72;
  Host host(std::move(options));
  EXPECT_EQ(host.send({0x4F, 0x03}), std::vector<Bytes>{(Bytes{0x01, 0x00})});
  EXPECT_NEAR(decoded(host.send({0x42})[0], fob::PositionScaling::inches_72).x_mm, 1200, 0.3);
  EXPECT_TRUE(host.send({0x50, 0x03, 0x00, 0x00}).empty());  // CHANGE VALUE: no reply
  EXPECT_EQ(host.bird.scaling(), fob::PositionScaling::inches_36);
  // 1200 mm is beyond 36": the word is clamped to full scale.
  EXPECT_NEAR(decoded(host.send({0x42})[0]).x_mm, 914.4, 0.2);
}

TEST(FlockEmulator, SaysNothingElse) {
  Host host;
  EXPECT_TRUE(host.send({0x00, 0x7A, 0x0D, 0x0A, 0x59}).empty());
  EXPECT_TRUE(host.send({0x4F, 0x07}).empty());  // a parameter not emulated
  EXPECT_TRUE(host.wait(2s).empty());           // no banner, no stream unasked
}

TEST(FlockEmulator, HearsNothingAtAnotherLineSpeed) {
  Host host;
  EXPECT_TRUE(host.send({0x42}, 9600).empty());
  EXPECT_EQ(host.send({0x42}, 115200).size(), 1u);
  EXPECT_EQ(host.send({0x42}, 0).size(), 1u);  // TCP: no speed to compare
}

TEST(FlockEmulator, RecordsFollowTheTrajectory) {
  FlockEmulatorOptions options;
  options.trajectory = BirdTrajectory::parse("0 0 0 0 170 0 0\n1 500 -100 50 -170 20 -10\n", false);
  Host host(std::move(options));
  host.send({0x40});
  host.wait(500ms);
  const fob::BirdPose halfway = decoded(host.send({0x42})[0]);
  EXPECT_NEAR(halfway.x_mm, 250, 0.2);
  EXPECT_NEAR(halfway.y_mm, -50, 0.2);
  EXPECT_NEAR(halfway.z_mm, 25, 0.2);
  EXPECT_NEAR(std::fabs(halfway.azimuth_deg), 180, 0.03);  // the short way, through 180
  EXPECT_NEAR(halfway.elevation_deg, 10, 0.03);
  host.wait(2s);
  EXPECT_NEAR(decoded(host.send({0x42})[0]).x_mm, 500, 0.2);  // held at the end
}

TEST(FlockEmulator, RefusesARateItCannotHave) {
  FlockEmulatorOptions options;
  options.rate_hz = 0;
  EXPECT_THROW(FlockEmulator{std::move(options)}, std::invalid_argument);
}

}  // namespace flock_emulator_test
}  // namespace playerkit::emulators
