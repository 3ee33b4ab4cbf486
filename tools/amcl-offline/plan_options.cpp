#include "plan_options.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>

namespace playerkit::amcl_offline {
namespace {

double parse_coordinate(std::string_view text, const std::string& flag, const std::string& whole) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    throw UsageError(flag + ": '" + whole + "' is not X,Y (two numbers in metres)");
  }
  return value;
}

Eigen::Vector2d parse_point(const std::string& text, const std::string& flag) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw UsageError(flag + ": '" + text + "' is not X,Y (two numbers in metres)");
  }
  const std::string_view all(text);
  return {parse_coordinate(all.substr(0, comma), flag, text), parse_coordinate(all.substr(comma + 1), flag, text)};
}

PlanFormat parse_format(const std::optional<std::string>& text, bool compare) {
  if (!text) return compare ? PlanFormat::text : PlanFormat::csv;
  if (*text == "json") return PlanFormat::json;
  if (!compare && *text == "csv") return PlanFormat::csv;
  if (compare && *text == "text") return PlanFormat::text;
  throw UsageError("--format: '" + *text + "' is not " + (compare ? "text or json (with --compare)" : "csv or json"));
}

}  // namespace

const char* const kPlanHelpFooter = R"(The path keeps robot radius + safety (default 0.30 m) from every occupied
and unknown cell and from the map's edge, all along its segments; among such
paths it is the shortest, with 1.5 wavefront's penalty for passing within a
further 0.15 m of them. A door must be at least 2 x (radius + safety) wide.

Examples:
  amcl-offline plan --map intel.yaml --start 0,0 --goal 12.5,-3 --plot plan.png
  amcl-offline plan --map intel.yaml --track est.csv --at 120 --goal 12.5,-3 --format json
  amcl-offline plan --map intel.yaml --track est.csv --compare --plot compare.png

Output: csv "x,y" and one row per waypoint, the start first and the goal last;
json {"start","goal","waypoints":[[x,y],...],"length_m","min_clearance_m",...}.
--compare: the driven path (the track's estimates) and the plan between its
first and last estimates: lengths, their ratio, the closest approach of each
to an occupied or unknown cell (measured up to 2 m). A summary goes to stderr.

Exit status: 0 done; 1 no path (start or goal outside the map, in an occupied
or unknown cell or nearer one than radius + safety, or no way between them:
the message says which) or another runtime error (unreadable map or track, no
estimate at or before --at, cannot write); 2 usage error.)";

PlanOptions make_plan_options(const PlanCommand& command) {
  PlanOptions options;
  options.map = command.map;
  if (command.scale && !(*command.scale > 0)) throw UsageError("--scale must be > 0");
  options.map_loading.resolution = command.scale;
  options.map_loading.negate = command.negate;
  if (command.origin) options.map_loading.origin = parse_point(*command.origin, "--origin");
  options.compare = command.compare;
  options.track = command.track;
  options.at = command.at;

  if (command.compare) {
    if (!command.track) throw UsageError("--compare needs --track TRACK.csv (the path driven)");
    if (command.start || command.goal || command.at) {
      throw UsageError("--compare plans between the track's first and last estimates: no --start, --goal or --at");
    }
  } else {
    if (!command.goal) throw UsageError("say where to go: --goal X,Y");
    options.goal = parse_point(*command.goal, "--goal");
    if (command.start && (command.track || command.at)) {
      throw UsageError("--start and --track/--at exclude each other");
    }
    if (command.at && !command.track) throw UsageError("--at needs --track TRACK.csv");
    if (command.track && !command.at) throw UsageError("--track needs --at T (the start) or --compare");
    if (!command.start && !command.track) throw UsageError("say where to start: --start X,Y or --track TRACK.csv --at T");
    if (command.start) options.start = parse_point(*command.start, "--start");
  }

  options.planner.robot_radius = command.robot_radius;
  options.planner.safety_distance = command.safety;
  if (!(command.robot_radius > 0) || !std::isfinite(command.robot_radius)) {
    throw UsageError("--robot-radius must be > 0");
  }
  if (!(command.safety >= 0) || !std::isfinite(command.safety)) throw UsageError("--safety must be >= 0");
  wavefront::validate(options.planner);

  options.format = parse_format(command.format, command.compare);
  options.output = command.output;
  options.plot = command.plot;
  return options;
}

}  // namespace playerkit::amcl_offline
