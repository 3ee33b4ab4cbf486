#include "drivers/amcl/amcl_driver.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "drivers/amcl/amcl_test_support.hpp"
#include "localization/localize_wire.hpp"
#include "drivers/logfile/readlog_driver.hpp"
#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/localize.hpp"

namespace playerkit::drivers {
namespace amcl_driver_test {

using namespace std::chrono_literals;
using protocol::kLocalizeCode;
using testing::eventually;
using localization::covariance_from_wire;
using localization::pose_from_wire;

// The manual's post-hoc localization example (7.36) on the cave map; with
// `guess`, a start 0.3 m and 6 degrees off the truth.
std::string post_hoc_config(const std::string& extra = "", bool guess = true) {
  return "position:0 (driver \"readlog\" index 0)\n"
         "laser:0 (driver \"readlog\" index 0)\n"
         "localize:0\n(\n  driver \"amcl\"\n  position_index 0\n  laser_index 0\n"
         "  map_file \"" + testing::cave_map_path().string() + "\"\n"
         "  map_scale 0.03\n  map_negate 1\n"
         + (guess ? "  init_pose [0.2 1.2 6]\n  init_pose_var [0.3 0.3 10]\n" : "") + extra + ")\n";
}

struct AmclDriverTest : ::testing::Test {
  void load(const std::string& config = post_hoc_config()) {
    testing::write_cave_log(log_path, drive);
    ReadlogSettings settings;
    settings.log = log_path;
    settings.timer = timer;
    builtin.registry.add(readlog_driver_spec(std::move(settings)));
    builtin.load(config);
  }

  core::Device& localize() { return builtin.device(kLocalizeCode, 0); }
  void expect_convergence(const std::string& config);

  protocol::LocalizeData latest() const {
    return protocol::decode<protocol::LocalizeData>(localize_device->latest_data()->payload);
  }

  core::RequestResult ask(std::vector<std::uint8_t> payload) {
    core::Device& device = localize();
    EXPECT_EQ(device.enqueue_request(testing::make_request(kLocalizeCode, std::move(payload))),
              core::Device::RequestStatus::kQueued);
    std::vector<core::Reply> replies;
    EXPECT_TRUE(eventually([&] {
      replies = device.take_replies();
      return !replies.empty();
    }));
    if (replies.empty()) return {};
    return {replies.front().type, replies.front().payload};
  }

  testing::ScratchDirectory scratch;
  std::filesystem::path log_path = scratch.file("cave.log");
  std::vector<testing::DriveStep> drive = testing::cave_drive();
  std::shared_ptr<testing::ManualReplayTimer> timer = std::make_shared<testing::ManualReplayTimer>();
  testing::BuiltinDevices builtin;  // last: its devices stop before the timer and clock go
  core::Device* localize_device = nullptr;
};

// Replays the whole drive through `config` and checks the last estimate.
void AmclDriverTest::expect_convergence(const std::string& config) {
  load(config);
  localize_device = &localize();
  ASSERT_TRUE(localize().subscribe());
  // The position and laser devices were set up for amcl.
  EXPECT_EQ(builtin.device(protocol::kPositionCode).subscriptions(), 1);
  EXPECT_EQ(builtin.device(protocol::kLaserCode).subscriptions(), 1);

  // Once the replay has started (it waits for its second line), let it run
  // through the whole log at once: amcl queues what it cannot process yet.
  ASSERT_TRUE(eventually([&] { return timer->waiting_for().has_value(); }));
  timer->set(1h);
  const protocol::Timestamp end = drive.back().time;
  ASSERT_TRUE(eventually([&] {
    const auto sample = localize().latest_data();
    return sample->sequence > 0 && sample->timestamp == end && latest().pending_count == 0;
  })) << localize().latest_data()->sequence << " " << localize().latest_data()->timestamp.seconds() << " pos "
      << builtin.device(protocol::kPositionCode).latest_data()->sequence << " laser "
      << builtin.device(protocol::kLaserCode).latest_data()->sequence << " waiting "
      << (timer->waiting_for() ? timer->waiting_for()->count() : -1) << " clock " << builtin.clock.now().seconds();

  const protocol::LocalizeData data = latest();
  EXPECT_EQ(localize().latest_data()->payload.size(), 14 + 88 * data.hypoth_count);
  ASSERT_GE(data.hypoth_count, 1u);
  EXPECT_LE(data.hypoth_count, 10u);
  EXPECT_EQ(data.pending_time_sec, end.sec);
  EXPECT_EQ(data.pending_time_usec, end.usec);

  // The heaviest hypothesis is where the robot really ended, (6, 1) facing
  // 81 degrees, although the odometry says 6.3 m and drifts in heading.
  const protocol::LocalizeHypothesis& best = data.hypoths[0];
  const geometry::Pose2 truth = drive.back().truth;
  const geometry::Pose2 estimate = pose_from_wire(best.mean);
  EXPECT_NEAR(estimate.x, truth.x, 0.2);
  EXPECT_NEAR(estimate.y, truth.y, 0.2);
  EXPECT_NEAR(geometry::angle_difference(estimate.yaw, truth.yaw), 0.0, 5.0 * std::numbers::pi / 180.0);
  EXPECT_GT(best.alpha, 500000u);  // most of the weight
  std::uint64_t total_alpha = 0;
  for (std::uint32_t i = 0; i < data.hypoth_count; ++i) total_alpha += data.hypoths[i].alpha;
  EXPECT_NEAR(static_cast<double>(total_alpha), 1e6, 1e6 * 0.01 + 10);

  // A converged filter: positive variances, a few cm and degrees, symmetric.
  const Eigen::Matrix3d covariance = covariance_from_wire(best.cov);
  EXPECT_GT(covariance(0, 0), 0.0);
  EXPECT_LT(std::sqrt(covariance(0, 0)), 0.2);
  EXPECT_LT(std::sqrt(covariance(1, 1)), 0.2);
  EXPECT_LT(std::sqrt(covariance(2, 2)), 10.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(best.cov[0][1], best.cov[1][0]);

  localize().unsubscribe();
  EXPECT_EQ(builtin.device(protocol::kPositionCode).subscriptions(), 0);
  EXPECT_EQ(builtin.device(protocol::kLaserCode).subscriptions(), 0);
}

TEST_F(AmclDriverTest, PostHocLocalizationAsInTheManualStartsGlobalAndConverges) {
  expect_convergence(post_hoc_config("", false));  // no init_pose: anywhere in the cave
}

TEST_F(AmclDriverTest, PostHocLocalizationFromARoughGuessConverges) {
  expect_convergence(post_hoc_config());
}

// A robot that never moves still gets its estimate: 1.5's amcl published
// only after the robot had moved past its update thresholds, so 1.5's
// wavefront, waiting for a pose, never planned until someone nudged the robot.
TEST_F(AmclDriverTest, AStandingRobotGetsItsEstimateAtOnce) {
  const testing::DriveStep first = drive.front();
  drive.clear();
  for (std::uint32_t i = 0; i < 5; ++i) drive.push_back({first.truth, first.odometry, {1000, i * 100000}});
  load();
  localize_device = &localize();
  ASSERT_TRUE(localize().subscribe());
  ASSERT_TRUE(eventually([&] { return timer->waiting_for().has_value(); }));
  timer->set(1h);
  ASSERT_TRUE(eventually([&] {
    const auto sample = localize().latest_data();
    return sample && sample->sequence > 0 && latest().hypoth_count > 0;
  })) << "no estimate while the robot stands still";
  // Where init_pose put it (0.2, 1.2), or nearer the truth (0, 1) if the
  // scan has been taken in.
  const geometry::Pose2 estimate = pose_from_wire(latest().hypoths[0].mean);
  EXPECT_LT(std::hypot(estimate.x - first.truth.x, estimate.y - first.truth.y), 0.3);
  localize().unsubscribe();
}

TEST_F(AmclDriverTest, SetPoseMovesTheEstimate) {
  load();
  localize_device = &localize();
  ASSERT_TRUE(localize().subscribe());
  protocol::LocalizeSetPose request;
  request.subtype = protocol::kLocalizeSetPoseReq;
  request.mean = {-3000, 2500, 90 * 3600};
  request.cov[0][0] = request.cov[1][1] = 10 * 10;                  // 1 cm
  request.cov[2][2] = std::int64_t{3600} * 3600;                     // 1 degree
  EXPECT_EQ(ask(protocol::encode(request)).type, protocol::MessageType::kAck);
  ASSERT_TRUE(eventually([&] { return localize().latest_data()->sequence > 0; }));
  const protocol::LocalizeData data = latest();
  ASSERT_GE(data.hypoth_count, 1u);
  EXPECT_NEAR(data.hypoths[0].mean[0], -3000, 10);
  EXPECT_NEAR(data.hypoths[0].mean[1], 2500, 10);
  EXPECT_NEAR(data.hypoths[0].mean[2], 90 * 3600, 600);
  EXPECT_NEAR(static_cast<double>(data.hypoths[0].cov[0][0]), 100.0, 30.0);

  // Too short for the struct: NACK.
  EXPECT_EQ(ask({protocol::kLocalizeSetPoseReq, 0, 0}).type, protocol::MessageType::kNack);
}

TEST_F(AmclDriverTest, MapInfoAndTilesDescribeTheMap) {
  load();
  localize_device = &localize();
  ASSERT_TRUE(localize().subscribe());
  const grid::OccupancyGrid map = testing::load_cave();

  const core::RequestResult info_reply = ask({protocol::kLocalizeGetMapInfoReq});
  ASSERT_EQ(info_reply.type, protocol::MessageType::kAck);
  const auto info = protocol::decode<protocol::LocalizeMapInfo>(info_reply.payload);
  EXPECT_EQ(info.subtype, protocol::kLocalizeGetMapInfoReq);
  EXPECT_EQ(info.scale, 33333u);  // 1 km / 0.03 m
  EXPECT_EQ(info.width, 500u);
  EXPECT_EQ(info.height, 500u);

  // A 60 x 30 tile over the room's west wall (column 220 is x = -0.9 m).
  protocol::LocalizeMapData tile;
  tile.subtype = protocol::kLocalizeGetMapDataReq;
  tile.col = 200;
  tile.row = 240;
  tile.width = 60;
  tile.height = 30;
  const core::RequestResult tile_reply = ask(protocol::encode(tile));
  ASSERT_EQ(tile_reply.type, protocol::MessageType::kAck);
  EXPECT_EQ(tile_reply.payload.size(), 17u + 60 * 30);
  const auto cells = protocol::decode<protocol::LocalizeMapData>(tile_reply.payload);
  EXPECT_EQ(cells.col, 200u);
  EXPECT_EQ(cells.height, 30u);
  ASSERT_EQ(cells.data.size(), 1800u);
  int occupied = 0, mismatches = 0;
  for (int j = 0; j < 30; ++j) {
    for (int i = 0; i < 60; ++i) {
      const std::int8_t cell = cells.data[static_cast<std::size_t>(i + j * 60)];
      if (cell != static_cast<std::int8_t>(map.at(200 + i, 240 + j))) ++mismatches;
      if (cell == 1) ++occupied;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(occupied, 0);  // the wall is in it

  // Past the edge, or more cells than the reply holds: NACK.
  tile.col = 480;
  tile.width = 21;
  tile.height = 1;
  EXPECT_EQ(ask(protocol::encode(tile)).type, protocol::MessageType::kNack);
  tile.col = 0;
  tile.width = 4080;
  EXPECT_EQ(ask(protocol::encode(tile)).type, protocol::MessageType::kNack);
  tile.width = 4079;
  EXPECT_EQ(ask(protocol::encode(tile)).type, protocol::MessageType::kNack);  // wider than the map
  tile.width = 500;
  tile.height = 8;
  EXPECT_EQ(ask(protocol::encode(tile)).type, protocol::MessageType::kAck);
}

TEST_F(AmclDriverTest, ConfigRoundTripsAndUnknownRequestsGetNack) {
  load(post_hoc_config("  pf_max_samples 2000\n"));
  localize_device = &localize();
  ASSERT_TRUE(localize().subscribe());
  auto get = [&] {
    const core::RequestResult reply = ask({protocol::kLocalizeGetConfigReq});
    EXPECT_EQ(reply.type, protocol::MessageType::kAck);
    return protocol::decode<protocol::LocalizeConfig>(reply.payload);
  };
  EXPECT_EQ(get().num_particles, 2000u);
  protocol::LocalizeConfig set;
  set.subtype = protocol::kLocalizeSetConfigReq;
  set.num_particles = 750;
  EXPECT_EQ(ask(protocol::encode(set)).type, protocol::MessageType::kAck);
  EXPECT_EQ(get().num_particles, 750u);
  set.num_particles = 0;
  EXPECT_EQ(ask(protocol::encode(set)).type, protocol::MessageType::kNack);
  EXPECT_EQ(get().num_particles, 750u);

  for (const int subtype : {0, 6, 200}) {
    EXPECT_EQ(ask({static_cast<std::uint8_t>(subtype)}).type, protocol::MessageType::kNack) << subtype;
  }
}

TEST_F(AmclDriverTest, SetupFailsWithoutTheLaser) {
  load("position:0 (driver \"readlog\" index 0)\n"
       "localize:0 (driver \"amcl\" position_index 0 laser_index 0 map_file \"" +
       testing::cave_map_path().string() + "\" map_scale 0.03 map_negate 1)\n");
  EXPECT_FALSE(localize().subscribe());
  EXPECT_EQ(builtin.device(protocol::kPositionCode).subscriptions(), 0);
}

TEST(AmclDriverSpec, ServesLocalizeReadOnlyWithAQueueOf100) {
  const core::DriverSpec spec = amcl_driver_spec();
  EXPECT_EQ(spec.name, "amcl");
  EXPECT_EQ(spec.interfaces, (std::vector<std::uint16_t>{kLocalizeCode}));
  EXPECT_EQ(spec.access, protocol::Access::kRead);
  EXPECT_EQ(spec.limits.request_queue, 100u);
}

}  // namespace amcl_driver_test
}  // namespace playerkit::drivers
