// The options in 1.5's form, read into one robot whichever device opens it,
// and the readings' mapping to Player's structs (rflex.md §3, §4).
#include <gtest/gtest.h>

#include <cmath>

#include "config/errors.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "drivers/test_support.hpp"
#include "families/rflex/driver/rflex_motion.hpp"
#include "families/rflex/driver/rflex_options.hpp"
#include "families/rflex/driver/rflex_readings.hpp"

namespace playerkit::drivers {
namespace rflex_options_test {

namespace hw = hardware::rflex;
using rflex::RflexReadings;
using rflex::RflexSettings;

TEST(RflexVelocity, TheSheetsTranslationAndTheRotationInArbitraryUnits) {
  RflexSettings settings;  // B21r: 103 per mm, 35000 per rad
  settings.default_trans_acceleration = 500;
  const auto [translation, rotation] = rflex::velocity_commands(300, -45, settings);
  // rflex.md §1.1: axis 0, 30900 arb/s, acceleration 51500, torque 30000, forward.
  EXPECT_EQ(translation, (hw::AxisCommand{0, 30900, 51500, 30000, true}));
  EXPECT_EQ(rotation.velocity, static_cast<std::uint32_t>(std::trunc(45 * std::acos(-1.0) / 180 * 35000)));
  EXPECT_FALSE(rotation.positive);
  EXPECT_EQ(rotation.acceleration, 100000U);
  EXPECT_EQ(rotation.torque, 35000U);
  const auto [still, turn] = rflex::velocity_commands(0, 0, settings);
  EXPECT_EQ(still.velocity, 0U);
  EXPECT_TRUE(still.positive);
  EXPECT_EQ(still.acceleration, 51500U);
}

TEST(RflexReadings, OdometryFromCounterStepsAcrossTheirWrap) {
  RflexSettings settings;
  RflexReadings readings(settings);
  EXPECT_FALSE(readings.take_motion({0, 0, 2147483000, 0}));
  EXPECT_TRUE(readings.take_motion({0, 1, 0, 0}));  // the first pair only sets the counters
  EXPECT_EQ(readings.position().xpos, 0);
  // 103 000 units forward across the 32-bit wrap: 1000 mm.
  readings.take_motion({0, 0, static_cast<std::int32_t>(2147483000LL + 103000 - 4294967296LL), 10300});
  readings.take_motion({0, 1, 0, 0});
  EXPECT_EQ(readings.position().xpos, 1000);
  EXPECT_EQ(readings.position().xspeed, 100);
  // A quarter turn left, then 1 m: y grows.
  readings.take_motion({0, 0, static_cast<std::int32_t>(2147483000LL + 103000 - 4294967296LL), 0});
  readings.take_motion({0, 1, static_cast<std::int32_t>(35000 * std::acos(-1.0) / 2), 0});
  EXPECT_EQ(readings.position().yaw, 90);
  readings.take_motion({0, 0, static_cast<std::int32_t>(2147483000LL + 206000 - 4294967296LL), 0});
  readings.take_motion({0, 1, static_cast<std::int32_t>(35000 * std::acos(-1.0) / 2), 0});
  EXPECT_EQ(readings.position().xpos, 1000);
  EXPECT_EQ(readings.position().ypos, 1000);
}

TEST(RflexReadings, SonarIsTheLeastOfTheLastAgeEchoesInBankOrder) {
  RflexSettings settings;
  settings.sonar_age = 3;
  settings.num_sonars = 4;
  settings.num_sonar_banks = 2;
  settings.num_sonars_in_bank = {2, 2};
  settings.range_distance_conversion = 2.0;
  RflexReadings readings(settings);
  readings.take_sonar({{0, 2000}, {1, 400}, {16, 1000}, {17, 600}});
  readings.take_sonar({{0, 1000}, {1, 800}});
  readings.take_sonar({{0, 3000}});
  const auto data = readings.sonar();
  EXPECT_EQ(data.range_count, 4);
  EXPECT_EQ(data.ranges[0], 500);  // min(2000, 1000, 3000) / 2
  EXPECT_EQ(data.ranges[1], 200);
  EXPECT_EQ(data.ranges[2], 500);  // id 16: board 1, channel 0
  EXPECT_EQ(data.ranges[3], 300);
  readings.take_sonar({{0, 3000}, {1, 3000}, {2, 3000}, {3, 3000}, {200, 1}});  // only num_sonars triples
  EXPECT_EQ(readings.unknown_sonar_ids(), 0U);
  readings.take_sonar({{200, 1}});
  EXPECT_EQ(readings.unknown_sonar_ids(), 1U);  // beyond max_num_sonars: 1.5 wrote past its table
}

TEST(RflexReadings, IrBumpersAndPower) {
  RflexSettings settings;
  settings.ir_bank_count = 2;
  settings.ir_base_bank = 1;
  settings.ir_banks = {2, 1};
  settings.ir_pose_count = 3;
  settings.ir_calibration = {{4, 1}, {1, 2}, {1, 1}};
  settings.ir_min_range = 100;
  settings.ir_max_range = 800;
  settings.bumper_count = 2;
  settings.power_offset = 12;
  RflexReadings readings(settings);
  readings.take_ir({{1, 1, 1, 1, 1, 1, 1, 1}, {100, 20, 3, 0, 0, 0, 0, 0}, {50, 0, 0, 0, 0, 0, 0, 0}});
  const auto ir = readings.ir();
  EXPECT_EQ(ir.range_count, 3);
  EXPECT_EQ(ir.voltages[0], 100);
  EXPECT_EQ(ir.ranges[0], 400);  // 4 x 100
  EXPECT_EQ(ir.ranges[1], 400);  // 20 squared
  EXPECT_EQ(ir.ranges[2], 0);    // 50 is below ir_min_range
  EXPECT_TRUE(readings.take_dio({0, 0x41, 0x1F}));
  EXPECT_FALSE(readings.take_dio({0, 0x42, 1}));
  EXPECT_EQ(readings.bumper().bumper_count, 2);
  EXPECT_EQ(readings.bumper().bumpers[1], 0x0F);
  readings.take_status({0, 2640, 0});
  EXPECT_EQ(readings.power().charge, 276);
}

TEST(RflexOptions, TwoDifferentPortsAreAnErrorAtTheSecond) {
  testing::BuiltinDevices devices;
  EXPECT_THROW(devices.load("position:0 ( driver \"rflex_position\" rflex_serial_port \"/dev/ttyR0\" )\n"
                            "sonar:0 ( driver \"rflex_sonar\" rflex_serial_port \"/dev/ttyR1\" )\n"),
               config::ConfigError);
  testing::BuiltinDevices other;
  EXPECT_THROW(other.load("sonar:0 ( driver \"rflex_sonar\" mmrad_sonar_poses [1 2] )\n"), config::ConfigError);
}

}  // namespace rflex_options_test
}  // namespace playerkit::drivers

namespace playerkit::drivers {
namespace rflex_options_readme_test {

// The README's tables are the schemas' own (between "<!-- options
// rflex_<role> -->" and "<!-- end options -->").
TEST(RflexOptions, TheReadmeTablesAreGeneratedFromTheSchemas) {
  const std::string readme = std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/rflex/README.md";
  for (const rflex::RflexRole role : {rflex::RflexRole::position, rflex::RflexRole::sonar, rflex::RflexRole::ir,
                                      rflex::RflexRole::bumper, rflex::RflexRole::power}) {
    const std::string table = rflex::rflex_option_schema(role).markdown();
    EXPECT_EQ(testing::readme_options_table(readme, rflex::driver_name(role)), table) << rflex::driver_name(role);
  }
}

}  // namespace rflex_options_readme_test
}  // namespace playerkit::drivers
