#include "drivers/amcl/amcl_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "drivers/amcl/amcl_test_support.hpp"
#include "drivers/test_support.hpp"

namespace playerkit::drivers {
namespace amcl_options_test {

const std::string kMap = testing::cave_map_path().string();

// The options of a `localize:0 ( driver "amcl" <body> )` section.
AmclOptions options_of(const std::string& body) {
  const auto config = config::ConfigFile::parse("localize:0 ( driver \"amcl\" " + body + " )\n", "test.cfg");
  return read_amcl_options(config.section(config.devices().at(0).section));
}

std::string error_of(const std::string& body) {
  try {
    (void)options_of(body);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kCave = "map_file \"" + kMap + "\" map_scale 0.03 map_negate 1 ";

TEST(AmclOptions, DefaultsFollowThe15Manual) {
  const AmclOptions options = options_of(kCave);
  EXPECT_EQ(options.position_index, 0);
  EXPECT_EQ(options.laser_index, 0);
  ASSERT_TRUE(options.map);
  EXPECT_EQ(options.map->width(), 500);
  EXPECT_DOUBLE_EQ(options.map->resolution(), 0.03);
  EXPECT_EQ(options.parameters.min_particles, 100u);
  EXPECT_DOUBLE_EQ(options.parameters.kld_error, 0.01);
  EXPECT_DOUBLE_EQ(options.parameters.kld_z, 3.0);
  EXPECT_EQ(options.parameters.laser_model, amcl::LaserModelType::likelihood_field);
  EXPECT_DOUBLE_EQ(options.laser_range_max, 8.0);
  EXPECT_FALSE(options.initial_pose);  // no init_pose: anywhere in the map
  EXPECT_EQ(options.seed, 0u);
}

TEST(AmclOptions, TheMapIsCentredUnlessMapOriginPlacesItsCorner) {
  // 500 pixels of 0.03 m: 1.5 put the corner at minus half the map.
  EXPECT_EQ(options_of(kCave).map->origin(), Eigen::Vector2d(-7.5, -7.5));
  // A Stage 1.3 world starts at the bitmap's bottom-left corner.
  EXPECT_EQ(options_of(kCave + "map_origin [0 0]").map->origin(), Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(options_of(kCave + "map_origin [1 -2]").map->origin(), Eigen::Vector2d(1.0, -2.0));
  const std::string error = error_of(kCave + "map_origin [1]");
  EXPECT_NE(error.find("amcl: map_origin must be [x y]"), std::string::npos) << error;
  EXPECT_EQ(error.rfind("test.cfg:1:", 0), 0u) << error;
}

TEST(AmclOptions, ReadsEveryOptionInConfigUnits) {
  const AmclOptions options = options_of(
      kCave +
      "odom_index 2 laser_index 3 pf_min_samples 50 pf_max_samples 800 pf_err 0.05 pf_z 2 "
      "laser_max_samples 12 laser_range_max 5.5 laser_pose [0.1 0 180] laser_model \"beam\" "
      "init_pose [1 2 90] init_pose_var [0.1 0.2 5] update_thresh [0.5 45] "
      "odom_alpha1 0.3 odom_alpha2 0.01 odom_alpha3 0.2 odom_alpha4 0.02 odom_alpha5 0.05 "
      "alpha_slow 0 alpha_fast 0 resample_interval 3 selective_resampling 1 short_reading_filter 0 seed 7 "
      "robot_radius 0.3");
  const amcl::AmclParameters& p = options.parameters;
  EXPECT_EQ(options.position_index, 2);
  EXPECT_EQ(options.laser_index, 3);
  EXPECT_EQ(p.min_particles, 50u);
  EXPECT_EQ(p.max_particles, 800u);
  EXPECT_DOUBLE_EQ(p.kld_error, 0.05);
  EXPECT_DOUBLE_EQ(p.kld_z, 2.0);
  EXPECT_EQ(p.laser_max_beams, 12u);
  EXPECT_EQ(p.laser_model, amcl::LaserModelType::beam);
  EXPECT_DOUBLE_EQ(options.laser_range_max, 5.5);
  EXPECT_DOUBLE_EQ(options.laser_pose.x, 0.1);
  EXPECT_NEAR(std::abs(options.laser_pose.yaw), std::numbers::pi, 1e-12);
  ASSERT_TRUE(options.initial_pose);
  EXPECT_DOUBLE_EQ(options.initial_pose->mean.y, 2.0);
  EXPECT_NEAR(options.initial_pose->mean.yaw, std::numbers::pi / 2, 1e-12);
  // init_pose_var holds standard deviations: the covariance is their squares.
  EXPECT_NEAR(options.initial_pose->covariance(0, 0), 0.01, 1e-12);
  EXPECT_NEAR(options.initial_pose->covariance(1, 1), 0.04, 1e-12);
  EXPECT_NEAR(options.initial_pose->covariance(2, 2), std::pow(5 * std::numbers::pi / 180, 2), 1e-12);
  EXPECT_DOUBLE_EQ(p.update_min_distance, 0.5);
  EXPECT_NEAR(p.update_min_angle, std::numbers::pi / 4, 1e-12);
  EXPECT_DOUBLE_EQ(p.rotation_noise_from_rotation, 0.3);
  EXPECT_DOUBLE_EQ(p.translation_noise_from_rotation, 0.02);
  EXPECT_DOUBLE_EQ(p.strafe_noise_from_translation, 0.05);
  EXPECT_DOUBLE_EQ(p.alpha_fast, 0.0);
  EXPECT_EQ(p.resample_interval, 3u);
  EXPECT_TRUE(p.selective_resampling);
  EXPECT_FALSE(p.short_reading_filter);
  EXPECT_EQ(options.seed, 7u);
}

TEST(AmclOptions, GlobalStartOnRequestOrWhenTheSpreadCoversTheMap) {
  EXPECT_FALSE(options_of(kCave + "init_pose [1 1 0] init_pose_global 1").initial_pose);
  EXPECT_FALSE(options_of(kCave + "init_pose [1 1 0] init_pose_var [1000 1000 100]").initial_pose);
  const AmclOptions guessed = options_of(kCave + "init_pose [1 1 0]");
  ASSERT_TRUE(guessed.initial_pose);
  EXPECT_NEAR(guessed.initial_pose->covariance(0, 0), 0.25, 1e-12);  // 0.5 m by default
}

TEST(AmclOptions, BadValuesAreConfigErrorsAtTheOption) {
  EXPECT_EQ(error_of("map_scale 0.03"), "test.cfg:1:1: amcl: no map: give map_file \"map.pgm\" (and map_scale)");
  const std::string missing = error_of("map_file \"/nonexistent/cave.pgm\" map_scale 0.03");
  EXPECT_EQ(missing.rfind("test.cfg:1:37: amcl: cannot load the map: ", 0), 0u) << missing;
  EXPECT_NE(missing.find("/nonexistent/cave.pgm"), std::string::npos) << missing;

  const std::string model = error_of(kCave + "laser_model \"sonar\"");
  EXPECT_NE(model.find("amcl: laser_model must be \"beam\" or \"likelihood_field\", got \"sonar\""),
            std::string::npos) << model;
  EXPECT_EQ(model.rfind("test.cfg:1:" + std::to_string(28 + kCave.size() + 12) + ":", 0), 0u) << model;

  const std::string count = error_of(kCave + "pf_min_samples -5");
  EXPECT_EQ(count, "test.cfg:1:" + std::to_string(28 + kCave.size() + 15) +
                       ": amcl: pf_min_samples must be at least 1, got -5");
  EXPECT_NE(error_of(kCave + "pf_min_samples 500 pf_max_samples 100").find("pf_max_samples must not be below"),
            std::string::npos);
  EXPECT_NE(error_of(kCave + "pf_err 0").find("pf_err must be greater than 0"), std::string::npos);
  EXPECT_NE(error_of(kCave + "position_index -1").find("position_index must be a device index"),
            std::string::npos);
  EXPECT_NE(error_of(kCave + "init_pose_var [0.1 -1 5]").find("init_pose_var"), std::string::npos);
  EXPECT_NE(error_of(kCave + "sonar_index 0").find("sonar_index is not supported"), std::string::npos);
}

TEST(AmclOptions, ErrorsReachTheServerAsConfigErrors) {
  testing::BuiltinDevices builtin;
  EXPECT_THROW(builtin.load("localize:0 ( driver \"amcl\" laser_model \"x\" " + kCave + ")\n"), config::ConfigError);
}

}  // namespace amcl_options_test
}  // namespace playerkit::drivers
