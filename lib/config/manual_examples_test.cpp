// Every configuration printed in the Player 1.5 manual (chapters 4 and 7),
// reconstructed with line breaks in tests/data/config/manual-*.cfg. Each test
// checks the declared devices and reads the options the way the driver would.

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "config/config_file.hpp"
#include "config/includes.hpp"
#include "config/test_support.hpp"

namespace playerkit::config {
namespace manual_examples_test {

using testing::data_path;
using testing::error_of;

ConfigFile load(const std::string& name, std::uint16_t port = 6665) {
  LoadOptions options;
  options.default_port = port;
  return ConfigFile::load(data_path(name), options);
}

// "port interface:index driver [alwayson]" for each device, in order.
std::vector<std::string> devices_of(const ConfigFile& config) {
  std::vector<std::string> devices;
  for (const DeviceDeclaration& d : config.devices()) {
    devices.push_back(std::to_string(d.port) + " " + d.interface_name + ":" +
                      std::to_string(d.address.index) + " " + d.driver +
                      (d.alwayson ? " alwayson" : ""));
  }
  return devices;
}

const Section& section_of(const ConfigFile& config, std::size_t device) {
  return config.section(config.devices().at(device).section);
}

std::vector<std::string> unused_of(const ConfigFile& config) {
  std::vector<std::string> warnings;
  for (const Warning& warning : config.unused_properties()) warnings.push_back(warning.to_string());
  return warnings;
}

TEST(ManualChapter4, PioneerWithGripperAndPtz) {
  const ConfigFile config = load("manual-4.1-pioneer.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 p2os_position", "6665 sonar:0 p2os_sonar",
                                      "6665 gripper:0 p2os_gripper", "6665 ptz:0 sonyevid30"}));
  EXPECT_EQ(config.ports(), (std::vector<std::uint16_t>{6665}));
  EXPECT_TRUE(config.unused_properties().empty());
}

TEST(ManualChapter4, DeviceWithAPortProperty) {
  const ConfigFile config = load("manual-4.1-port.cfg");
  EXPECT_EQ(devices_of(config), (std::vector<std::string>{"6665 position:0 p2os_position"}));
  EXPECT_EQ(section_of(config, 0).read_string("port", "/dev/ttyS1"), "/dev/ttyS0");
}

TEST(ManualChapter4, DefinedDeviceType) {
  const ConfigFile config = load("manual-4.2-define.cfg");
  EXPECT_EQ(devices_of(config), (std::vector<std::string>{"6665 position:0 p2os_position"}));
  const Section& pioneer = section_of(config, 0);
  EXPECT_EQ(pioneer.type(), "position");
  EXPECT_EQ(pioneer.where(), (SourceLocation{data_path("manual-4.2-define.cfg"), 3, 1}));
  EXPECT_EQ(pioneer.read_string("port", ""), "/dev/ttyS0");
}

TEST(ManualAmcl, WithAPioneer) {
  const ConfigFile config = load("manual-7.3-amcl-pioneer.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 p2os_position", "6665 laser:0 sicklms200",
                                      "6665 localize:0 amcl"}));
  EXPECT_EQ(section_of(config, 0).read_string("port", ""), "/dev/ttyS1");
  EXPECT_EQ(section_of(config, 1).read_string("port", ""), "/dev/ttyS2");
  const Section& amcl = section_of(config, 2);
  EXPECT_EQ(amcl.read_int("position_index", -1), 0);
  EXPECT_EQ(amcl.read_int("laser_index", -1), 0);
  EXPECT_EQ(amcl.read_int("sonar_index", -1), -1);
  EXPECT_EQ(amcl.read_filename("map_file", ""), data_path("mymap.pgm"));
  EXPECT_DOUBLE_EQ(amcl.read_length("map_scale", 1.0), 0.05);
  EXPECT_EQ(amcl.read_int("map_negate", 0), 0);
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualAmcl, WithStageThroughPassthrough) {
  // player -p 7000 amcl.cfg
  const ConfigFile config = load("manual-7.3-amcl-stage.cfg", 7000);
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"7000 position:0 passthrough", "7000 laser:0 passthrough",
                                      "7000 localize:0 amcl"}));
  EXPECT_EQ(config.ports(), (std::vector<std::uint16_t>{7000}));
  for (std::size_t i = 0; i < 2; ++i) {
    const Section& remote = section_of(config, i);
    EXPECT_EQ(remote.read_string("host", "localhost"), "localhost");
    EXPECT_EQ(remote.read_int("port", 0), 6665);
    EXPECT_EQ(remote.read_int("index", -1), 0);
  }
  const Section& amcl = section_of(config, 2);
  EXPECT_EQ(amcl.read_filename("map_file", ""), data_path("cave.pnm"));
  EXPECT_DOUBLE_EQ(amcl.read_length("map_scale", 0.05), 0.03);
  EXPECT_EQ(amcl.read_int("map_negate", 0), 1);
  EXPECT_EQ(amcl.read_int("position_index", -1), 0);
  EXPECT_EQ(amcl.read_int("laser_index", -1), 0);
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualCmucam2, AsPrintedThePlaceholderWordsAreRejected) {
  EXPECT_EQ(error_of([] { (void)load("manual-7.5-cmucam2-verbatim.cfg"); }),
            data_path("manual-7.5-cmucam2-verbatim.cfg") +
                ":7:12: syntax error: expected a number or a string in the tuple of 'color0', "
                "found word 'red_min'");
}

TEST(ManualCmucam2, WithNumbersTheStrayParenClosesTheSectionEarly) {
  // The ')' after color0 ends the blobfinder section, leaving color1 outside.
  EXPECT_EQ(error_of([] { (void)load("manual-7.5-cmucam2-numbers.cfg"); }),
            data_path("manual-7.5-cmucam2-numbers.cfg") +
                ":9:3: property 'color1' is outside any section (only unit_length and unit_angle "
                "may be set at global level)");
}

TEST(ManualCmucam2, Corrected) {
  const ConfigFile config = load("manual-7.5-cmucam2.cfg");
  EXPECT_EQ(devices_of(config), (std::vector<std::string>{"6665 blobfinder:0 cmucam2"}));
  const Section& camera = section_of(config, 0);
  EXPECT_EQ(camera.read_string("devicepath", ""), "/dev/ttyS1");
  EXPECT_EQ(camera.read_int("num_blobs", 1), 2);
  ASSERT_EQ(camera.tuple_size("color0"), 6u);
  ASSERT_EQ(camera.tuple_size("color1"), 6u);
  std::vector<int> color0;
  std::vector<int> color1;
  for (std::size_t i = 0; i < 6; ++i) {
    color0.push_back(camera.read_tuple_int("color0", i, 0));
    color1.push_back(camera.read_tuple_int("color1", i, 0));
  }
  EXPECT_EQ(color0, (std::vector<int>{200, 240, 40, 80, 40, 80}));
  EXPECT_EQ(color1, (std::vector<int>{40, 80, 40, 80, 150, 240}));
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualP2os, EveryP2osDriverWithPortAndRadio) {
  const ConfigFile config = load("manual-7.30-p2os.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 p2os_position", "6665 sonar:0 p2os_sonar",
                                      "6665 power:0 p2os_power", "6665 gripper:0 p2os_gripper",
                                      "6665 bumper:0 p2os_bumper", "6665 aio:0 p2os_aio",
                                      "6665 dio:0 p2os_dio", "6665 blobfinder:0 p2os_cmucam",
                                      "6665 position:1 p2os_compass", "6665 sound:0 p2os_sound"}));
  const Section& position = section_of(config, 0);
  EXPECT_EQ(position.read_string("port", "/dev/ttyS0"), "/dev/ttyS0");
  EXPECT_EQ(position.read_int("radio", 0), 1);
  EXPECT_EQ(section_of(config, 1).read_int("radio", 0), 0);  // the default where absent
  (void)section_of(config, 9).read_string("port", "/dev/ttyS0");
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualPassthrough, TheRobotsOwnServer) {
  const ConfigFile config = load("manual-7.31-robot.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 p2os_position", "6665 laser:0 sicklms200"}));
}

TEST(ManualPassthrough, OracAggregatesTwoRobots) {
  const ConfigFile config = load("manual-7.31-orac.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 passthrough", "6665 laser:0 passthrough",
                                      "6665 position:1 passthrough", "6665 laser:1 passthrough"}));
  const std::vector<std::string> hosts = {"bee", "bee", "bug", "bug"};
  for (std::size_t i = 0; i < hosts.size(); ++i) {
    EXPECT_EQ(section_of(config, i).read_string("host", "localhost"), hosts[i]);
    EXPECT_EQ(section_of(config, i).read_int("port", 0), 6665);
    EXPECT_EQ(section_of(config, i).read_int("index", -1), 0);
  }
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualPassthrough, ShiftingComputationAsPrintedStopsAtThePlaceholder) {
  // "..." lexes as a number (a run of dots) standing where a property should be.
  EXPECT_EQ(error_of([] { (void)load("manual-7.31-shifting-verbatim.cfg"); }),
            data_path("manual-7.31-shifting-verbatim.cfg") +
                ":3:66: syntax error: expected a property or a section, found number '...'");
  EXPECT_EQ(error_of([] { (void)load("manual-7.31-stage-verbatim.cfg"); }),
            data_path("manual-7.31-stage-verbatim.cfg") +
                ":3:66: syntax error: expected a property or a section, found number '...'");
}

TEST(ManualPassthrough, ShiftingComputationWithoutThePlaceholderNamesTheOldDriver) {
  const std::string path = data_path("manual-7.31-shifting-verbatim.cfg");
  std::string text = read_text_file(path).value();
  text.erase(text.find(" ..."), 4);
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse(text, path); }),
            path + ":3:20: unknown driver 'adaptive_mcl' for localize:0");
}

TEST(ManualPassthrough, ShiftingComputationCorrected) {
  const ConfigFile config = load("manual-7.31-shifting.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 passthrough", "6665 laser:0 passthrough",
                                      "6665 localize:0 amcl"}));
  EXPECT_EQ(section_of(config, 1).read_string("host", ""), "bee");
  EXPECT_EQ(section_of(config, 2).read_filename("map_file", ""), data_path("mymap.pgm"));
}

TEST(ManualPassthrough, AmclWithStageCorrected) {
  const ConfigFile config = load("manual-7.31-stage.cfg", 7000);
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"7000 position:0 passthrough", "7000 laser:0 passthrough",
                                      "7000 localize:0 amcl"}));
  EXPECT_EQ(section_of(config, 0).read_string("host", "localhost"), "localhost");
  EXPECT_EQ(section_of(config, 2).read_int("map_negate", 0), 1);
}

TEST(ManualRflex, OptionsOfEveryTable) {
  const ConfigFile config = load("manual-7.34-rflex.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 rflex_position", "6665 sonar:0 rflex_sonar",
                                      "6665 bumper:0 rflex_bumper", "6665 ir:0 rflex_ir",
                                      "6665 power:0 rflex_power"}));
  const Section& position = section_of(config, 0);
  EXPECT_EQ(position.read_string("rflex_serial_port", ""), "/dev/ttyS0");
  EXPECT_EQ(position.read_int("mm_length", 0), 500);
  EXPECT_EQ(position.read_int("mm_width", 0), 500);
  EXPECT_DOUBLE_EQ(position.read_float("odo_distance_conversion", 0), 93.0);
  EXPECT_DOUBLE_EQ(position.read_float("odo_angle_conversion", 0), 38197.0);
  EXPECT_EQ(position.read_int("default_trans_acceleration", 0), 500);
  EXPECT_DOUBLE_EQ(position.read_float("default_rot_acceleration", 0), 0.7);

  const Section& sonar = section_of(config, 1);
  EXPECT_FALSE(sonar.has("rflex_serial_port"));  // only the first rflex device names it
  EXPECT_DOUBLE_EQ(sonar.read_float("range_distance_conversion", 0), 1.476);
  EXPECT_EQ(sonar.read_int("sonar_age", 0), 1);
  EXPECT_EQ(sonar.read_int("max_num_sonars", 0), 64);
  EXPECT_EQ(sonar.read_int("num_sonars", 0), 3);
  EXPECT_EQ(sonar.read_int("num_sonar_banks", 0), 1);
  EXPECT_EQ(sonar.read_int("num_sonars_possible_per_bank", 0), 16);
  EXPECT_EQ(sonar.tuple_size("num_sonars_in_bank"), 1u);
  EXPECT_EQ(sonar.read_tuple_int("num_sonars_in_bank", 0, 0), 3);
  ASSERT_EQ(sonar.tuple_size("mmrad_sonar_poses"), 9u);
  EXPECT_DOUBLE_EQ(sonar.read_tuple_float("mmrad_sonar_poses", 4, 0), 60.0);
  EXPECT_DOUBLE_EQ(sonar.read_tuple_float("mmrad_sonar_poses", 8, 0), -0.26);

  const Section& bumper = section_of(config, 2);
  EXPECT_EQ(bumper.read_int("bumper_count", 0), 2);
  ASSERT_EQ(bumper.tuple_size("bumper_def"), 10u);
  EXPECT_DOUBLE_EQ(bumper.read_tuple_float("bumper_def", 7, 0), 3.14);
  EXPECT_EQ(bumper.read_int("rflex_bumper_address", 64), 64);

  const Section& ir = section_of(config, 3);
  EXPECT_EQ(ir.read_int("rflex_base_bank", -1), 0);
  EXPECT_EQ(ir.read_int("rflex_bank_count", 0), 2);
  EXPECT_EQ(ir.tuple_size("rflex_banks"), 2u);
  EXPECT_EQ(ir.read_tuple_int("rflex_banks", 1, 0), 1);
  EXPECT_EQ(ir.read_int("pose_count", 0), 2);
  EXPECT_EQ(ir.read_int("ir_min_range", 0), 100);
  EXPECT_EQ(ir.read_int("ir_max_range", 0), 800);
  EXPECT_DOUBLE_EQ(ir.read_tuple_float("rflex_ir_calib", 0, 1), 1.2);
  EXPECT_DOUBLE_EQ(ir.read_tuple_float("rflex_ir_calib", 1, 1), 0.9);
  ASSERT_EQ(ir.tuple_size("poses"), 6u);
  EXPECT_DOUBLE_EQ(ir.read_tuple_angle("poses", 5, 0), std::numbers::pi);

  const Section& power = section_of(config, 4);
  EXPECT_EQ(power.read_int("rflex_power_offset", 0), 12);
  EXPECT_EQ(power.read_int("rflex_done", 0), 1);
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualReadlog, ReplayOdometryAndLaser) {
  const ConfigFile config = load("manual-7.36-readlog.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 readlog", "6665 laser:0 readlog"}));
  EXPECT_EQ(section_of(config, 0).read_int("index", -1), 0);
  EXPECT_EQ(section_of(config, 1).read_int("index", -1), 0);
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualReadlog, PostHocLocalization) {
  const ConfigFile config = load("manual-7.36-readlog-amcl.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 readlog", "6665 laser:0 readlog",
                                      "6665 localize:0 amcl"}));
  const Section& amcl = section_of(config, 2);
  EXPECT_EQ(amcl.read_filename("map_file", ""), data_path("mymap.pnm"));
  EXPECT_DOUBLE_EQ(amcl.read_length("map_scale", 1), 0.05);
}

TEST(ManualWritelog, LogOdometryAndLaserFromStartup) {
  const ConfigFile config = load("manual-7.48-writelog.cfg");
  EXPECT_EQ(devices_of(config),
            (std::vector<std::string>{"6665 position:0 p2os_position", "6665 laser:0 sicklms200",
                                      "6665 null:0 writelog alwayson"}));
  const Section& writelog = section_of(config, 2);
  EXPECT_EQ(writelog.read_string("filename", "writelog.log"), "foo.log");
  ASSERT_EQ(writelog.tuple_size("devices"), 2u);
  EXPECT_EQ(writelog.read_tuple_string("devices", 0, ""), "position:0");
  EXPECT_EQ(writelog.read_tuple_string("devices", 1, ""), "laser:0");
  EXPECT_TRUE(unused_of(config).empty());
}

TEST(ManualWritelog, UnreadOptionsAreReported) {
  // Before the writelog driver reads its options, both are reported.
  const ConfigFile config = load("manual-7.48-writelog.cfg");
  const std::string file = data_path("manual-7.48-writelog.cfg");
  EXPECT_EQ(unused_of(config),
            (std::vector<std::string>{
                file + ":6:3: warning: property 'filename' is defined but not used",
                file + ":7:3: warning: property 'devices' is defined but not used"}));
}

}  // namespace manual_examples_test
}  // namespace playerkit::config
