#include "families/sick/driver/sick_scan_config.hpp"

#include <gtest/gtest.h>

#include <variant>

namespace playerkit::drivers::sick_laser {
namespace sick_scan_config_test {

namespace sick = hardware::sick;

ScanConfig lms(int resolution, int fov, int min_angle, int max_angle) {
  ScanConfig config;
  config.resolution_cdeg = resolution;
  config.fov_deg = fov;
  config.min_angle_cdeg = min_angle;
  config.max_angle_cdeg = max_angle;
  return config;
}

TEST(SickScanConfig, DefaultsAreTheSheets361ValuesFromMinus90To90) {
  const ScanConfig config = default_scan_config(Model::lms200);
  EXPECT_FALSE(problem_with(config, Model::lms200));
  EXPECT_EQ(window_of(config), (ScanWindow{0, 360}));
  EXPECT_EQ(window_min_angle(config), -9000);
  EXPECT_EQ(window_max_angle(config), 9000);
  EXPECT_TRUE(std::holds_alternative<sick::StreamAllRequest>(stream_request(config, Model::lms200)));
  EXPECT_EQ(device_unit(config, Model::lms200), sick::Unit::millimetre);
  EXPECT_TRUE(config.intensity);
  EXPECT_FALSE(default_scan_config(Model::pls).intensity);
}

TEST(SickScanConfig, EveryLms200VariantStreamsAllItsValues) {
  // sicklms200.md §3.1: res 100 -> 181 values, res 25 -> 401 over -50..50.
  struct Case {
    int resolution, fov, count;
  };
  for (const Case c : {Case{50, 180, 361}, Case{100, 180, 181}, Case{25, 100, 401}, Case{50, 100, 201},
                       Case{100, 100, 101}}) {
    const ScanConfig config = lms(c.resolution, c.fov, -c.fov * 50, c.fov * 50);
    EXPECT_FALSE(problem_with(config, Model::lms200)) << c.resolution << "/" << c.fov;
    EXPECT_EQ(window_of(config).count(), c.count);
    EXPECT_EQ(device_value_count(config, Model::lms200), c.count);
    EXPECT_EQ(device_variant(config, Model::lms200), (sick::Variant{static_cast<std::uint16_t>(c.fov),
                                                                     static_cast<std::uint16_t>(c.resolution)}));
    EXPECT_TRUE(std::holds_alternative<sick::StreamAllRequest>(stream_request(config, Model::lms200)));
  }
}

TEST(SickScanConfig, ANarrowerWindowIsASubrangeWithOneBasedIndices) {
  // -45..45 deg at 0.5 deg: segments 90..270, device values 91..271.
  const ScanConfig config = lms(50, 180, -4500, 4500);
  EXPECT_EQ(window_of(config), (ScanWindow{90, 270}));
  const auto request = stream_request(config, Model::lms200);
  ASSERT_TRUE(std::holds_alternative<sick::StreamSubrangeRequest>(request));
  EXPECT_EQ(std::get<sick::StreamSubrangeRequest>(request).range, (sick::Subrange{91, 271}));
}

TEST(SickScanConfig, AnglesBetweenBeamsTruncateAsThe15Driver) {
  // (angle + 9000) / resolution with C truncation: -8990 -> segment 0.
  const ScanConfig config = lms(50, 180, -8990, 8990);
  EXPECT_EQ(window_of(config), (ScanWindow{0, 359}));
  EXPECT_EQ(window_min_angle(config), -9000);
  EXPECT_EQ(window_max_angle(config), 8950);
}

TEST(SickScanConfig, ImpossibleCombinationsAreNamed) {
  EXPECT_EQ(problem_with(lms(30, 180, -9000, 9000), Model::lms200).value_or(""),
            "resolution 30 is not one of 25, 50, 100 (0.01 deg)");
  EXPECT_EQ(problem_with(lms(25, 180, -9000, 9000), Model::lms200).value_or(""),
            "resolution 25 (0.25 deg) needs fov 100");
  ScanConfig bad_unit = lms(50, 180, -9000, 9000);
  bad_unit.range_res = 5;
  EXPECT_EQ(problem_with(bad_unit, Model::lms200).value_or(""), "range_res 5 is not one of 1, 10, 100");
  EXPECT_EQ(problem_with(lms(50, 180, 100, -100), Model::lms200).value_or(""),
            "min_angle 1 deg is above max_angle -1 deg");
  EXPECT_NE(problem_with(lms(50, 100, -9000, 9000), Model::lms200).value_or("").find("outside the field of view"),
            std::string::npos);
  EXPECT_EQ(problem_with(lms(25, 180, -9000, 9000), Model::pls).value_or(""),
            "resolution 25 is not 50 or 100 (0.01 deg): the PLS scans at 0.5 deg");
}

TEST(SickScanConfig, SetConfigFollowsTheResolutionWithTheFieldOfViewAndClampsAngles) {
  protocol::LaserConfig request{protocol::kLaserSetConfig, -9000, 9000, 25, 10, 0};
  ScanConfig config = from_laser_config(request, Model::lms200, 180);
  EXPECT_EQ(config.fov_deg, 100);
  EXPECT_EQ(config.min_angle_cdeg, -5000);
  EXPECT_EQ(config.max_angle_cdeg, 5000);
  EXPECT_EQ(config.range_res, 10);
  EXPECT_FALSE(config.intensity);
  EXPECT_FALSE(problem_with(config, Model::lms200));
  EXPECT_EQ(device_unit(config, Model::lms200), sick::Unit::centimetre);

  request.resolution = 50;
  EXPECT_EQ(from_laser_config(request, Model::lms200, 180).fov_deg, 180);
  EXPECT_EQ(from_laser_config(request, Model::lms200, 100).fov_deg, 100);
}

TEST(SickScanConfig, LaserConfigCarriesTheWindowInForce) {
  const protocol::LaserConfig config = to_laser_config(lms(100, 180, -4550, 4550), Model::lms200, 3);
  EXPECT_EQ(config.subtype, 3);
  EXPECT_EQ(config.min_angle, -4600);  // (4450 / 100) truncates to segment 44
  EXPECT_EQ(config.max_angle, 4500);
  EXPECT_EQ(config.resolution, 100);
  EXPECT_EQ(config.range_res, 1);
  EXPECT_EQ(config.intensity, 1);
  EXPECT_EQ(to_laser_config(default_scan_config(Model::pls), Model::pls, 3).intensity, 0);
}

TEST(SickScanConfig, APlsAtOneDegreeTakesEverySecondValue) {
  ScanConfig config = default_scan_config(Model::pls);
  config.resolution_cdeg = 100;
  EXPECT_FALSE(problem_with(config, Model::pls));
  EXPECT_EQ(device_variant(config, Model::pls), sick::kPlsVariant);
  EXPECT_EQ(decimation(config, Model::pls), 2);
  EXPECT_EQ(window_of(config).count(), 181);
  EXPECT_EQ(device_value_count(config, Model::pls), 361);
  EXPECT_TRUE(std::holds_alternative<sick::StreamAllRequest>(stream_request(config, Model::pls)));
  EXPECT_EQ(device_unit(config, Model::pls), sick::Unit::centimetre);

  // 0..45 deg at 1 deg: segments 90..135, 0.5 deg values 181..271.
  config.min_angle_cdeg = 0;
  config.max_angle_cdeg = 4500;
  const auto request = stream_request(config, Model::pls);
  ASSERT_TRUE(std::holds_alternative<sick::StreamSubrangeRequest>(request));
  EXPECT_EQ(std::get<sick::StreamSubrangeRequest>(request).range, (sick::Subrange{181, 271}));
  EXPECT_EQ(device_value_count(config, Model::pls), 91);
}

}  // namespace sick_scan_config_test
}  // namespace playerkit::drivers::sick_laser
