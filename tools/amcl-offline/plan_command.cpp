#include "plan_command.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "map/map_file.hpp"
#include "map/trajectory_plot.hpp"
#include "output_file.hpp"

namespace playerkit::amcl_offline {
namespace {

// Closest approaches are measured up to this far; beyond, "at least".
constexpr double kClearanceReach = 2.0;  // m

std::string point_text(const Eigen::Vector2d& p) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << "(" << p.x() << ", " << p.y() << ")";
  return text.str();
}

double polyline_length(const std::vector<Eigen::Vector2d>& points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

wavefront::PlanResult plan_or_throw(wavefront::WavefrontPlanner& planner, const Eigen::Vector2d& start,
                                    const Eigen::Vector2d& goal) {
  wavefront::PlanResult plan = planner.plan(start, goal);
  if (!plan.found()) {
    std::string message = "no path from " + point_text(start) + " to " + point_text(goal) + ": " +
                          wavefront::describe_failure(plan, planner.parameters());
    const bool clearance_matters = plan.status == wavefront::PlanStatus::unreachable ||
                                   plan.start == wavefront::EndpointState::too_close ||
                                   plan.goal == wavefront::EndpointState::too_close ||
                                   plan.start == wavefront::EndpointState::cornered ||
                                   plan.goal == wavefront::EndpointState::cornered;
    if (clearance_matters) message += " (a smaller --safety or --robot-radius asks for less)";
    throw std::runtime_error(message);
  }
  return plan;
}

void write_point_array(std::ostream& out, const std::vector<Eigen::Vector2d>& points) {
  out << "[";
  for (std::size_t i = 0; i < points.size(); ++i) {
    out << (i ? "," : "") << "[" << points[i].x() << "," << points[i].y() << "]";
  }
  out << "]";
}

// A circle as a closed polyline: how start and goal are marked on the plot
// (the robot with its clearance around it).
std::vector<Eigen::Vector2d> circle(const Eigen::Vector2d& centre, double radius) {
  constexpr int kSides = 24;
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k <= kSides; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / kSides;
    points.push_back(centre + radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  return points;
}

void plot(const std::string& png, const grid::OccupancyGrid& grid, const wavefront::PlanResult& plan,
          const std::vector<Eigen::Vector2d>* driven, double marker_radius) {
  std::vector<map::PlotPath> paths;
  if (driven) paths.push_back({*driven, {230, 120, 0}, "driven"});
  paths.push_back({plan.waypoints, {0, 0, 220}, "planned"});
  paths.push_back({circle(plan.waypoints.front(), marker_radius), {0, 160, 0}, "start"});
  paths.push_back({circle(plan.waypoints.back(), marker_radius), {220, 0, 0}, "goal"});
  map::write_trajectory_plot(png, grid, paths, {}, std::nullopt);
}

}  // namespace

Eigen::Vector2d position_at(const localization::Trajectory& track, double time, const std::string& name) {
  const localization::TimedPose* found = nullptr;
  for (const auto& row : track) {
    if (row.time <= time && (!found || row.time >= found->time)) found = &row;
  }
  if (!found) {
    std::ostringstream message;
    message << name << ": no estimate at or before " << time << " s";
    if (!track.empty()) message << " (the first is at " << std::fixed << std::setprecision(3) << track.front().time << " s)";
    throw std::runtime_error(message.str());
  }
  return found->pose.translation();
}

int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<std::string> inputs{options.map};
  if (options.track) inputs.push_back(*options.track);
  if (options.plot) tools::refuse_output_over_inputs(*options.plot, inputs);
  tools::OutputFile output(options.output, out, inputs);

  const grid::OccupancyGrid grid = map::load_map(options.map, options.map_loading);
  localization::Trajectory track;
  if (options.track) track = localization::read_trajectory_csv(std::filesystem::path(*options.track));

  std::vector<Eigen::Vector2d> driven;
  Eigen::Vector2d start, goal;
  if (options.compare) {
    for (const auto& row : track) driven.push_back(row.pose.translation());
    if (driven.size() < 2) throw std::runtime_error(*options.track + ": fewer than two estimates to compare");
    start = driven.front();
    goal = driven.back();
  } else {
    start = options.start ? *options.start : position_at(track, *options.at, *options.track);
    goal = *options.goal;
  }

  const auto began = std::chrono::steady_clock::now();
  wavefront::WavefrontPlanner planner(grid, options.planner);
  const wavefront::PlanResult plan = plan_or_throw(planner, start, goal);
  const double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
  const auto& clearance = planner.clearance();
  const double planned_clearance = clearance.polyline_clearance(plan.waypoints, kClearanceReach);
  const double required = options.planner.required_clearance();

  std::ostream& data = output.stream();
  data << std::fixed << std::setprecision(4);
  if (options.compare) {
    const double driven_length = polyline_length(driven);
    const double driven_clearance = clearance.polyline_clearance(driven, kClearanceReach);
    const double ratio = driven_length / plan.length_m;
    if (options.format == PlanFormat::json) {
      data << "{\"driven\":{\"length_m\":" << driven_length << ",\"min_clearance_m\":" << driven_clearance
           << ",\"estimates\":" << driven.size() << "},\"planned\":{\"length_m\":" << plan.length_m
           << ",\"min_clearance_m\":" << planned_clearance << ",\"waypoints\":";
      write_point_array(data, plan.waypoints);
      data << "},\"length_ratio\":" << ratio << ",\"required_clearance_m\":" << required
           << ",\"clearance_reach_m\":" << kClearanceReach << "}\n";
    } else {
      data << std::setprecision(3) << std::left << std::setw(9) << "" << std::right << std::setw(10) << "length_m"
           << std::setw(14) << "closest_m" << "\n";
      data << std::left << std::setw(9) << "driven" << std::right << std::setw(10) << driven_length << std::setw(14)
           << driven_clearance << "\n";
      data << std::left << std::setw(9) << "planned" << std::right << std::setw(10) << plan.length_m << std::setw(14)
           << planned_clearance << "\n";
      data << "driven/planned length " << ratio << "; closest approach to an occupied or unknown cell (up to "
           << kClearanceReach << " m), the plan keeping " << required << " m\n";
    }
  } else if (options.format == PlanFormat::json) {
    data << "{\"start\":[" << start.x() << "," << start.y() << "],\"goal\":[" << goal.x() << "," << goal.y()
         << "],\"waypoints\":";
    write_point_array(data, plan.waypoints);
    data << ",\"length_m\":" << plan.length_m << ",\"min_clearance_m\":" << planned_clearance
         << ",\"required_clearance_m\":" << required << ",\"robot_radius_m\":" << options.planner.robot_radius
         << ",\"safety_m\":" << options.planner.safety_distance << "}\n";
  } else {
    data << "x,y\n";
    for (const auto& p : plan.waypoints) data << p.x() << "," << p.y() << "\n";
  }
  output.commit();

  if (options.plot) plot(*options.plot, grid, plan, options.compare ? &driven : nullptr, required);
  err << std::fixed << std::setprecision(2) << "amcl-offline: " << plan.waypoints.size() << " waypoints, "
      << plan.length_m << " m, closest approach " << planned_clearance << " m (keeping " << required
      << " m); " << std::setprecision(1) << milliseconds << " ms on a " << grid.width() << "x" << grid.height()
      << " map\n";
  return kExitOk;
}

}  // namespace playerkit::amcl_offline
