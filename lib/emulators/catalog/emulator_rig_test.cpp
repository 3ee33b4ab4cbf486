#include "emulators/catalog/emulator_rig.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <stdexcept>

#include "hardware/sick/frame_format.hpp"
#include "hardware/sick/requests.hpp"
#include "hardware/sick/scan.hpp"
#include "hardware/sick/telegram.hpp"
#include "links/framed_reader.hpp"
#include "links/open_link.hpp"

namespace playerkit::emulators {
namespace emulator_rig_test {

using namespace std::chrono_literals;

// 10 m x 10 m of 5 cm cells centred on the origin, free but for a wall
// whose face is at x = 2 m.
std::shared_ptr<const grid::OccupancyGrid> wall_at_two_metres() {
  auto map = std::make_shared<grid::OccupancyGrid>(grid::OccupancyGrid::centred(200, 200, 0.05, grid::CellState::free));
  const int column = map->world_to_cell({2.0 + 0.025, 0.0}).x();
  for (int row = 0; row < map->height(); ++row) map->set(column, row, grid::CellState::occupied);
  return map;
}

// The middle beam (straight ahead) of the first whole scan the laser on
// `port` streams, in metres: asks for the stream, reads at most 5 s.
double range_ahead(const std::string& port) {
  namespace sick = hardware::sick;
  auto link = links::open_link(port, {.baud = 9600});
  const auto format = sick::SickFrameFormat::replies();
  links::FramedReader reader(*link, format, 1024);
  link->write_all(sick::encode_request(sick::StreamAllRequest{}), links::deadline_in(1s));
  const auto deadline = links::deadline_in(5s);
  while (auto telegram = reader.next(deadline)) {
    const sick::Reply reply = sick::unframe_reply(*telegram);
    if (reply.code != sick::kScanReply) continue;
    const sick::Scan scan = sick::parse_scan(reply);
    return sick::distance_of(scan.values.at(scan.values.size() / 2)) / 1000.0;
  }
  return -1.0;
}

TEST(EmulatorRig, ALaserAloneSeesTheWallFromItsPose) {
  EmulatorRig rig({{"sicklms200", {{"pose", "0.5,0,0"}}, PtyEndpoint{}}}, {.map = wall_at_two_metres(), .faults = {}});
  ASSERT_EQ(rig.size(), 1u);
  EXPECT_FALSE(rig.carried(0));
  EXPECT_NEAR(range_ahead(rig.runner(0).device_path()), 1.5, 0.06);
}

TEST(EmulatorRig, ALaserRidesOnTheRobotAtItsMount) {
  // The laser is listed first; the robot is started first all the same.
  EmulatorRig rig({{"sicklms200", {{"mount", "0.25,0,0"}}, PtyEndpoint{}},
                   {"p2os", {{"pose", "1,0,0"}}, PtyEndpoint{}}},
                  {.map = wall_at_two_metres(), .faults = {}});
  ASSERT_EQ(rig.size(), 2u);
  EXPECT_EQ(rig.kind(0).name, "sicklms200");
  EXPECT_TRUE(rig.carried(0));
  EXPECT_FALSE(rig.carried(1));
  EXPECT_NEAR(range_ahead(rig.runner(0).device_path()), 0.75, 0.06);
  EXPECT_EQ(rig.config_line(1),
            "position:0 ( driver \"p2os_position\" port \"" + rig.runner(1).device_path() + "\" )");
  EXPECT_NE(rig.describe(1).find("waiting for SYNC0"), std::string::npos) << rig.describe(1);
}

TEST(EmulatorRig, SymlinksAndTcpPortsAreTheLinesAsked) {
  const auto link = std::filesystem::temp_directory_path() /
                    ("emulator_rig_test_" + std::to_string(::getpid()) + "_robot");
  {
    EmulatorRig rig({{"p2os", {}, PtyEndpoint{link}}, {"sickpls", {}, TcpEndpoint{}}}, {});
    EXPECT_EQ(rig.runner(0).device_path(), link.string());
    EXPECT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_EQ(rig.runner(1).device_path().rfind("tcp:127.0.0.1:", 0), 0u) << rig.runner(1).device_path();
    // With a robot in the rig but no map, the laser still rides on it.
    EXPECT_TRUE(rig.carried(1));
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(EmulatorRig, ABadRequestStartsNothing) {
  const auto link = std::filesystem::temp_directory_path() /
                    ("emulator_rig_test_" + std::to_string(::getpid()) + "_first");
  EXPECT_THROW(EmulatorRig({{"p2os", {}, PtyEndpoint{link}}, {"sicklms", {}, PtyEndpoint{}}}, {}),
               std::invalid_argument);
  EXPECT_THROW(EmulatorRig({{"p2os", {}, PtyEndpoint{link}}, {"sicklms200", {{"noise", "x"}}, PtyEndpoint{}}}, {}),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

}  // namespace emulator_rig_test
}  // namespace playerkit::emulators
