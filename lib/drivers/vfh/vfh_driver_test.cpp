// vfh between a simulated base and its laser (drivers of the test's own, on
// threads of their own like real ones): a goal reached and reported, a
// velocity command that would hit a wall stopped short of it, the base's
// requests passed through, the stall flag once boxed in, and the options.

#include "drivers/vfh/vfh_driver.hpp"
#include "drivers/vfh/vfh_options.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <stop_token>
#include <string>

#include "algorithms/geometry/pose2.hpp"
#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "core/device.hpp"
#include "core/driver.hpp"
#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {
namespace vfh_driver_test {

using namespace std::chrono_literals;
using testing::eventually;

constexpr double kPi = std::numbers::pi;
const protocol::PositionGeom kBaseGeometry{.subtype = 1, .pose = {{0, 0, 0}}, .size = {{450, 380}}};

// The world both fake devices share: the base's true pose, moved by its
// latest command, and what the laser sees from there.
struct World {
  std::mutex mutex;
  geometry::Pose2 pose;
  double speed = 0, turn_rate = 0;  // as last commanded
  std::function<double(const geometry::Pose2& from, double angle)> ray = [](const geometry::Pose2&, double) {
    return 8.0;
  };
  std::atomic<int> motor_power_requests = 0;
  std::atomic<std::uint32_t> tenths = 0;  // simulated time, 0.1 s a tick
};

// Simulated time runs as fast as the base's thread: 10 ticks a simulated
// second, each publishing odometry; the laser publishes with it.
class FakeBase final : public core::ThreadedDriver {
 public:
  explicit FakeBase(std::shared_ptr<World> world) : world_(std::move(world)) {}
  core::RequestResult handle_request(const core::Request& request) override {
    if (request.subtype() == protocol::kPositionGetGeomReq) return core::RequestResult::ack(protocol::encode(kBaseGeometry));
    if (request.subtype() == protocol::kPositionMotorPowerReq) {
      ++world_->motor_power_requests;
      return core::RequestResult::ack();
    }
    return core::RequestResult::nack();
  }
  core::Device* laser = nullptr;

 protected:
  void run(std::stop_token stop) override {
    while (sleep_for(stop, 2ms)) {
      device().service_requests();
      if (const auto command = device().take_command()) {
        const auto c = protocol::decode<protocol::PositionCommand>(command->payload);
        std::lock_guard lock(world_->mutex);
        world_->speed = c.state ? c.xspeed / 1000.0 : 0.0;
        world_->turn_rate = c.state ? c.yawspeed * kPi / 180.0 : 0.0;
      }
      protocol::PositionData odometry;
      protocol::LaserData scan;
      {
        std::lock_guard lock(world_->mutex);
        geometry::Pose2& p = world_->pose;
        p.yaw = geometry::normalize_angle(p.yaw + world_->turn_rate * 0.1);
        p.x += world_->speed * 0.1 * std::cos(p.yaw);
        p.y += world_->speed * 0.1 * std::sin(p.yaw);
        odometry.xpos = static_cast<std::int32_t>(std::lround(p.x * 1000));
        odometry.ypos = static_cast<std::int32_t>(std::lround(p.y * 1000));
        odometry.yaw = static_cast<std::int32_t>(std::lround(p.yaw * 180 / kPi));
        odometry.xspeed = static_cast<std::int32_t>(std::lround(world_->speed * 1000));
        scan.min_angle = -9000;
        scan.max_angle = 9000;
        scan.resolution = 100;
        scan.range_res = 1;
        scan.range_count = 181;
        for (int i = 0; i < 181; ++i) {
          const double r = std::min(world_->ray(p, p.yaw + (i - 90) * kPi / 180), 8.0);
          scan.ranges[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(std::lround(r * 1000));
        }
      }
      const std::uint32_t tick = ++world_->tenths;
      const protocol::Timestamp now{tick / 10, (tick % 10) * 100000};
      if (laser != nullptr) laser->publish(protocol::encode(scan), now);
      device().publish(protocol::encode(odometry), now);
    }
  }

 private:
  std::shared_ptr<World> world_;
};

// Published by the base's thread; only here to be subscribed to.
class FakeLaser final : public core::Driver {};

struct Vfh : ::testing::Test {
  Vfh() {
    devices.registry.add({.name = "fakebase",
                          .interfaces = {protocol::kPositionCode},
                          .access = protocol::Access::kAll,
                          .factory = [this](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
                            auto base = std::make_unique<FakeBase>(world);
                            fake_base = base.get();
                            return base;
                          },
                          .limits = {},
                          .summary = "test"});
    devices.registry.add({.name = "fakelaser",
                          .interfaces = {protocol::kLaserCode},
                          .access = protocol::Access::kRead,
                          .factory = [](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
                            return std::make_unique<FakeLaser>();
                          },
                          .limits = {},
                          .summary = "test"});
  }
  void load(const std::string& vfh_options = "") {
    devices.load("position:0 ( driver \"fakebase\" )\n"
                 "laser:0 ( driver \"fakelaser\" )\n"
                 "position:1 ( driver \"vfh\" " + vfh_options + ")\n");
    fake_base->laser = &devices.device(protocol::kLaserCode, 0);
    ASSERT_TRUE(vfh().subscribe());
  }
  core::Device& vfh() { return devices.device(protocol::kPositionCode, 1); }
  void command(const protocol::PositionCommand& c) {
    ASSERT_EQ(vfh().put_command(1, protocol::encode(c)), core::Device::CommandStatus::kAccepted);
  }
  std::optional<protocol::PositionData> data() {
    const auto sample = vfh().latest_data();
    if (sample->sequence == 0) return std::nullopt;
    return protocol::decode<protocol::PositionData>(sample->payload);
  }
  geometry::Pose2 true_pose() {
    std::lock_guard lock(world->mutex);
    return world->pose;
  }
  double simulated_seconds() const { return world->tenths / 10.0; }
  std::uint64_t counter(const std::string& name) {
    for (const core::DriverCounter& c : vfh().driver().counters()) {
      if (c.name == name) return c.value;
    }
    return ~std::uint64_t{0};
  }
  std::optional<core::Reply> ask(std::vector<std::uint8_t> payload) {
    (void)vfh().take_replies();
    EXPECT_EQ(vfh().enqueue_request({1, vfh().address(), std::move(payload), {}}), core::Device::RequestStatus::kQueued);
    std::optional<core::Reply> reply;
    eventually([&] {
      auto replies = vfh().take_replies();
      if (!replies.empty()) reply = replies.front();
      return reply.has_value();
    }, 5s);
    return reply;
  }

  std::shared_ptr<World> world = std::make_shared<World>();
  FakeBase* fake_base = nullptr;
  testing::BuiltinDevices devices;
};

TEST_F(Vfh, DrivesTheBaseToAGoalAndPublishesItsOdometry) {
  load();
  command({.xpos = 2000, .ypos = 1000, .yaw = 90, .xspeed = 0, .yspeed = 0, .yawspeed = 0, .state = 1, .type = 1});
  ASSERT_TRUE(eventually([&] { return counter("goals_reached") == 1; }, 60s))
      << "at " << true_pose().x << ", " << true_pose().y << " after " << simulated_seconds() << " s";
  const geometry::Pose2 at = true_pose();
  EXPECT_LT(std::hypot(at.x - 2.0, at.y - 1.0), 0.5);
  EXPECT_LT(std::abs(geometry::angle_difference(at.yaw, kPi / 2)), 10 * kPi / 180 + 0.02);
  // Stopped there, and what vfh publishes is the base's odometry.
  ASSERT_TRUE(eventually([&] { return data() && data()->xspeed == 0; }, 5s));
  EXPECT_NEAR(data()->xpos, at.x * 1000, 2);
  EXPECT_NEAR(data()->ypos, at.y * 1000, 2);
}

TEST_F(Vfh, AVelocityCommandAtAWallStopsShortOfIt) {
  world->ray = [](const geometry::Pose2& from, double angle) {
    return std::cos(angle) > 1e-9 ? (1.5 - from.x) / std::cos(angle) : 8.0;
  };
  load();
  command({.xpos = 0, .ypos = 0, .yaw = 0, .xspeed = 300, .yspeed = 0, .yawspeed = 0, .state = 1, .type = 0});
  ASSERT_TRUE(eventually([&] { return simulated_seconds() > 20; }, 30s));
  EXPECT_LE(true_pose().x, 1.5 - 0.25 - 0.1 + 0.01);
  EXPECT_GT(true_pose().x, 0.5);  // it did drive
  // Motors off stops it at once.
  command({.xpos = 0, .ypos = 0, .yaw = 0, .xspeed = 300, .yspeed = 0, .yawspeed = 0, .state = 0, .type = 0});
  ASSERT_TRUE(eventually([&] {
    std::lock_guard lock(world->mutex);
    return world->speed == 0.0;
  }, 5s));
}

TEST_F(Vfh, PassesGeometryAndMotorPowerToTheBaseAndRefusesTheRest) {
  load();
  const auto geometry = ask({protocol::kPositionGetGeomReq});
  ASSERT_TRUE(geometry);
  ASSERT_EQ(geometry->type, protocol::MessageType::kAck);
  EXPECT_EQ(protocol::decode<protocol::PositionGeom>(geometry->payload), kBaseGeometry);
  const auto power = ask(protocol::encode(protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1}));
  ASSERT_TRUE(power);
  EXPECT_EQ(power->type, protocol::MessageType::kAck);
  EXPECT_EQ(world->motor_power_requests, 1);
  const auto other = ask({protocol::kPositionResetOdomReq});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->type, protocol::MessageType::kNack);
}

TEST_F(Vfh, BoxedInItGivesTheGoalUpAndSetsStall) {
  world->ray = [](const geometry::Pose2&, double) { return 0.45; };
  load();
  command({.xpos = 5000, .ypos = 0, .yaw = 0, .xspeed = 0, .yspeed = 0, .yawspeed = 0, .state = 1, .type = 1});
  ASSERT_TRUE(eventually([&] { return data() && data()->stall == 1; }, 60s)) << simulated_seconds() << " s";
  EXPECT_EQ(counter("stuck"), 1u);
  EXPECT_NEAR(true_pose().x, 0.0, 1e-9);  // turned in place, never drove
}

vfh_driver::VfhOptions options_of(const std::string& body) {
  const auto config = config::ConfigFile::parse("position:1 ( driver \"vfh\" " + body + " )\n", "test.cfg");
  return vfh_driver::read_vfh_options(config.section(config.devices().at(0).section));
}

TEST(VfhOptions, DefaultsAreTheSheets) {
  const vfh_driver::VfhOptions o = options_of("");
  EXPECT_EQ(o.position_index, 0);
  EXPECT_EQ(o.laser_index, 0);
  EXPECT_DOUBLE_EQ(o.navigator.planner.max_speed, 0.2);
  EXPECT_DOUBLE_EQ(o.navigator.planner.max_turn_rate, 40 * kPi / 180);
  EXPECT_DOUBLE_EQ(o.navigator.planner.obstacle_cutoff, 2e6);
  EXPECT_DOUBLE_EQ(o.navigator.distance_epsilon, 0.5);
  EXPECT_DOUBLE_EQ(o.navigator.angle_epsilon, 10 * kPi / 180);
}

TEST(VfhOptions, ReadsBothSpeedUnitsAndBothEpsilonNames) {
  EXPECT_DOUBLE_EQ(options_of("max_speed 0.3").navigator.planner.max_speed, 0.3);  // 1.5's source and files
  EXPECT_DOUBLE_EQ(options_of("max_speed 300").navigator.planner.max_speed, 0.3);  // the manual's mm/s
  EXPECT_DOUBLE_EQ(options_of("dist_eps 0.3").navigator.distance_epsilon, 0.3);
  EXPECT_DOUBLE_EQ(options_of("distance_epsilon 0.4").navigator.distance_epsilon, 0.4);
  EXPECT_DOUBLE_EQ(options_of("free_space_cutoff 1000000").navigator.planner.obstacle_cutoff, 1e6);
  EXPECT_DOUBLE_EQ(options_of("free_space_cutoff 1000000 obs_cutoff 3000000").navigator.planner.obstacle_cutoff, 3e6);
}

std::string refusal(const std::string& body) {
  try {
    (void)options_of(body);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(VfhOptions, RefusesWhatItCannotDoAtTheValuesPlace) {
  EXPECT_NE(refusal("truth_index 0").find("test.cfg:1:"), std::string::npos) << refusal("truth_index 0");
  EXPECT_NE(refusal("truth_index 0").find("not supported"), std::string::npos);
  EXPECT_NE(refusal("sector_angle 7").find("must divide 360"), std::string::npos) << refusal("sector_angle 7");
  EXPECT_NE(refusal("min_turnrate 50").find("must not exceed max_turnrate"), std::string::npos);
  EXPECT_NE(refusal("free_space_cutoff 3000000 obs_cutoff 1000000").find("obs_cutoff"), std::string::npos);
}

}  // namespace vfh_driver_test
}  // namespace playerkit::drivers
