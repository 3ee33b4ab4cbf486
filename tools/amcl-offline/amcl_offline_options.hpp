#pragma once
// What amcl-offline was asked to do, checked: the flags as CLI11 fills them
// (the *Command structs) become the library's option structs, or a
// UsageError naming the flag at fault. Pure, so the rules are unit-tested.
// Filter parameters are checked by amcl::validate alone; the rules here are
// only the command line's own (number syntax, flags that exclude each other).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "algorithms/grid/occupancy_grid_builder.hpp"
#include "exit_status.hpp"
#include "localization/odometry_perturbation.hpp"
#include "localization/estimate_writer.hpp"
#include "localization/map_from_log.hpp"
#include "localization/offline_localizer.hpp"
#include "map/map_file.hpp"

namespace playerkit::amcl_offline {

// 1: unreadable input, cannot write.
using tools::kExitFailure;
using tools::kExitOk;
using tools::kExitUsage;
using tools::UsageError;

struct MapCommand {
  std::string log;
  std::string output;  // .pgm; the .yaml goes beside it
  double resolution = 0.05;
  double max_range = 30.0;
  double no_return_clears = 0.0;  // metres; 0: no-return readings leave the map alone
  bool use_odometry = false;  // logs without truth: trust their odometry
};

struct PerturbCommand {
  std::string log;
  std::string output;  // "-" = stdout
  std::uint64_t seed = 1;
  localization::OdometryErrorModel model;
};

struct LocalizeCommand {
  std::string log;
  std::string map;
  std::optional<double> scale;  // m/pixel for Player images
  bool negate = false;
  std::optional<std::string> origin;  // "X,Y": a map image's bottom-left corner (default: centred)
  std::optional<std::string> init_pose;  // "X,Y,YAW_DEG" or "truth"
  std::optional<std::string> init_var;   // "SX,SY,SYAW_DEG" (standard deviations)
  bool global = false;
  std::optional<std::string> particles;  // "MIN,MAX"
  std::string model = "likelihood";
  std::optional<std::size_t> laser_beams;
  std::optional<double> alpha_slow, alpha_fast;  // augmented MCL (0,0: no random particles)
  std::optional<double> odom_noise_scale;         // multiplies the four motion-noise alphas
  std::optional<std::string> update_thresh;       // "D,A_DEG": update after this much motion
  std::optional<double> sigma_hit;                // laser hit noise (m)
  bool every_reading = false;                     // score readings cut short by what the map lacks too
  std::uint64_t seed = 0;
  std::string format = "csv";
  std::string output = "-";
  std::optional<std::string> plot;
  bool progress = false;  // stderr is a terminal
};

struct MapOptions {
  std::string log;
  std::string output;  // .pgm; the .yaml goes beside it
  grid::OccupancyMappingParameters mapping;
  localization::MapFromLogOptions reading;
};

struct LocalizeOptions {
  std::string log;
  std::string map;
  map::MapLoadOptions map_loading;
  localization::OfflineLocalizationOptions localization;
  localization::EstimateFormat format = localization::EstimateFormat::csv;
  std::string output = "-";
  std::optional<std::string> plot;
  bool progress = false;
};

// Throw UsageError.
MapOptions make_map_options(const MapCommand& command);
LocalizeOptions make_localize_options(const LocalizeCommand& command);

}  // namespace playerkit::amcl_offline
