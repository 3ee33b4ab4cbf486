#include "amcl_offline_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace amcl_offline_options_test {

using playerkit::amcl_offline::LocalizeCommand;
using playerkit::amcl_offline::make_localize_options;
using playerkit::amcl_offline::make_map_options;
using playerkit::amcl_offline::MapCommand;
using playerkit::amcl_offline::UsageError;
namespace localization = playerkit::localization;

LocalizeCommand global_command() {
  LocalizeCommand command;
  command.log = "run.log";
  command.map = "map.yaml";
  command.global = true;
  return command;
}

// The UsageError's text, or "" when none was thrown.
std::string usage_error(const LocalizeCommand& command) {
  try {
    (void)make_localize_options(command);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(AmclOfflineOptions, DefaultsGiveTheLibrarysFilterParameters) {
  const auto options = make_localize_options(global_command());
  const playerkit::amcl::AmclParameters defaults;
  EXPECT_EQ(options.localization.filter.min_particles, defaults.min_particles);
  EXPECT_EQ(options.localization.filter.max_particles, defaults.max_particles);
  EXPECT_EQ(options.localization.filter.laser_model, playerkit::amcl::LaserModelType::likelihood_field);
  EXPECT_EQ(options.localization.initial.kind, localization::InitialBelief::Kind::global);
  EXPECT_EQ(options.format, localization::EstimateFormat::csv);
  EXPECT_EQ(options.output, "-");
  EXPECT_EQ(options.log, "run.log");
  EXPECT_EQ(options.map, "map.yaml");
}

TEST(AmclOfflineOptions, FlagsReachTheFilter) {
  auto command = global_command();
  command.particles = "200,800";
  command.model = "beam";
  command.laser_beams = 60;
  command.alpha_slow = 0.001;
  command.alpha_fast = 0.1;
  command.update_thresh = "0.5,90";
  command.sigma_hit = 0.1;
  command.every_reading = true;
  command.odom_noise_scale = 2.0;
  command.seed = 7;
  command.format = "log";
  command.scale = 0.03;
  command.negate = true;
  const auto options = make_localize_options(command);
  const auto& filter = options.localization.filter;
  const playerkit::amcl::AmclParameters defaults;
  EXPECT_EQ(filter.min_particles, 200u);
  EXPECT_EQ(filter.max_particles, 800u);
  EXPECT_EQ(filter.laser_model, playerkit::amcl::LaserModelType::beam);
  EXPECT_EQ(filter.laser_max_beams, 60u);
  EXPECT_DOUBLE_EQ(filter.alpha_slow, 0.001);
  EXPECT_DOUBLE_EQ(filter.alpha_fast, 0.1);
  EXPECT_DOUBLE_EQ(filter.update_min_distance, 0.5);
  EXPECT_DOUBLE_EQ(filter.update_min_angle, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(filter.sigma_hit, 0.1);
  EXPECT_FALSE(filter.short_reading_filter);
  EXPECT_TRUE(defaults.short_reading_filter);
  EXPECT_DOUBLE_EQ(filter.rotation_noise_from_rotation, 2.0 * defaults.rotation_noise_from_rotation);
  EXPECT_DOUBLE_EQ(filter.strafe_noise_from_translation, 2.0 * defaults.strafe_noise_from_translation);
  EXPECT_EQ(options.localization.seed, 7u);
  EXPECT_EQ(options.format, localization::EstimateFormat::player_log);
  ASSERT_TRUE(options.map_loading.resolution.has_value());
  EXPECT_DOUBLE_EQ(*options.map_loading.resolution, 0.03);
  EXPECT_TRUE(options.map_loading.negate);
  EXPECT_FALSE(options.map_loading.origin.has_value());  // centred, as Player 1.5
}

TEST(AmclOfflineOptions, OriginPlacesTheMapImage) {
  auto command = global_command();
  command.origin = "0,-1.5";
  const auto options = make_localize_options(command);
  ASSERT_TRUE(options.map_loading.origin.has_value());
  EXPECT_EQ(*options.map_loading.origin, Eigen::Vector2d(0.0, -1.5));
  command.origin = "0";
  EXPECT_TRUE(contains(usage_error(command), "--origin")) << usage_error(command);
  command.origin = "0,x";
  EXPECT_TRUE(contains(usage_error(command), "--origin: 'x' is not a number")) << usage_error(command);
}

TEST(AmclOfflineOptions, InitialPoseInDegreesBecomesRadians) {
  auto command = global_command();
  command.global = false;
  command.init_pose = "1.5,-2,90";
  command.init_var = "0.2,0.3,10";
  const auto initial = make_localize_options(command).localization.initial;
  EXPECT_EQ(initial.kind, localization::InitialBelief::Kind::pose);
  EXPECT_DOUBLE_EQ(initial.pose.x, 1.5);
  EXPECT_DOUBLE_EQ(initial.pose.y, -2.0);
  EXPECT_NEAR(initial.pose.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(initial.sigma_x_m, 0.2);
  EXPECT_DOUBLE_EQ(initial.sigma_y_m, 0.3);
  EXPECT_NEAR(initial.sigma_yaw_rad, 10 * std::numbers::pi / 180, 1e-12);

  command.init_pose = "truth";
  EXPECT_EQ(make_localize_options(command).localization.initial.kind, localization::InitialBelief::Kind::first_truth);
}

TEST(AmclOfflineOptions, CommandLineRulesNameTheirFlag) {
  auto command = global_command();
  command.global = false;
  EXPECT_TRUE(contains(usage_error(command), "--init-pose X,Y,YAW_DEG")) << usage_error(command);
  EXPECT_TRUE(contains(usage_error(command), "--global"));
  command.init_pose = "1,2";
  EXPECT_EQ(usage_error(command), "--init-pose: expected 3 comma-separated numbers, got '1,2'");
  command.init_pose = "1,x,2";
  EXPECT_EQ(usage_error(command), "--init-pose: 'x' is not a number");
  command.global = true;
  EXPECT_EQ(usage_error(command), "--global and --init-pose exclude each other");

  command = global_command();
  command.model = "sonar";
  EXPECT_EQ(usage_error(command), "--model: 'sonar' is not beam or likelihood");
  command = global_command();
  command.format = "xml";
  EXPECT_EQ(usage_error(command), "--format: 'xml' is not csv, json or log");
  command = global_command();
  command.particles = "1.5,10";
  EXPECT_TRUE(contains(usage_error(command), "--particles")) << usage_error(command);
  command = global_command();
  command.odom_noise_scale = 0.0;
  EXPECT_EQ(usage_error(command), "--odom-noise must be > 0");
  command = global_command();
  command.init_var = "0.1,0,3";
  EXPECT_EQ(usage_error(command), "--init-var: every deviation must be > 0");
}

// The filter's own rules come from amcl::validate, under the flag's name.
TEST(AmclOfflineOptions, FilterRulesAreTheLibrarysUnderTheFlagsNames) {
  auto command = global_command();
  command.particles = "500,100";
  EXPECT_TRUE(contains(usage_error(command), "--particles: ")) << usage_error(command);
  command.particles = "0,100";
  EXPECT_TRUE(contains(usage_error(command), "--particles: ")) << usage_error(command);

  command = global_command();
  command.alpha_slow = 0.1;
  command.alpha_fast = 0.01;
  EXPECT_TRUE(contains(usage_error(command), "--alpha-slow/--alpha-fast: ")) << usage_error(command);
  command.alpha_fast = 2.0;
  EXPECT_TRUE(contains(usage_error(command), "--alpha-slow/--alpha-fast: ")) << usage_error(command);
  command.alpha_slow = -0.1;
  command.alpha_fast = 0.1;
  EXPECT_TRUE(contains(usage_error(command), "--alpha-slow/--alpha-fast: ")) << usage_error(command);

  command = global_command();
  command.laser_beams = 0;
  EXPECT_TRUE(contains(usage_error(command), "--laser-beams: ")) << usage_error(command);
  command = global_command();
  command.sigma_hit = 0.0;
  EXPECT_TRUE(contains(usage_error(command), "--sigma-hit: ")) << usage_error(command);
  command = global_command();
  command.update_thresh = "-1,30";
  EXPECT_TRUE(contains(usage_error(command), "--update-thresh: ")) << usage_error(command);
}

TEST(AmclOfflineOptions, MapFlags) {
  MapCommand command;
  command.log = "run.log";
  command.output = "map.pgm";
  command.resolution = 0.1;
  command.max_range = 20;
  command.no_return_clears = 5;
  command.use_odometry = true;
  const auto options = make_map_options(command);
  EXPECT_DOUBLE_EQ(options.mapping.resolution, 0.1);
  EXPECT_DOUBLE_EQ(options.mapping.max_usable_range, 20.0);
  EXPECT_DOUBLE_EQ(options.mapping.no_return_clear_range, 5.0);
  EXPECT_TRUE(options.reading.use_odometry_without_truth);
  EXPECT_EQ(options.output, "map.pgm");

  command.resolution = 0;
  EXPECT_THROW((void)make_map_options(command), UsageError);
  command.resolution = 0.1;
  command.max_range = std::nan("");
  EXPECT_THROW((void)make_map_options(command), UsageError);
  command.max_range = 20;
  command.no_return_clears = -1;
  EXPECT_THROW((void)make_map_options(command), UsageError);
}

}  // namespace amcl_offline_options_test
