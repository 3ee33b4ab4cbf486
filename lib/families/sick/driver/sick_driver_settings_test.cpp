// Options of sicklms200 and sickpls as a config file gives them, through the
// built-in registry as the server reads them; no laser needed.
#include "families/sick/driver/sick_driver_settings.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "drivers/driver_harness_test_support.hpp"
#include "drivers/test_support.hpp"
#include "families/sick/driver/sick_laser_driver.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers::sick_laser {
namespace sick_driver_settings_test {

SickDriverSettings settings_of(const std::string& section) {
  testing::BuiltinDevices builtin;
  builtin.load(section + "\n");
  return dynamic_cast<SickLaserDriver&>(builtin.device(protocol::kLaserCode).driver()).settings();
}

std::string error_of(const std::string& section) { return testing::config_error_of(section + "\n"); }

TEST(SickDriverSettings, Lms200DefaultsAreThoseOfThe15Manual) {
  const SickDriverSettings s = settings_of("laser ( driver \"sicklms200\" )");
  EXPECT_EQ(s.model, Model::lms200);
  EXPECT_EQ(s.port, "/dev/ttyS1");
  EXPECT_EQ(s.rate, 38400);
  EXPECT_EQ(s.delay.count(), 0);
  EXPECT_EQ(s.scan, default_scan_config(Model::lms200));
  EXPECT_FALSE(s.invert);
  EXPECT_EQ(s.pose_x, 0.0);
  EXPECT_EQ(s.size_x, 0.15);
  EXPECT_EQ(s.size_y, 0.15);
  EXPECT_EQ(s.reply_timeout.count(), 1000);
}

TEST(SickDriverSettings, PlsDefaultsAreThoseOfThe15Manual) {
  const SickDriverSettings s = settings_of("laser ( driver \"sickpls\" )");
  EXPECT_EQ(s.model, Model::pls);
  EXPECT_EQ(s.rate, 9600);
  EXPECT_FALSE(s.scan.intensity);
  EXPECT_EQ(s.scan.range_res, 1);
}

TEST(SickDriverSettings, EveryOptionIsRead) {
  const SickDriverSettings s = settings_of(
      "laser ( driver \"sicklms200\" port \"tcp:127.0.0.1:4001\" rate 500000 delay 2 resolution 25 "
      "range_res 10 intensity 0 invert 1 min_angle -45 max_angle 30 pose [0.1 -0.2 90] size [0.2 0.3] "
      "reply_timeout 0.25 retry_interval 2 )");
  EXPECT_EQ(s.port, "tcp:127.0.0.1:4001");
  EXPECT_EQ(s.rate, 500000);
  EXPECT_EQ(s.delay.count(), 2);
  EXPECT_EQ(s.scan.resolution_cdeg, 25);
  EXPECT_EQ(s.scan.fov_deg, 100);  // 0.25 deg is scanned over 100 deg
  EXPECT_EQ(s.scan.range_res, 10);
  EXPECT_FALSE(s.scan.intensity);
  EXPECT_TRUE(s.invert);
  EXPECT_EQ(s.scan.min_angle_cdeg, -4500);
  EXPECT_EQ(s.scan.max_angle_cdeg, 3000);
  EXPECT_DOUBLE_EQ(s.pose_x, 0.1);
  EXPECT_DOUBLE_EQ(s.pose_y, -0.2);
  EXPECT_NEAR(s.pose_yaw, std::numbers::pi / 2, 1e-12);  // an angle, degrees in the file
  EXPECT_DOUBLE_EQ(s.size_x, 0.2);
  EXPECT_DOUBLE_EQ(s.size_y, 0.3);
  EXPECT_EQ(s.reply_timeout.count(), 250);
  EXPECT_EQ(s.retry_interval.count(), 2000);
}

TEST(SickDriverSettings, AFieldOfViewOf100KeepsAnglesWithinIt) {
  const SickDriverSettings s = settings_of("laser ( driver \"sicklms200\" resolution 100 fov 100 )");
  EXPECT_EQ(s.scan.fov_deg, 100);
  EXPECT_EQ(s.preferred_fov, 100);
  EXPECT_EQ(s.scan.min_angle_cdeg, -5000);
  EXPECT_EQ(s.scan.max_angle_cdeg, 5000);
}

TEST(SickDriverSettings, BadValuesAreErrorsAtTheirOption) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"driver \"sicklms200\" rate 19200", "test.cfg:1:34: sicklms200: rate must be one of 9600, 38400, 500000 (got 19200)"},
      {"driver \"sicklms200\" resolution 30", "sicklms200: resolution must be one of 25, 50, 100 (got 30)"},
      {"driver \"sicklms200\" resolution 25 fov 180", "sicklms200: fov must be 100 with resolution 25"},
      {"driver \"sicklms200\" range_res 5", "sicklms200: range_res must be one of 1, 10, 100 (got 5)"},
      {"driver \"sicklms200\" min_angle -95", "sicklms200: min_angle must lie within the field of view, -90 to 90 deg"},
      {"driver \"sicklms200\" min_angle 10 max_angle -10", "sicklms200: max_angle must not be below min_angle"},
      {"driver \"sicklms200\" invert 2", "sicklms200: invert must be 0 or 1 (got 2)"},
      {"driver \"sicklms200\" port \"\"", "sicklms200: port must not be empty"},
      {"driver \"sicklms200\" pose [40 0 0]", "sicklms200: pose must lie within 32.767 m"},
      {"driver \"sicklms200\" reply_timeout 0", "sicklms200: reply_timeout must be between 0.05 and 30"},
      {"driver \"sickpls\" resolution 25", "sickpls: resolution must be one of 50, 100 (got 25)"},
      // The port is parsed as the link will be: a bad tcp: address is a
      // config error now, not a failed first subscription.
      {"driver \"sicklms200\" port \"tcp:localhost\"", "sicklms200: port is not a serial port or tcp:HOST:PORT"},
      {"driver \"sicklms200\" port \"tcp:localhost:99999\"", "'99999' is not a TCP port (1..65535)"},
      {"driver \"sickpls\" port \"tcp:localhost\"", "sickpls: port is not a serial port or tcp:HOST:PORT"},
      {"driver \"sickpls\" port \"tcp:localhost:99999\"", "'99999' is not a TCP port (1..65535)"},
  };
  for (const auto& [options, expected] : cases) {
    const std::string error = error_of("laser ( " + options + " )");
    EXPECT_NE(error.find(expected), std::string::npos) << options << "\n  got: " << error;
    EXPECT_EQ(error.rfind("test.cfg:1:", 0), 0u) << error;
  }
}

TEST(SickDriverSettings, ABadPortIsAnErrorAtItsValue) {
  // laser ( driver "sicklms200" port "...": the value starts at column 34.
  EXPECT_EQ(error_of("laser ( driver \"sicklms200\" port \"tcp:localhost\" )")
                .rfind("test.cfg:1:34: sicklms200: port is not a serial port or tcp:HOST:PORT: bad port 'tcp:localhost'", 0),
            0u);
}

// The README's options tables are the schemas' own (between the markers
// "<!-- options DRIVER -->" and "<!-- end options -->").
std::string readme_table(const std::string& driver) {
  return testing::readme_options_table(
      std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/sick/driver/README.md", driver);
}

TEST(SickDriverSettings, TheReadmeTablesAreGeneratedFromTheSchemas) {
  EXPECT_EQ(readme_table("sicklms200"), sick_option_schema(Model::lms200).markdown());
  EXPECT_EQ(readme_table("sickpls"), sick_option_schema(Model::pls).markdown());
}

TEST(SickDriverSettings, BothDriversAreRegisteredReadOnlyForTheLaserWithDocs) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  for (const char* name : {"sicklms200", "sickpls"}) {
    const core::DriverSpec* spec = registry.find(name);
    ASSERT_NE(spec, nullptr) << name;
    EXPECT_EQ(spec->interfaces, std::vector<std::uint16_t>{protocol::kLaserCode});
    EXPECT_EQ(spec->access, protocol::Access::kRead);
    EXPECT_EQ(spec->limits.request_queue, 10u);
    EXPECT_EQ(spec->family, "sick");
    EXPECT_TRUE(spec->doc.needs_hardware);
    EXPECT_FALSE(spec->doc.option_rows().empty());
    EXPECT_NE(spec->doc.example.find(name), std::string::npos);
  }
  EXPECT_EQ(registry.find("sicklms200")->doc.manual_section, "7.39");
  EXPECT_EQ(registry.find("sickpls")->doc.manual_section, "7.40");
}

}  // namespace sick_driver_settings_test
}  // namespace playerkit::drivers::sick_laser
