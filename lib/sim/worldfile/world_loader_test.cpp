// Dialect detection, units, device addresses, errors and warnings of the
// loader, on small worlds written here.
#include "sim/worldfile/world_loader.hpp"

#include <gtest/gtest.h>

#include "sim/worldfile/world_loader_test_support.hpp"

namespace playerkit::sim::worldfile {
namespace world_loader_test {

using namespace loader_test_support;

TEST(WorldLoaderDialect, CluesPickTheDialect) {
  EXPECT_EQ(describe_text("position ( port 6665 )").dialect, Dialect::stage13);
  EXPECT_EQ(describe_text("position ( truth ( ) )").dialect, Dialect::stage13);
  EXPECT_EQ(describe_text("sim_timestep 0.05\nposition ( )").dialect, Dialect::stage13);
  EXPECT_EQ(describe_text("position ( pose [1 2 0 90] )").dialect, Dialect::stage4);
  EXPECT_EQ(describe_text("position ( ranger ( sensor ( samples 10 ) ) )").dialect, Dialect::stage4);
  EXPECT_EQ(describe_text("interval_sim 50\nposition ( laser ( ) )").dialect, Dialect::stage3);
  EXPECT_EQ(describe_text("position ( pose [1 2 0 0] ranger ( scount 4 ) )").dialect, Dialect::stage3);
  EXPECT_EQ(describe_text("define floorplan model ( )\nfloorplan ( )").dialect, Dialect::stage4);
  // No clue either way: Player 1.5's own.
  EXPECT_EQ(describe_text("position ( pose [1 2 0] laser ( ) )").dialect, Dialect::stage13);
  EXPECT_EQ(describe_text("").dialect, Dialect::stage13);
}

TEST(WorldLoaderDialect, MixedCluesAreAnError) {
  EXPECT_EQ(load_error("position ( port 6665 )\nposition ( pose [1 2 0 90] )"),
            "t.world:2:12: this world mixes Stage 1.3 (a port property at t.world:1:12) and Stage 3/4 (a 4-element "
            "pose here) syntax");
}

TEST(WorldLoaderSettings, StepsAndResolutionsPerDialect) {
  const WorldDescription old = describe_text("position ( )");
  EXPECT_DOUBLE_EQ(old.settings.step, 0.1);
  EXPECT_DOUBLE_EQ(old.map.resolution(), 0.05);
  const WorldDescription fast = describe_text("sim_timestep 0.02\nresolution 0.1\nposition ( )");
  EXPECT_DOUBLE_EQ(fast.settings.step, 0.02);
  EXPECT_DOUBLE_EQ(fast.map.resolution(), 0.1);
  const WorldDescription modern = describe_text("interval_sim 50\nposition ( pose [0 0 0 0] )");
  EXPECT_DOUBLE_EQ(modern.settings.step, 0.05);
  EXPECT_DOUBLE_EQ(modern.map.resolution(), 0.02);
  EXPECT_EQ(load_error("interval_sim 0\nmodel ( )"), "t.world:1:1: interval_sim must be more than 0 ms");
  EXPECT_EQ(load_error("resolution -1\nposition ( )"), "t.world:1:1: the world's resolution must be more than 0 m");
}

TEST(WorldLoaderUnits, LengthAndAngleUnitsApplyToTheWholeFile) {
  // unit_* may come after the entities they apply to.
  const WorldDescription world = describe_text(
      "position ( pose [200 100 1.5707963267948966] size [44 38] offset [-4 0] laser ( max_range 500 ) )\n"
      "resolution 5\nunit_length \"cm\"\nunit_angle \"radians\"\n");
  const ModelSpec& robot = world.models.at(0);
  EXPECT_NEAR(robot.pose.x, 2.0, 1e-12);
  EXPECT_NEAR(robot.pose.y, 1.0, 1e-12);
  EXPECT_NEAR(robot.pose.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(robot.body.size.x(), 0.44, 1e-12);
  EXPECT_NEAR(robot.body.offset.x, -0.04, 1e-12);
  EXPECT_NEAR(std::get<LaserSpec>(world.models.at(1).params).range_max, 5.0, 1e-12);
  EXPECT_NEAR(world.map.resolution(), 0.05, 1e-12);  // a length in 1.3
  // Stage 4: resolution, interval_sim and blobfinder range stay plain numbers.
  const WorldDescription modern = describe_text(
      "unit_length \"mm\"\nresolution 0.02\nposition ( pose [1000 0 0 90] velocity_bounds [-500 500 0 0 0 0 -90 90] "
      "blobfinder ( range 6 fov 60 ) )\n");
  EXPECT_NEAR(modern.models.at(0).pose.x, 1.0, 1e-12);
  EXPECT_NEAR(modern.models.at(0).pose.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(std::get<PositionSpec>(modern.models.at(0).params).max_velocity.x(), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(modern.map.resolution(), 0.02);
  EXPECT_DOUBLE_EQ(std::get<BlobfinderSpec>(modern.models.at(1).params).range, 6.0);
  const WorldDescription odd = describe_text("unit_length \"inch\"\nposition ( pose [1 0 0] )");
  ASSERT_EQ(odd.warnings.size(), 1u);
  EXPECT_EQ(odd.warnings[0], "t.world:1:1: unit_length \"inch\" is not \"m\", \"cm\" or \"mm\": lengths stay in metres");
}

TEST(WorldLoaderDevices, Stage13IndicesAreExplicitOrTheNextFree) {
  // Stage 1.3 put both sonars at index 0 (the second overwrote the first).
  const WorldDescription world = describe_text(
      "position ( port 7001 sonar ( scount 2 ) sonar ( scount 3 index 0 ) laser ( port 7002 ) )\n"
      "position ( laser ( ) )\n");
  EXPECT_EQ(device_list(world), (std::vector<std::string>{"7001:4:0 position", "7001:5:1 sonar", "7001:5:0 sonar",
                                                          "7002:6:0 laser", "7001:15:0 truth", "6665:4:0 position",
                                                          "6665:6:0 laser", "6665:15:0 truth"}));
  EXPECT_EQ(std::get<SonarSpec>(world.models.at(device(world, 7001, 5, 0).model).params).transducers.size(), 3u);
  EXPECT_EQ(load_error("position ( sonar ( index 1 ) sonar ( index 1 ) )"),
            "t.world:1:30: sonar:1 on port 6665 is given twice (also at t.world:1:12)");
  EXPECT_EQ(load_error("position ( port 70000 )"), "t.world:1:12: a port must be between 0 and 65535");
}

TEST(WorldLoaderDevices, Stage4RobotKTakesIndexKWhereFree) {
  const WorldDescription world = describe_text(
      "position ( pose [0 0 0 0] ranger ( sensor ( samples 90 ) ) ranger ( sensor ( samples 90 ) ) )\n"
      "position ( pose [1 0 0 0] ranger ( sensor ( samples 90 ) ) fiducial ( ) )\n"
      "position ( pose [2 0 0 0] ranger ( sensor ( ) sensor ( ) ) )\n"
      "model ( pose [3 0 0 0] fiducial ( ) )\n",
      {.default_port = 6000});
  EXPECT_EQ(device_list(world),
            (std::vector<std::string>{"6000:4:0 position", "6000:6:0 ranger", "6000:6:1 ranger", "6000:15:0 truth",
                                      "6000:4:1 position", "6000:6:2 ranger", "6000:10:1 fiducial", "6000:15:1 truth",
                                      "6000:4:2 position", "6000:5:2 ranger", "6000:15:2 truth", "6000:10:0 fiducial"}));
}

TEST(WorldLoaderDevices, EveryRobotHasATruthDevice) {
  const WorldDescription world = describe_text("position ( pose [0 0 0 0] )\nposition ( name \"b\" pose [1 0 0 0] )");
  EXPECT_EQ(device_list(world), (std::vector<std::string>{"6665:4:0 position", "6665:15:0 truth", "6665:4:1 position",
                                                          "6665:15:1 truth"}));
  EXPECT_EQ(model_named(world, "b.truth:0").parent, 2);
}

TEST(WorldLoaderModels, Stage4NamesFollowStage) {
  const WorldDescription world = describe_text(
      "position ( pose [0 0 0 0] ranger ( ) ranger ( name \"front\" ) ranger ( name \"/global\" ) ranger ( ) )\n"
      "position ( pose [1 0 0 0] )\nmodel ( name \"x\" )\nmodel ( name \"x\" )\n");
  std::vector<std::string> names;
  for (const ModelSpec& model : world.models) names.push_back(model.name);
  EXPECT_EQ(names, (std::vector<std::string>{"position:0", "position:0.ranger:0", "position:0.front", "global",
                                             "position:0.ranger:3", "position:0.truth:0", "position:1",
                                             "position:1.truth:0", "x", "x#2"}));
  EXPECT_NE(std::find(world.warnings.begin(), world.warnings.end(),
                      "t.world:4:1: the name \"x\" is taken; this model is named \"x#2\""),
            world.warnings.end());
}

TEST(WorldLoaderModels, Stage3LaserAndScountRanger) {
  const WorldDescription world = describe_text(
      "position ( pose [0 0 0 0] laser ( samples 90 range_max 4 fov 90 laser_return 2 )\n"
      "  ranger ( scount 2 spose[0] [0.1 0 0] spose3[1] [0 0.1 0.2 90] sview [0.1 3 30] ) )\n");
  EXPECT_EQ(world.dialect, Dialect::stage3);
  const auto& laser = std::get<LaserSpec>(world.models.at(1).params);
  EXPECT_EQ(laser.samples, 90);
  EXPECT_DOUBLE_EQ(laser.range_max, 4.0);
  EXPECT_NEAR(laser.fov, 90 * kDeg, 1e-12);
  EXPECT_TRUE(world.models.at(1).returns.laser_bright);
  const auto& sonar = std::get<SonarSpec>(world.models.at(2).params);
  ASSERT_EQ(sonar.transducers.size(), 2u);
  EXPECT_NEAR(sonar.transducers[0].x, 0.1, 1e-12);
  EXPECT_NEAR(sonar.transducers[1].y, 0.1, 1e-12);
  EXPECT_NEAR(sonar.transducers[1].yaw, 90 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(sonar.range_min, 0.1);
  EXPECT_DOUBLE_EQ(sonar.range_max, 3.0);
}

TEST(WorldLoaderModels, Stage4RangerNoiseAndUpdateInterval) {
  const WorldDescription world = describe_text(
      "position ( pose [0 0 0 0] ranger ( update_interval 200 sensor ( samples 11 fov 90 range [0.2 4] "
      "noise [0.0004 0.01 2] ) ) )\n");
  const auto& laser = std::get<LaserSpec>(world.models.at(1).params);
  EXPECT_NEAR(laser.noise_sd, 0.02, 1e-12);  // Stage's c is a variance
  EXPECT_DOUBLE_EQ(laser.noise_proportional, 0.01);
  EXPECT_NEAR(laser.angle_jitter, 2 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(laser.range_min, 0.2);
  EXPECT_DOUBLE_EQ(laser.interval, 0.2);
}

TEST(WorldLoaderErrors, UnknownModelTypeIsAnErrorWithASuggestion) {
  EXPECT_EQ(load_error("define pioneer2dx position ( )\n\n  pioneer2x ( port 6665 )"),
            "t.world:3:3: unknown macro or model type \"pioneer2x\" (did you mean \"pioneer2dx\"?) in a Stage 1.3 world");
  EXPECT_EQ(load_error("position ( pose [0 0 0 0] lazer ( ) )"),
            "t.world:1:27: unknown macro or model type \"lazer\" (did you mean \"laser\"?) in a Stage 4 world");
  EXPECT_EQ(load_error("define robot gps ( )\nrobot ( port 6665 )"),
            "t.world:2:1: unknown macro or model type \"gps\" (the base of macro \"robot\") in a Stage 1.3 world");
  EXPECT_EQ(load_error("robot ( port 6665 )\ndefine robot position ( )"),
            "t.world:1:1: macro \"robot\" is used before its definition at t.world:2:1 (a macro must be defined before "
            "it is used)");
}

TEST(WorldLoaderErrors, ValuesOfTheWrongShape) {
  EXPECT_EQ(load_error("model ( pose [1 2 3] size [1 1 1] origin [0 0 0 0] )"),
            "t.world:1:9: \"pose\" needs 4 values [x y z a], found 3");
  EXPECT_EQ(load_error("position ( port 1 pose [1 2] )"), "t.world:1:19: \"pose\" needs 3 values [x y th], found 2");
  EXPECT_EQ(load_error("position ( port 1 laser ( ) fiducialfinder ( ) )"),
            "t.world:1:29: a fiducialfinder must sit inside a laser (it uses the laser's scan)");
  EXPECT_EQ(load_error("model ( sensor ( ) )"), "t.world:1:9: a sensor must sit inside a ranger");
  EXPECT_EQ(load_error("bitmap ( file \"nowhere.pnm\" resolution 0.1 )").substr(0, 51),
            "t.world:1:10: cannot read the bitmap: " + (worlds_dir() / "nowhere.pnm").string().substr(0, 13));
  EXPECT_EQ(load_error("position ( port 1 x 99999999999999999999999999999999999999999999999999999999999999999999"
                       "99999999999999999999999999999999999999999999999999999999999999999999999999999999999999999"
                       "99999999999999999999999999999999999999999999999999999999999999999999999999999999999999999"
                       "9999999999999999999999999999999999999999999999999999999999999999999999999 )")
                .substr(0, 30),
            "");  // unknown properties are not read: no error
  EXPECT_EQ(load_error("position ( port 1 index 1"
                       "0000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
                       "000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
                       "000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
                       "00000000000000000000 )")
                .substr(0, 50),
            "t.world:1:25: \"index\" must be an integer between -");
  EXPECT_EQ(load_error("position ( port 1 index 1" + std::string(400, '0') + " )").substr(0, 40),
            "t.world:1:25: the number 100000000000000");
}

TEST(WorldLoaderErrors, HostileSizesAreRefused) {
  EXPECT_EQ(load_error("position ( pose [0 0 0 0] ranger ( sensor ( samples 1000000000 ) ) )"),
            "t.world:1:36: samples must be between 1 and 100000, not 1000000000");
  EXPECT_EQ(load_error("position ( pose [0 0 0 0] blobfinder ( image [80 1000000000] ) )"),
            "t.world:1:40: a blobfinder's image must be between 1 and 100000 pixels each way");
  EXPECT_NE(load_error("model ( size [" + std::string(300, '9') + " 1 1] pose [0 0 0 0] boundary 1 )")
                .find("t.world: the world spans more than 1000000 m"),
            std::string::npos);
  EXPECT_EQ(load_error("model ( pose [0 0 0 0] size [0 16 1] bitmap \"stage-cave.png\" )"),
            "t.world:1:38: a model with a bitmap needs a size above 0 in x and y");
}

TEST(WorldLoaderWarnings, UnknownPropertiesAreNamedAndGuiOnesAreNot) {
  const WorldDescription world = describe_text(
      "gui ( size [600 600] scale 0.03 )\n"
      "position ( port 6665 colr \"red\" gui_nose 1\n  laser ( max_rnage 4 ) )\n");
  ASSERT_EQ(world.warnings.size(), 2u);
  EXPECT_EQ(world.warnings[0], "t.world:2:22: unknown property \"colr\" of a position, ignored (did you mean \"color\"?)");
  EXPECT_EQ(world.warnings[1],
            "t.world:3:11: unknown property \"max_rnage\" of a laser, ignored (did you mean \"max_range\"?)");
  const WorldDescription modern = describe_text(
      "window ( size [700 700] scale 30 )\nmodel ( pose [0 0 0 0] gui_move 0 trail_length 5 stack_children 0 )\n");
  EXPECT_TRUE(modern.warnings.empty()) << modern.warnings.front();
}

TEST(WorldLoaderWarnings, ValuesStageWouldMisreadAreNamed) {
  const WorldDescription world =
      describe_text("position ( port 6665 pose [1.2.3 0 0] color \"octarine\" laser_return \"shiny\" )\n");
  ASSERT_EQ(world.warnings.size(), 3u);
  EXPECT_EQ(world.warnings[0], "t.world:1:28: \"1.2.3\" is not a number; it reads as 1.2, as in Stage");
  EXPECT_EQ(world.warnings[1], "t.world:1:45: unknown colour \"octarine\": red is used, as in Stage");
  EXPECT_EQ(world.warnings[2],
            "t.world:1:69: \"shiny\" is not \"visible\", \"bright\" or \"invisible\": invisible, as in Stage");
  EXPECT_NEAR(world.models.at(0).pose.x, 1.2, 1e-12);
  EXPECT_EQ(world.models.at(0).color, (Rgb{255, 0, 0}));
}

TEST(WorldLoaderModels, Stage13ReturnsAndBoxColours) {
  const WorldDescription world = describe_text(
      "position ( port 6665 color \"blue\" box ( ) )\nbox ( )\npuck ( )\n"
      "box ( obstacle_return \"invisible\" sonar_return \"invisible\" laser_return \"invisible\" )\n");
  const ModelSpec& robot = world.models.at(0);
  EXPECT_TRUE(robot.returns.obstacle);
  EXPECT_DOUBLE_EQ(robot.returns.ranger, 1.0);  // sonar-visible
  EXPECT_EQ(world.models.at(1).color, (Rgb{0, 0, 255}));  // a box takes its parent's colour
  EXPECT_EQ(world.models.at(3).color, (Rgb{255, 255, 0}));  // else yellow
  const ModelSpec& puck = world.models.at(4);
  EXPECT_EQ(puck.body.shape, Shape::circle);
  EXPECT_FALSE(puck.returns.obstacle);
  EXPECT_DOUBLE_EQ(puck.returns.ranger, -1.0);
  EXPECT_TRUE(puck.returns.gripper);
  const ModelSpec& ghost = world.models.at(5);
  EXPECT_FALSE(ghost.returns.obstacle);
  EXPECT_DOUBLE_EQ(ghost.returns.ranger, -1.0);
}

TEST(WorldLoaderMap, Stage13BitmapWithAPoseIsCentredThere) {
  // cave.pnm centred at (10, 10) and turned 90 degrees.
  const WorldDescription world =
      describe_text("size [20 20]\nresolution 0.03\nbitmap ( file \"cave.pnm\" resolution 0.03 pose [10 10 90] )\n");
  EXPECT_GE(world.map.width() * 0.03, 20.0 - 1e-9);
  // Pixel (c, r) of the image is at local ((c + 0.5 - 250) 0.03, (249.5 - r) 0.03),
  // turned by 90 degrees: (-local.y, local.x).
  const auto world_of = [](int col, int row) {
    const Eigen::Vector2d local((col + 0.5 - 250.0) * 0.03, (249.5 - row) * 0.03);
    return Eigen::Vector2d(10.0 - local.y(), 10.0 + local.x());
  };
  // The cave's outer wall runs along the image's edges; its inside is free.
  EXPECT_EQ(world.map.state_at_world(world_of(250, 250)), grid::CellState::free);
  int walls = 0;
  for (int col = 0; col < 500; ++col) walls += world.map.state_at_world(world_of(col, 0)) == grid::CellState::occupied;
  EXPECT_GT(walls, 0);
}

}  // namespace world_loader_test
}  // namespace playerkit::sim::worldfile
