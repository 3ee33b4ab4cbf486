// player-serve -s WORLD as its library runs it (daemon::Daemon), on a free
// loopback port: a Player client opens the simulated robot, drives it and
// reads its position and laser, stamped with simulation time.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "client/client.hpp"
#include "daemon/daemon.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/simulation.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit {
namespace simulated_robot_test {

using namespace std::chrono_literals;
using protocol::Access;
using protocol::MessageType;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kLaser{protocol::kLaserCode, 0};
constexpr protocol::DeviceAddress kTruth{protocol::kTruthCode, 0};
constexpr protocol::DeviceAddress kSimulation{protocol::kSimulationCode, 0};

// simple.world served on a free loopback port, at `speedup`× real time.
struct ServedWorld {
  explicit ServedWorld(double speedup, bool paused = false) : daemon(options(speedup, paused)) {
    daemon.load();
    daemon.start();
    serving = std::jthread([this] { daemon.run(); });
  }
  ~ServedWorld() { daemon.stop(); }

  static daemon::ServeOptions options(double speedup, bool paused) {
    daemon::ServeOptions options;
    options.port = 0;
    options.bind_address = "127.0.0.1";
    options.log_level = core::LogLevel::kError;
    daemon::SimulationOptions simulation;
    simulation.world = std::string(PLAYERKIT_WORLDS_DIR) + "/simple.world";
    simulation.speedup = speedup;
    simulation.paused = paused;
    options.simulation = simulation;
    return options;
  }

  daemon::Daemon daemon;
  std::jthread serving;  // last: stops (joins) before the daemon goes
};

// The next data message of `device`, skipping the rest.
std::optional<protocol::Message> next_data(client::Client& client, protocol::DeviceAddress device) {
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (std::chrono::steady_clock::now() < deadline) {
    auto message = client.read(1s);
    if (message && message->type() == MessageType::kData && message->device() == device) return message;
  }
  return std::nullopt;
}

TEST(SimulatedRobotTest, AClientDrivesTheRobotAndReadsPositionAndLaser) {
  ServedWorld world(4.0);
  auto client = client::Client::connect("127.0.0.1", world.daemon.default_port());
  const auto devices = client.device_list();
  ASSERT_EQ(devices.size(), 5u);  // position, sonar, laser, truth, simulation
  EXPECT_EQ(devices[0].driver_name, "position");
  EXPECT_EQ(devices[2].driver_name, "laser");
  ASSERT_EQ(client.request_access(kPosition, Access::kAll).access, Access::kAll);
  ASSERT_EQ(client.request_access(kLaser, Access::kRead).access, Access::kRead);

  // The laser: Stage 1.3's 361 samples over 180°, and the cave's walls in view.
  const auto scan_message = next_data(client, kLaser);
  ASSERT_TRUE(scan_message);
  const auto scan = protocol::decode<protocol::LaserData>(scan_message->payload);
  EXPECT_EQ(scan.range_count, 361);
  EXPECT_EQ(scan.min_angle, -9000);
  EXPECT_EQ(scan.resolution, 50);
  int hits = 0;
  for (int i = 0; i < scan.range_count; ++i) {
    EXPECT_LE(scan.ranges[static_cast<std::size_t>(i)], 8000);
    if (scan.ranges[static_cast<std::size_t>(i)] < 8000) ++hits;
  }
  EXPECT_GT(hits, 0);
  // Simulation time: seconds since the world was loaded, not the epoch.
  EXPECT_LT(scan_message->timestamp().seconds(), 1000.0);

  // Drive: 300 mm/s ahead. Once the data says so, the odometry covers
  // 300 mm per second of simulation time.
  protocol::PositionCommand drive;
  drive.xspeed = 300;
  drive.state = 1;
  client.write_command(kPosition, protocol::encode(drive));
  std::optional<protocol::Message> first;
  for (int i = 0; i < 200 && !first; ++i) {
    auto message = next_data(client, kPosition);
    ASSERT_TRUE(message);
    if (protocol::decode<protocol::PositionData>(message->payload).xspeed == 300) first = message;
  }
  ASSERT_TRUE(first) << "the command never showed in the data";
  std::optional<protocol::Message> later;
  while (!later) {
    auto message = next_data(client, kPosition);
    ASSERT_TRUE(message);
    if (message->timestamp().seconds() >= first->timestamp().seconds() + 1.5) later = message;
  }
  const auto a = protocol::decode<protocol::PositionData>(first->payload);
  const auto b = protocol::decode<protocol::PositionData>(later->payload);
  ASSERT_EQ(b.stall, 0);
  const double elapsed = later->timestamp().seconds() - first->timestamp().seconds();
  const double travelled = std::hypot(b.xpos - a.xpos, b.ypos - a.ypos);
  // Odometry error: Stage's default draw, at most 1.5 % per axis.
  EXPECT_NEAR(travelled, 300.0 * elapsed, 0.03 * 300.0 * elapsed + 2.0);
  // The header's time is the server clock: simulation time too.
  EXPECT_LT(later->time().seconds(), 1000.0);
  EXPECT_GE(later->time(), later->timestamp());
}

TEST(SimulatedRobotTest, PausedNothingNewArrivesAndAStepBringsOneStepMore) {
  ServedWorld world(1.0, true);
  auto client = client::Client::connect("127.0.0.1", world.daemon.default_port());
  ASSERT_EQ(client.request_access(kTruth, Access::kRead).access, Access::kRead);
  ASSERT_EQ(client.request_access(kSimulation, Access::kAll).access, Access::kAll);
  // Paused from the start: one step, and the truth says where the robot is then.
  auto reply = client.request(kSimulation, std::vector<std::uint8_t>{2});
  ASSERT_EQ(reply.type(), MessageType::kAck);
  EXPECT_EQ(protocol::decode<protocol::SimulationData>(reply.payload).data, 1);
  const auto truth = next_data(client, kTruth);
  ASSERT_TRUE(truth);
  EXPECT_EQ(truth->timestamp(), (protocol::Timestamp{0, 100000}));
  const auto pose = protocol::decode<protocol::TruthData>(truth->payload);
  EXPECT_EQ(pose.px, 2000);  // simple.world: pose [2.0 2.0 45]
  EXPECT_EQ(pose.py, 2000);
  EXPECT_EQ(pose.pa, 45);
  // Nothing more while paused (push-new: only SYNCHs).
  for (int i = 0; i < 5; ++i) {
    const auto message = client.read(100ms);
    if (message && message->type() == MessageType::kData) {
      EXPECT_NE(message->device(), kTruth) << "data while paused";
    }
  }
  reply = client.request(kSimulation, std::vector<std::uint8_t>{2});
  ASSERT_EQ(reply.type(), MessageType::kAck);
  const auto next = next_data(client, kTruth);
  ASSERT_TRUE(next);
  EXPECT_EQ(next->timestamp(), (protocol::Timestamp{0, 200000}));
}

// A Stage 1.3 world of 65 robots without ports: a position and a truth device
// each and the simulation device, 131 on the -p port, more than Player 1.5's
// device list holds (64).
TEST(SimulatedRobotTest, MoreDevicesThanTheDeviceListHoldsAreAllServed) {
  const auto world_file = std::filesystem::temp_directory_path() /
                          ("playerkit-crowd-" + std::to_string(::getpid()) + ".world");
  {
    std::ofstream out(world_file);
    out << "size [40 40]\n";
    for (int robot = 0; robot < 65; ++robot) {
      out << "position ( pose [" << 2 + 2 * (robot % 9) << " " << 2 + 2 * (robot / 9) << " 0] )\n";
    }
  }
  daemon::ServeOptions options = ServedWorld::options(1.0, true);
  options.simulation->world = world_file.string();
  options.log_level = core::LogLevel::kWarning;
  daemon::Daemon served(options);
  std::mutex log_mutex;
  std::vector<std::string> warnings;
  served.logger().set_sink([&](core::LogLevel level, std::string_view line) {
    std::lock_guard lock(log_mutex);
    if (level == core::LogLevel::kWarning) warnings.emplace_back(line);
  });
  served.load();
  served.start();
  std::jthread serving([&] { served.run(); });
  struct StopFirst {  // before `serving` joins, whatever fails below
    daemon::Daemon& daemon;
    ~StopFirst() { daemon.stop(); }
  } stop_first{served};
  {
    std::lock_guard lock(log_mutex);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("serves 131 devices; Player 1.5's device list holds 64"), std::string::npos)
        << warnings[0] << " / " << warnings.size();
  }
  auto client = client::Client::connect("127.0.0.1", served.default_port());
  EXPECT_EQ(client.device_list().size(), 64u);
  // Past the list, still there.
  EXPECT_EQ(client.request_access({protocol::kPositionCode, 64}, Access::kRead).access, Access::kRead);
  EXPECT_EQ(client.request_access(kSimulation, Access::kRead).access, Access::kRead);
  client.close();
  std::filesystem::remove(world_file);
}

}  // namespace simulated_robot_test
}  // namespace playerkit
