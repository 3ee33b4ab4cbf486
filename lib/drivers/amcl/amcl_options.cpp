#include "drivers/amcl/amcl_options.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>

#include "config/errors.hpp"
#include "map/map_file.hpp"
#include "map/map_file_error.hpp"

namespace playerkit::drivers {

namespace {

// Player 1.5's defaults where the manual gives them.
constexpr double kDefaultMapScale = 0.05;  // m/pixel
// Initial spread when init_pose is given without init_pose_var (standard
// deviations): the manual's default is unreadable in the PDF, and 1.5's code
// amounts to "anywhere", which would make init_pose alone pointless.
constexpr double kDefaultInitialStdDev = 0.5;                           // m
constexpr double kDefaultInitialYawStdDev = 30.0 * std::numbers::pi / 180.0;  // rad

config::SourceLocation location_of(const config::Section& section, std::string_view name,
                                   std::size_t element = 0) {
  const config::Property* property = section.property(name);
  if (property == nullptr) return section.where();
  if (element < property->values.size()) return property->values[element].where;
  return property->where;
}

[[noreturn]] void fail(const config::Section& section, std::string_view name, const std::string& message,
                       std::size_t element = 0) {
  throw config::ConfigError(location_of(section, name, element),
                            std::string("amcl: ") + std::string(name) + " " + message);
}

// The first of `names` that is present (primary name first, then aliases).
std::string_view present_name(const config::Section& section, std::initializer_list<std::string_view> names) {
  for (std::string_view name : names) {
    if (section.has(name)) return name;
  }
  return *names.begin();
}

int read_index(const config::Section& section, std::initializer_list<std::string_view> names, int fallback) {
  const std::string_view name = present_name(section, names);
  const int value = section.read_int(name, fallback);
  if (value < 0) fail(section, name, "must be a device index (0 or more), got " + std::to_string(value));
  return value;
}

std::size_t read_count(const config::Section& section, std::string_view name, std::size_t fallback,
                       int minimum) {
  if (!section.has(name)) return fallback;
  const int value = section.read_int(name, static_cast<int>(fallback));
  if (value < minimum) {
    fail(section, name, "must be at least " + std::to_string(minimum) + ", got " + std::to_string(value));
  }
  return static_cast<std::size_t>(value);
}

double read_number(const config::Section& section, std::string_view name, double fallback, double minimum,
                   bool minimum_allowed) {
  const double value = section.read_float(name, fallback);
  const bool ok = std::isfinite(value) && (minimum_allowed ? value >= minimum : value > minimum);
  if (!ok) {
    fail(section, name,
         std::string(minimum_allowed ? "must be at least " : "must be greater than ") + std::to_string(minimum) +
             ", got " + std::to_string(value));
  }
  return value;
}

double nonnegative(const config::Section& section, std::string_view name, double fallback) {
  return read_number(section, name, fallback, 0.0, true);
}

double positive(const config::Section& section, std::string_view name, double fallback) {
  return read_number(section, name, fallback, 0.0, false);
}

std::shared_ptr<const grid::OccupancyGrid> load_map_option(const config::Section& section) {
  const std::string_view name = present_name(section, {"map_file", "laser_map"});
  if (!section.has(name)) {
    throw config::ConfigError(section.where(), "amcl: no map: give map_file \"map.pgm\" (and map_scale)");
  }
  const std::string file = section.read_filename(name, "");
  map::MapLoadOptions load;
  load.resolution = section.read_length("map_scale", kDefaultMapScale);
  if (!(*load.resolution > 0.0)) fail(section, "map_scale", "must be greater than 0");
  load.negate = section.read_int("map_negate", 0) != 0;
  // playerkit's addition: 1.5 centred every map on the world origin, which
  // puts the estimate of a Stage 1.3 robot (its world starts at the bitmap's
  // bottom-left corner) half a map away from its true pose.
  if (section.has("map_origin")) {
    if (section.tuple_size("map_origin") != 2) {
      fail(section, "map_origin", "must be [x y]: where the image's bottom-left corner lies");
    }
    load.origin = Eigen::Vector2d(section.read_tuple_length("map_origin", 0, 0.0),
                                  section.read_tuple_length("map_origin", 1, 0.0));
  }
  try {
    auto grid = std::make_shared<grid::OccupancyGrid>(map::load_map(file, load));
    const auto cells = grid->cells();
    if (std::none_of(cells.begin(), cells.end(), [](grid::CellState s) { return s == grid::CellState::free; })) {
      fail(section, name, "has no free cells (wrong map_negate?)");
    }
    return grid;
  } catch (const map::MapFileError& e) {
    throw config::ConfigError(location_of(section, name), std::string("amcl: cannot load the map: ") + e.what());
  }
}

amcl::LaserModelType read_laser_model(const config::Section& section) {
  const std::string model = section.read_string("laser_model", "likelihood_field");
  if (model == "likelihood_field") return amcl::LaserModelType::likelihood_field;
  if (model == "beam") return amcl::LaserModelType::beam;
  fail(section, "laser_model", "must be \"beam\" or \"likelihood_field\", got \"" + model + "\"");
}

void read_filter_parameters(const config::Section& section, amcl::AmclParameters& p) {
  p.min_particles = read_count(section, "pf_min_samples", p.min_particles, 1);
  p.max_particles = read_count(section, "pf_max_samples", p.max_particles, 1);
  if (p.max_particles < p.min_particles) {
    fail(section, "pf_max_samples", "must not be below pf_min_samples (" + std::to_string(p.min_particles) + ")");
  }
  p.kld_error = positive(section, "pf_err", p.kld_error);
  p.kld_z = positive(section, "pf_z", p.kld_z);
  p.alpha_slow = nonnegative(section, "alpha_slow", p.alpha_slow);
  p.alpha_fast = nonnegative(section, "alpha_fast", p.alpha_fast);

  p.rotation_noise_from_rotation = nonnegative(section, "odom_alpha1", p.rotation_noise_from_rotation);
  p.rotation_noise_from_translation = nonnegative(section, "odom_alpha2", p.rotation_noise_from_translation);
  p.translation_noise_from_translation =
      nonnegative(section, "odom_alpha3", p.translation_noise_from_translation);
  p.translation_noise_from_rotation = nonnegative(section, "odom_alpha4", p.translation_noise_from_rotation);
  p.strafe_noise_from_translation = nonnegative(section, "odom_alpha5", p.strafe_noise_from_translation);

  p.laser_model = read_laser_model(section);
  p.laser_max_beams = read_count(section, present_name(section, {"laser_max_samples", "laser_max_beams"}),
                                 p.laser_max_beams, 1);
  p.z_hit = nonnegative(section, "laser_z_hit", p.z_hit);
  p.z_rand = nonnegative(section, "laser_z_rand", p.z_rand);
  p.sigma_hit = positive(section, "laser_sigma_hit", p.sigma_hit);

  if (section.has("update_thresh")) {
    p.update_min_distance = section.read_tuple_length("update_thresh", 0, p.update_min_distance);
    p.update_min_angle = section.read_tuple_angle("update_thresh", 1, p.update_min_angle);
    if (!(p.update_min_distance >= 0.0)) fail(section, "update_thresh", "distance must not be negative", 0);
    if (!(p.update_min_angle >= 0.0)) fail(section, "update_thresh", "angle must not be negative", 1);
  }
  p.resample_interval = read_count(section, "resample_interval", p.resample_interval, 1);
  p.selective_resampling = section.read_int("selective_resampling", p.selective_resampling ? 1 : 0) != 0;
  p.short_reading_filter = section.read_int("short_reading_filter", p.short_reading_filter ? 1 : 0) != 0;

  try {
    amcl::validate(p);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(section.where(), std::string("amcl: ") + e.what());
  }
}

geometry::Pose2 read_pose(const config::Section& section, std::string_view name) {
  return {section.read_tuple_length(name, 0, 0.0), section.read_tuple_length(name, 1, 0.0),
          geometry::normalize_angle(section.read_tuple_angle(name, 2, 0.0))};
}

std::optional<amcl::StartPose> read_initial_pose(const config::Section& section, const grid::OccupancyGrid& map) {
  const bool global = section.read_int("init_pose_global", 0) != 0;
  const bool has_pose = section.has("init_pose");
  const bool has_spread = section.has("init_pose_var");
  amcl::StartPose initial;
  initial.mean = read_pose(section, "init_pose");
  // Standard deviations (m, m, angle), as 1.5 read them despite the name.
  const double sx = section.read_tuple_length("init_pose_var", 0, kDefaultInitialStdDev);
  const double sy = section.read_tuple_length("init_pose_var", 1, kDefaultInitialStdDev);
  const double sa = section.read_tuple_angle("init_pose_var", 2, kDefaultInitialYawStdDev);
  for (const auto& [value, element] : {std::pair{sx, 0}, std::pair{sy, 1}, std::pair{sa, 2}}) {
    if (!(value >= 0.0) || !std::isfinite(value)) {
      fail(section, "init_pose_var", "must hold non-negative standard deviations",
           static_cast<std::size_t>(element));
    }
  }
  if (global || (!has_pose && !has_spread)) return std::nullopt;
  // A spread wider than the map is 1.5's way of saying "anywhere".
  const double width = map.width() * map.resolution();
  const double height = map.height() * map.resolution();
  if (sx >= width || sy >= height) return std::nullopt;
  initial.covariance = Eigen::Vector3d(sx * sx, sy * sy, sa * sa).asDiagonal();
  return initial;
}

}  // namespace

AmclOptions read_amcl_options(const config::Section& section) {
  AmclOptions options;
  options.position_index = read_index(section, {"position_index", "odom_index"}, 0);
  options.laser_index = read_index(section, {"laser_index"}, 0);
  if (section.read_int("sonar_index", -1) >= 0 || section.read_int("wifi_index", -1) >= 0) {
    fail(section, section.has("sonar_index") ? "sonar_index" : "wifi_index",
         "is not supported: this amcl uses odometry and a laser only");
  }
  options.map = load_map_option(section);
  (void)section.read_length("robot_radius", 0.2);  // accepted; the free-space check uses map cells
  (void)section.read_int("enable_gui", 0);          // accepted; there is no built-in GUI
  read_filter_parameters(section, options.parameters);
  options.laser_pose = read_pose(section, "laser_pose");
  options.laser_range_max = positive(section, "laser_range_max", options.laser_range_max);
  options.initial_pose = read_initial_pose(section, *options.map);
  const int seed = section.read_int("seed", 0);
  if (seed < 0) fail(section, "seed", "must not be negative");
  options.seed = static_cast<std::uint64_t>(seed);
  return options;
}

}  // namespace playerkit::drivers
