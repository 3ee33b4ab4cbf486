// `player-drivers emulate p2os sicklms200` without the tool: the built-in
// families' emulators in one rig, a SICK laser riding on an emulated
// Pioneer and seeing a wall from where the robot has it. The rig itself is
// tested with toy kinds in lib/emulators/catalog/emulator_rig_test.cpp.

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/catalog/emulator_rig.hpp"
#include "families/builtin_families.hpp"
#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/scan.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "links/framed_reader.hpp"
#include "links/open_link.hpp"

namespace playerkit {
namespace pioneer_rig_test {

using namespace std::chrono_literals;
using emulators::EmulatorRig;
using emulators::PtyEndpoint;
using emulators::TcpEndpoint;

emulators::EmulatorCatalog catalog() { return families::builtin_families().emulator_catalog(); }

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

std::filesystem::path temp_link(const std::string& what) {
  return std::filesystem::temp_directory_path() /
         ("pioneer_rig_test_" + std::to_string(::getpid()) + "_" + what);
}

TEST(PioneerRig, TheBuiltInFamiliesOfferTheRigsEmulators) {
  // Every family built adds its kinds; this rig needs the Pioneer and both lasers.
  const auto kinds = catalog();
  for (const char* name : {"p2os", "sicklms200", "sickpls"}) EXPECT_NE(kinds.find(name), nullptr) << name;
  try {
    EmulatorRig rig(kinds, {{"sicklms", {}, PtyEndpoint{}}}, {});
    ADD_FAILURE() << "started";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "no emulator 'sicklms'; there are " + kinds.names());
  }
}

TEST(PioneerRig, ALaserAloneSeesTheWallFromItsPose) {
  EmulatorRig rig(catalog(), {{"sicklms200", {{"pose", "0.5,0,0"}}, PtyEndpoint{}}},
                  {.map = wall_at_two_metres(), .faults = {}});
  ASSERT_EQ(rig.size(), 1u);
  EXPECT_FALSE(rig.carried(0));
  EXPECT_NEAR(range_ahead(rig.runner(0).device_path()), 1.5, 0.06);
}

TEST(PioneerRig, ALaserRidesOnTheRobotAtItsMount) {
  // The laser is listed first; the robot is started first all the same.
  EmulatorRig rig(catalog(),
                  {{"sicklms200", {{"mount", "0.25,0,0"}}, PtyEndpoint{}}, {"p2os", {{"pose", "1,0,0"}}, PtyEndpoint{}}},
                  {.map = wall_at_two_metres(), .faults = {}});
  ASSERT_EQ(rig.size(), 2u);
  EXPECT_EQ(rig.kind(0).name, "sicklms200");
  EXPECT_TRUE(rig.carried(0));
  EXPECT_FALSE(rig.carried(1));
  EXPECT_NEAR(range_ahead(rig.runner(0).device_path()), 0.75, 0.06);
  EXPECT_EQ(rig.config_line(0), "laser:0 ( driver \"sicklms200\" port \"" + rig.runner(0).device_path() + "\" )");
  EXPECT_EQ(rig.config_line(1),
            "position:0 ( driver \"p2os_position\" port \"" + rig.runner(1).device_path() + "\" )");
  EXPECT_NE(rig.describe(1).find("waiting for SYNC0"), std::string::npos) << rig.describe(1);
}

TEST(PioneerRig, APlsOnATcpPortRidesOnTheRobotWithoutAMap) {
  const auto link = temp_link("robot");
  {
    EmulatorRig rig(catalog(), {{"p2os", {}, PtyEndpoint{link}}, {"sickpls", {}, TcpEndpoint{}}}, {});
    EXPECT_EQ(rig.runner(0).device_path(), link.string());
    EXPECT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_EQ(rig.runner(1).device_path().rfind("tcp:127.0.0.1:", 0), 0u) << rig.runner(1).device_path();
    // With a robot in the rig but no map, the laser still rides on it.
    EXPECT_TRUE(rig.carried(1));
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(PioneerRig, ABadRequestStartsNothing) {
  const auto link = temp_link("first");
  EXPECT_THROW(EmulatorRig(catalog(), {{"p2os", {}, PtyEndpoint{link}}, {"sicklms", {}, PtyEndpoint{}}}, {}),
               std::invalid_argument);
  EXPECT_THROW(
      EmulatorRig(catalog(), {{"p2os", {}, PtyEndpoint{link}}, {"sicklms200", {{"noise", "x"}}, PtyEndpoint{}}}, {}),
      std::invalid_argument);
  // A carried laser told where it stands (pose) instead of where it sits (mount).
  EXPECT_THROW(
      EmulatorRig(catalog(), {{"p2os", {}, PtyEndpoint{link}}, {"sickpls", {{"pose", "1,0,0"}}, PtyEndpoint{}}}, {}),
      std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

}  // namespace pioneer_rig_test
}  // namespace playerkit
