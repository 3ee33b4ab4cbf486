#pragma once
// What `amcl-offline plan` was asked to do, checked: the flags as CLI11
// fills them (PlanCommand) become PlanOptions, or a UsageError naming the
// flag at fault. Pure, so the rules are unit-tested (plan_options_test.cpp).

#include <Eigen/Core>

#include <optional>
#include <string>

#include "algorithms/wavefront/wavefront_planner.hpp"
#include "exit_status.hpp"
#include "map/map_file.hpp"

namespace playerkit::amcl_offline {

using tools::kExitFailure;
using tools::kExitOk;
using tools::kExitUsage;
using tools::UsageError;

struct PlanCommand {
  std::string map;
  std::optional<double> scale;  // m/pixel for Player images
  bool negate = false;
  std::optional<std::string> origin;  // "X,Y": a map image's bottom-left corner (default: centred)
  std::optional<std::string> start;  // "X,Y"
  std::optional<std::string> goal;   // "X,Y"
  std::optional<std::string> track;  // a localize CSV (time,x,y,yaw,...)
  std::optional<double> at;          // s: the track's estimate at or before this time is the start
  bool compare = false;              // the track's path against a plan between its ends
  double robot_radius = 0.15;
  double safety = 0.15;
  std::optional<std::string> format;  // plan: csv (default) or json; --compare: text (default) or json
  std::string output = "-";
  std::optional<std::string> plot;
};

enum class PlanFormat { csv, json, text };

struct PlanOptions {
  std::string map;
  map::MapLoadOptions map_loading;
  bool compare = false;
  std::optional<Eigen::Vector2d> start;  // else from the track at `at`
  std::optional<Eigen::Vector2d> goal;   // not with --compare
  std::optional<std::string> track;
  std::optional<double> at;
  wavefront::PlannerParameters planner;
  PlanFormat format = PlanFormat::csv;
  std::string output = "-";
  std::optional<std::string> plot;
};

// Throws UsageError.
PlanOptions make_plan_options(const PlanCommand& command);

// The end of `amcl-offline plan --help`: examples, output, exit statuses.
extern const char* const kPlanHelpFooter;

}  // namespace playerkit::amcl_offline
