// player-serve --picture: the host feeds the trails every step and writes the
// PNG on request (the simulation device's byte 3) and when it stops.

#include "drivers/sim/simulation_picture.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "drivers/sim/sim_test_support.hpp"
#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/messages/simulation.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::sim {
namespace simulation_picture_test {

using namespace testing;
using protocol::MessageType;

// Collects what the host logs.
struct LogLines {
  core::Logger logger;
  std::vector<std::string> lines;
  LogLines() {
    logger.set_sink([this](core::LogLevel, std::string_view line) { lines.emplace_back(line); });
  }
  [[nodiscard]] int count(const std::string& part) const {
    int found = 0;
    for (const std::string& line : lines) found += line.find(part) != std::string::npos ? 1 : 0;
    return found;
  }
};

// A red robot at the origin facing +x on the 20 x 20 m floor: 1600 px at 80 px/m.
World robot_world() {
  World world({.step = 0.1, .seed = 1}, open_floor());
  world.add(test_robot("robot"));
  return world;
}

SimulationSettings with_picture(const std::filesystem::path& file, std::vector<std::filesystem::path> inputs = {}) {
  SimulationSettings settings = stepped_by_hand();
  settings.picture = PictureSettings{.file = file, .inputs = std::move(inputs)};
  return settings;
}

// Drives the robot 2 m along +x at 1 m/s, a step at a time.
void drive_two_metres(SimulationHost& host) {
  host.activate(0);
  host.with_world([](World& world) { world.command_velocity(0, {1.0, 0.0, 0.0}); });
  for (int i = 0; i < 20; ++i) host.step();
}

cv::Vec3b pixel_at(const cv::Mat& image, double x, double y) {
  // 80 px/m from the map's top left corner (-10, 10).
  const int col = static_cast<int>((x + 10.0) * 80.0);
  const int row = static_cast<int>((10.0 - y) * 80.0);
  return image.at<cv::Vec3b>(row, col);
}

bool near_bgr(const cv::Vec3b& actual, int b, int g, int r, int tolerance) {
  return std::abs(actual[0] - b) <= tolerance && std::abs(actual[1] - g) <= tolerance &&
         std::abs(actual[2] - r) <= tolerance;
}

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SimulationPictureTest, TheTrailFollowsEveryStepAndTheRequestWritesIt) {
  const playerkit::testing::ScratchDirectory scratch("simulation_picture_test");
  const auto file = scratch.file("world.png");
  LogLines log;
  SimulationHost host(robot_world(), "test.world", with_picture(file), log.logger);
  drive_two_metres(host);
  ASSERT_TRUE(host.write_picture());
  EXPECT_EQ(log.count("test.world: wrote the picture " + file.string() + " (t = 2 s)"), 1);

  const cv::Mat image = cv::imread(file.string(), cv::IMREAD_COLOR);
  ASSERT_EQ(image.cols, 1600);
  ASSERT_EQ(image.rows, 1600);
  // The trail (3/5 of the robot's red, 2 px wide along y = 0) from the start
  // to where the body now begins (2 - 0.265 m); nothing before the start or beside it.
  for (const double x : {0.1, 0.5, 1.0, 1.5}) {
    EXPECT_TRUE(near_bgr(pixel_at(image, x, 0.0), 0, 0, 153, 40)) << x << " " << pixel_at(image, x, 0.0);
  }
  EXPECT_TRUE(near_bgr(pixel_at(image, -0.5, 0.0), 255, 255, 255, 0));
  EXPECT_TRUE(near_bgr(pixel_at(image, 1.0, 0.5), 255, 255, 255, 0));
  // The body where the robot is now, in its colour.
  EXPECT_TRUE(near_bgr(pixel_at(image, 2.0 - 0.15, 0.1), 0, 0, 255, 0));
}

TEST(SimulationPictureTest, StoppingWritesTheFinalPictureOnce) {
  const playerkit::testing::ScratchDirectory scratch("simulation_picture_test");
  const auto file = scratch.file("final.png");
  LogLines log;
  {
    SimulationHost host(robot_world(), "test.world", with_picture(file), log.logger);
    host.start();
    drive_two_metres(host);
    host.stop();
    EXPECT_EQ(contents(file).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    std::filesystem::remove(file);
    host.stop();  // again, and by the destructor: nothing more
  }
  EXPECT_FALSE(std::filesystem::exists(file));
  EXPECT_EQ(log.count("wrote the picture"), 1);
  // Never started (--check, a set-up that failed): no picture at all.
  { SimulationHost host(robot_world(), "test.world", with_picture(file), log.logger); }
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(SimulationPictureTest, NoPictureOrOneOverAnInputIsRefusedAndLogged) {
  const playerkit::testing::ScratchDirectory scratch("simulation_picture_test");
  LogLines log;
  SimulationHost none(robot_world(), "test.world", stepped_by_hand(), log.logger);
  EXPECT_FALSE(none.write_picture());
  EXPECT_EQ(log.count("no picture to write"), 1);

  const auto world_file = scratch.write("test.world", "resolution 0.05\n");
  SimulationHost over(robot_world(), "test.world", with_picture(world_file, {world_file}), log.logger);
  EXPECT_FALSE(over.write_picture());
  EXPECT_EQ(log.count("picture not written"), 1);
  EXPECT_EQ(contents(world_file), "resolution 0.05\n");
}

TEST(SimulationPictureTest, TheSimulationDeviceWritesItOnByteThree) {
  const playerkit::testing::ScratchDirectory scratch("simulation_picture_test");
  const auto file = scratch.file("asked.png");
  SimDevices sim{robot_world(), with_picture(file)};
  sim.load("simulation:0 ( driver \"simulation\" )\n");
  core::Device& control = sim.device(protocol::kSimulationCode);
  ASSERT_TRUE(control.subscribe());
  const core::Reply reply = sim.ask(control, {SimControlDriver::kPicture});
  ASSERT_EQ(reply.type, MessageType::kAck);
  EXPECT_EQ(protocol::decode<protocol::SimulationData>(reply.payload).data, 1);  // still paused
  EXPECT_TRUE(std::filesystem::exists(file));
  std::filesystem::remove(file);
  // As a command, at the device's next cycle.
  ASSERT_EQ(control.put_command(1, std::vector<std::uint8_t>{SimControlDriver::kPicture}),
            core::Device::CommandStatus::kAccepted);
  sim.cycle(control);
  EXPECT_TRUE(std::filesystem::exists(file));

  SimDevices without{robot_world()};
  without.load("simulation:0 ( driver \"simulation\" )\n");
  core::Device& plain = without.device(protocol::kSimulationCode);
  ASSERT_TRUE(plain.subscribe());
  EXPECT_EQ(without.ask(plain, {SimControlDriver::kPicture}).type, MessageType::kNack);
}

}  // namespace simulation_picture_test
}  // namespace playerkit::drivers::sim
