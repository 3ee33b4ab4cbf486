#include "amcl_offline_options.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "algorithms/amcl/amcl_parameters.hpp"

namespace playerkit::amcl_offline {
namespace {


std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    double value = 0;
    const char* first = item.data();
    const char* last = item.data() + item.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || !std::isfinite(value)) {
      throw UsageError(what + ": '" + item + "' is not a number");
    }
    values.push_back(value);
  }
  if (values.size() != count) {
    throw UsageError(what + ": expected " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
  }
  return values;
}

bool is_count(double value) { return value >= 0 && value == std::floor(value); }

amcl::LaserModelType parse_model(const std::string& text) {
  if (text == "likelihood" || text == "likelihood_field") return amcl::LaserModelType::likelihood_field;
  if (text == "beam") return amcl::LaserModelType::beam;
  throw UsageError("--model: '" + text + "' is not beam or likelihood");
}

localization::EstimateFormat parse_format(const std::string& text) {
  if (text == "csv") return localization::EstimateFormat::csv;
  if (text == "json") return localization::EstimateFormat::json;
  if (text == "log") return localization::EstimateFormat::player_log;
  throw UsageError("--format: '" + text + "' is not csv, json or log");
}

// amcl::validate names parameters; the user knows flags. Which flag sets
// which parameter, by the words of validate's messages.
std::string flags_for(std::string_view message) {
  struct Mention {
    std::string_view words;
    std::string_view flags;
  };
  constexpr std::array<Mention, 6> kMentions{{
      {"particles", "--particles"},
      {"alpha_", "--alpha-slow/--alpha-fast"},
      {"motion noise", "--odom-noise"},
      {"laser_max_beams", "--laser-beams"},
      {"sigma_hit", "--sigma-hit"},
      {"update thresholds", "--update-thresh"},
  }};
  for (const auto& mention : kMentions) {
    if (message.find(mention.words) != std::string_view::npos) return std::string(mention.flags);
  }
  return "filter options";
}

void check_filter(const amcl::AmclParameters& filter) {
  try {
    amcl::validate(filter);
  } catch (const std::invalid_argument& e) {
    throw UsageError(flags_for(e.what()) + ": " + e.what());
  }
}

void apply_filter_flags(const LocalizeCommand& command, amcl::AmclParameters& filter) {
  filter.laser_model = parse_model(command.model);
  if (command.laser_beams) filter.laser_max_beams = *command.laser_beams;
  if (command.particles) {
    const auto bounds = parse_numbers(*command.particles, 2, "--particles");
    if (!is_count(bounds[0]) || !is_count(bounds[1])) throw UsageError("--particles: MIN,MAX, whole numbers");
    filter.min_particles = static_cast<std::size_t>(bounds[0]);
    filter.max_particles = static_cast<std::size_t>(bounds[1]);
  }
  if (command.alpha_slow) filter.alpha_slow = *command.alpha_slow;
  if (command.alpha_fast) filter.alpha_fast = *command.alpha_fast;
  if (command.odom_noise_scale) {
    // A scale of 0 would be a valid (noiseless) filter but never what was meant.
    if (!(*command.odom_noise_scale > 0)) throw UsageError("--odom-noise must be > 0");
    const double scale = *command.odom_noise_scale;
    filter.rotation_noise_from_rotation *= scale;
    filter.rotation_noise_from_translation *= scale;
    filter.translation_noise_from_translation *= scale;
    filter.translation_noise_from_rotation *= scale;
    filter.strafe_noise_from_translation *= scale;
  }
  if (command.update_thresh) {
    const auto thresholds = parse_numbers(*command.update_thresh, 2, "--update-thresh");
    filter.update_min_distance = thresholds[0];
    filter.update_min_angle = thresholds[1] * geometry::kRadiansPerDegree;
  }
  if (command.sigma_hit) filter.sigma_hit = *command.sigma_hit;
  if (command.every_reading) filter.short_reading_filter = false;
  check_filter(filter);
}

localization::InitialBelief initial_belief(const LocalizeCommand& command) {
  localization::InitialBelief initial;
  if (command.global && command.init_pose) throw UsageError("--global and --init-pose exclude each other");
  if (command.init_var) {
    const auto sigma = parse_numbers(*command.init_var, 3, "--init-var");
    if (sigma[0] <= 0 || sigma[1] <= 0 || sigma[2] <= 0) throw UsageError("--init-var: every deviation must be > 0");
    initial.sigma_x_m = sigma[0];
    initial.sigma_y_m = sigma[1];
    initial.sigma_yaw_rad = sigma[2] * geometry::kRadiansPerDegree;
  }
  if (command.global) {
    initial.kind = localization::InitialBelief::Kind::global;
  } else if (!command.init_pose) {
    throw UsageError("say where the robot starts: --init-pose X,Y,YAW_DEG, --init-pose truth, or --global");
  } else if (*command.init_pose == "truth") {
    initial.kind = localization::InitialBelief::Kind::first_truth;
  } else {
    const auto pose = parse_numbers(*command.init_pose, 3, "--init-pose");
    initial.kind = localization::InitialBelief::Kind::pose;
    initial.pose = {pose[0], pose[1], geometry::normalize_angle(pose[2] * geometry::kRadiansPerDegree)};
  }
  return initial;
}

}  // namespace

MapOptions make_map_options(const MapCommand& command) {
  if (!(command.resolution > 0)) throw UsageError("--resolution must be > 0");
  if (!(command.max_range > 0)) throw UsageError("--max-range must be > 0");
  if (!(command.no_return_clears >= 0)) throw UsageError("--no-return-clears must be >= 0");
  MapOptions options;
  options.log = command.log;
  options.output = command.output;
  options.mapping.resolution = command.resolution;
  options.mapping.max_usable_range = command.max_range;
  options.mapping.no_return_clear_range = command.no_return_clears;
  options.reading.use_odometry_without_truth = command.use_odometry;
  return options;
}

LocalizeOptions make_localize_options(const LocalizeCommand& command) {
  LocalizeOptions options;
  options.log = command.log;
  options.map = command.map;
  options.localization.seed = command.seed;
  apply_filter_flags(command, options.localization.filter);
  options.localization.initial = initial_belief(command);
  options.format = parse_format(command.format);
  options.map_loading.resolution = command.scale;
  options.map_loading.negate = command.negate;
  if (command.origin) {
    const auto corner = parse_numbers(*command.origin, 2, "--origin");
    options.map_loading.origin = Eigen::Vector2d(corner[0], corner[1]);
  }
  options.output = command.output;
  options.plot = command.plot;
  options.progress = command.progress;
  return options;
}

}  // namespace playerkit::amcl_offline
