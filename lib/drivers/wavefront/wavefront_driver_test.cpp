// wavefront between a base that goes wherever it is sent at once and a
// localize device reporting its pose in the map frame (the sheet's fakes,
// wavefront.md §6), on maps written by the tests: goals reached with stall
// going 0 then 1, waypoints that keep clear of a wall, a goal that cannot be
// reached refused at once, the odometric frame, and planning again after the
// localization jumps.

#include "drivers/wavefront/wavefront_driver.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "core/device.hpp"
#include "core/driver.hpp"
#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/localize.hpp"
#include "protocol/messages/position.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers {
namespace wavefront_driver_test {

using namespace std::chrono_literals;
using testing::eventually;

constexpr double kPi = std::numbers::pi;

// The base's odometry and where the localize device puts it on the map.
struct World {
  std::mutex mutex;
  geometry::Pose2 odometry;
  geometry::Pose2 map_from_odometry;  // map pose = map_from_odometry (+) odometry
  std::vector<protocol::PositionCommand> commands;  // as the base received them
  bool frozen = false;  // holds the target it was sent until thawed, as a slow base would
  std::optional<geometry::Pose2> target;
};

class TeleportingBase final : public core::ThreadedDriver {
 public:
  explicit TeleportingBase(std::shared_ptr<World> world) : world_(std::move(world)) {}
  core::Device* localize = nullptr;

 protected:
  void run(std::stop_token stop) override {
    std::uint32_t tick = 0;
    while (sleep_for(stop, 2ms)) {
      protocol::PositionData odometry;
      protocol::LocalizeData localized;
      {
        std::lock_guard lock(world_->mutex);
        if (const auto command = device().take_command()) {
          const auto c = protocol::decode<protocol::PositionCommand>(command->payload);
          world_->commands.push_back(c);
          if (c.type == 1) world_->target = geometry::Pose2{c.xpos / 1000.0, c.ypos / 1000.0, c.yaw * kPi / 180};
          if (c.state == 0) world_->target.reset();
        }
        if (world_->target && !world_->frozen) world_->odometry = *std::exchange(world_->target, std::nullopt);
        const geometry::Pose2& o = world_->odometry;
        odometry.xpos = static_cast<std::int32_t>(std::lround(o.x * 1000));
        odometry.ypos = static_cast<std::int32_t>(std::lround(o.y * 1000));
        odometry.yaw = static_cast<std::int32_t>(std::lround(std::fmod(o.yaw * 180 / kPi + 360, 360)));
        const geometry::Pose2 on_map = world_->map_from_odometry.compose(o);
        localized.hypoth_count = 1;
        localized.hypoths[0].mean = {static_cast<std::int32_t>(std::lround(on_map.x * 1000)),
                                     static_cast<std::int32_t>(std::lround(on_map.y * 1000)),
                                     static_cast<std::int32_t>(std::lround(on_map.yaw * 180 / kPi * 3600))};
      }
      ++tick;
      const protocol::Timestamp now{tick / 10, (tick % 10) * 100000};
      if (localize != nullptr) localize->publish(protocol::encode(localized), now);
      device().publish(protocol::encode(odometry), now);
    }
  }

 private:
  std::shared_ptr<World> world_;
};

class FakeLocalize final : public core::Driver {};

// A PGM of `size` x `size` white pixels with the black ones `blocked(column,
// row from the bottom)` says.
std::filesystem::path write_map(const std::filesystem::path& folder, const std::string& name, int size,
                                const std::function<bool(int, int)>& blocked) {
  const std::filesystem::path file = folder / name;
  std::ofstream out(file, std::ios::binary);
  out << "P5\n" << size << " " << size << "\n255\n";
  for (int row = 0; row < size; ++row) {
    for (int column = 0; column < size; ++column) out.put(blocked(column, size - 1 - row) ? char(0) : char(255));
  }
  return file;
}

struct Wavefront : ::testing::Test {
  Wavefront() {
    devices.registry.add({.name = "teleportingbase",
                          .interfaces = {protocol::kPositionCode},
                          .access = protocol::Access::kAll,
                          .factory = [this](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
                            auto base = std::make_unique<TeleportingBase>(world);
                            teleporter = base.get();
                            return base;
                          },
                          .limits = {},
                          .summary = "test"});
    devices.registry.add({.name = "fakelocalize",
                          .interfaces = {protocol::kLocalizeCode},
                          .access = protocol::Access::kRead,
                          .factory = [](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
                            return std::make_unique<FakeLocalize>();
                          },
                          .limits = {},
                          .summary = "test"});
  }
  void load(const std::filesystem::path& map, const std::string& more = "") {
    devices.load("position:0 ( driver \"teleportingbase\" )\n"
                 "localize:0 ( driver \"fakelocalize\" )\n"
                 "position:1 ( driver \"wavefront\" position_index 0 localize_index 0 map_filename \"" +
                 map.string() + "\" map_scale 0.1 " + more + ")\n");
    teleporter->localize = &devices.device(protocol::kLocalizeCode, 0);
    ASSERT_TRUE(wavefront().subscribe());
  }
  core::Device& wavefront() { return devices.device(protocol::kPositionCode, 1); }
  void goal(int x_mm, int y_mm, int yaw_degrees) {
    ASSERT_EQ(wavefront().put_command(1, protocol::encode(protocol::PositionCommand{
                                             .xpos = x_mm, .ypos = y_mm, .yaw = yaw_degrees, .xspeed = 0,
                                             .yspeed = 0, .yawspeed = 0, .state = 1, .type = 1})),
              core::Device::CommandStatus::kAccepted);
  }
  std::optional<protocol::PositionData> data() {
    const auto sample = wavefront().latest_data();
    if (sample->sequence == 0) return std::nullopt;
    return protocol::decode<protocol::PositionData>(sample->payload);
  }
  std::uint64_t counter(const std::string& name) {
    for (const core::DriverCounter& c : wavefront().driver().counters()) {
      if (c.name == name) return c.value;
    }
    return ~std::uint64_t{0};
  }
  std::vector<protocol::PositionCommand> commands() {
    std::lock_guard lock(world->mutex);
    return world->commands;
  }
  bool stalled() { return data() && data()->stall == 1; }
  // After a goal is reached the base is told to stop; the base takes it on its next tick.
  bool told_to_stop() {
    const auto sent = commands();
    return !sent.empty() && sent.back().state == 0;
  }

  ::playerkit::testing::ScratchDirectory folder;
  std::shared_ptr<World> world = std::make_shared<World>();
  TeleportingBase* teleporter = nullptr;
  testing::BuiltinDevices devices;
};

TEST_F(Wavefront, AGoalInAnEmptyMapIsDrivenToAndReported) {
  load(write_map(folder.path(), "empty.pgm", 41, [](int, int) { return false; }));
  ASSERT_TRUE(eventually([&] { return stalled(); }, 5s));  // stopped before any goal
  goal(1000, 0, 0);
  ASSERT_TRUE(eventually([&] { return counter("goals_reached") == 1 && told_to_stop(); }, 10s));
  ASSERT_TRUE(eventually([&] { return stalled(); }, 5s));
  const auto sent = commands();
  ASSERT_GE(sent.size(), 2u);
  const auto& last_waypoint = sent[sent.size() - 2];
  EXPECT_EQ(last_waypoint.xpos, 1000);
  EXPECT_EQ(last_waypoint.ypos, 0);
  EXPECT_EQ(last_waypoint.type, 1);
  EXPECT_EQ(sent.back().state, 0);  // then told to stop
  EXPECT_EQ(data()->xpos, 1000);
}

TEST_F(Wavefront, WaypointsGoRoundAWallAndKeepClearOfIt) {
  // The sheet's wall: column 35 (x = 0.5 m), rows 15 to 60 from the bottom (y = -1.5 to 3 m).
  load(write_map(folder.path(), "wall.pgm", 61, [](int column, int row) { return column == 35 && row >= 15; }),
       "robot_radius 0.15 safety_dist 0.1");
  goal(1500, 0, 0);
  ASSERT_TRUE(eventually([&] { return counter("goals_reached") == 1 && told_to_stop(); }, 10s));
  double previous_x = 0, previous_y = 0;
  for (const auto& c : commands()) {
    if (c.type != 1) continue;
    const double x = c.xpos / 1000.0, y = c.ypos / 1000.0;
    // Clear of the wall's cells (0.45 to 0.55 m wide, from y = -1.55 m up) by the radius.
    const double dx = std::max(0.0, std::abs(x - 0.5) - 0.05);
    const double dy = std::max(0.0, -1.55 - y);
    EXPECT_GE(std::hypot(dx, dy), 0.15 - 1e-3) << x << ", " << y;
    // No leg crosses the wall: a crossing of x = 0.5 happens below its end.
    if ((previous_x - 0.5) * (x - 0.5) < 0) {
      const double t = (0.5 - previous_x) / (x - previous_x);
      EXPECT_LT(previous_y + t * (y - previous_y), -1.55) << "crossed the wall";
    }
    previous_x = x;
    previous_y = y;
  }
  EXPECT_EQ(commands()[commands().size() - 2].xpos, 1500);
}

TEST_F(Wavefront, AGoalThatCannotBeReachedIsRefusedAtOnce) {
  // A ring of black pixels round (2, 0).
  load(write_map(folder.path(), "ring.pgm", 61, [](int column, int row) {
    const int dx = column - 50, dy = row - 30;
    return std::max(std::abs(dx), std::abs(dy)) == 4;
  }));
  goal(2000, 0, 0);
  ASSERT_TRUE(eventually([&] { return counter("goals_refused") == 1; }, 10s));
  EXPECT_TRUE(stalled());
  EXPECT_TRUE(commands().empty()) << "drove at a goal it cannot reach";
  goal(0, 1000, 0);  // a reachable one afterwards is fine
  ASSERT_TRUE(eventually([&] { return counter("goals_reached") == 1; }, 10s));
}

TEST_F(Wavefront, WaypointsAreHandedDownInTheOdometricFrame) {
  {
    std::lock_guard lock(world->mutex);
    world->map_from_odometry = {1.0, -0.5, kPi / 2};
  }
  load(write_map(folder.path(), "empty.pgm", 41, [](int, int) { return false; }));
  goal(0, 0, 90);  // the map's origin: in odometry, (0.5, 1) facing 0 degrees
  ASSERT_TRUE(eventually([&] { return counter("goals_reached") == 1 && told_to_stop(); }, 10s));
  const auto sent = commands();
  ASSERT_GE(sent.size(), 2u);
  EXPECT_NEAR(sent[sent.size() - 2].xpos, 500, 1);
  EXPECT_NEAR(sent[sent.size() - 2].ypos, 1000, 1);
  EXPECT_NEAR(sent[sent.size() - 2].yaw, 0, 1);
}

TEST_F(Wavefront, PlansAgainWhenTheLocalizationJumps) {
  load(write_map(folder.path(), "empty.pgm", 41, [](int, int) { return false; }));
  {
    std::lock_guard lock(world->mutex);
    world->frozen = true;
  }
  goal(1500, 0, 0);
  ASSERT_TRUE(eventually([&] { return !commands().empty(); }, 10s));
  EXPECT_EQ(counter("replans"), 0u);
  {
    std::lock_guard lock(world->mutex);
    world->map_from_odometry = {0.0, 1.0, 0};  // kidnapped 1 m to the left
  }
  ASSERT_TRUE(eventually([&] { return counter("replans") == 1; }, 10s))
      << counter("replans") << " replans, " << counter("plans") << " plans";
  {
    std::lock_guard lock(world->mutex);
    world->frozen = false;
  }
  ASSERT_TRUE(eventually([&] { return counter("goals_reached") == 1; }, 10s))
      << counter("replans") << " replans, " << counter("plans") << " plans";
  // Reached on the map: in odometry the goal lies 1 m to the right of where it was asked for.
  ASSERT_TRUE(eventually([&] { return told_to_stop(); }, 5s));
  const auto sent = commands();
  EXPECT_EQ(sent[sent.size() - 2].ypos, -1000);
}

}  // namespace wavefront_driver_test
}  // namespace playerkit::drivers
