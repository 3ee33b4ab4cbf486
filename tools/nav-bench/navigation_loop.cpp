#include "navigation_loop.hpp"

#include <ctime>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <variant>

#include "algorithms/amcl/amcl_filter.hpp"
#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/vfh/vfh_navigator.hpp"
#include "algorithms/wavefront/wavefront_navigator.hpp"
#include "protocol/interfaces.hpp"
#include "sim/world/world.hpp"
#include "sim/worldfile/world_loader.hpp"

namespace playerkit::nav_bench {

// The models the loop drives and reads.
struct LoopRobot {
  sim::ModelId position = sim::kNoModel;
  sim::ModelId laser = sim::kNoModel;
  geometry::Pose2 laser_mount;  // in the robot's frame
};

namespace {

// The processor time of this thread: what the figures mean to say (the
// cost of a vfh cycle, of a plan), unlike wall time, which other programs
// on the machine stretch.
struct CpuClock {
  using time_point = double;  // ms
  static time_point now() {
    timespec spent{};
    ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &spent);
    return static_cast<double>(spent.tv_sec) * 1e3 + static_cast<double>(spent.tv_nsec) / 1e6;
  }
};
using Clock = CpuClock;

constexpr double kSuccessDistance = 0.30;                     // m, truth from the goal
constexpr double kSuccessAngle = 15.0 * std::numbers::pi / 180.0;
constexpr double kLimitSpeed = 0.3;                           // m/s: the time limit's speed...
constexpr double kLimitSlack = 20.0;                          // s: ...plus this
constexpr double kFlipTurnRate = 0.1;                         // rad/s: a turn that counts as one
constexpr double kLostDistance = 0.5;                         // m: the filter is reset on the truth

double milliseconds_since(Clock::time_point start) { return Clock::now() - start; }

// The first position device whose robot also carries a laser.
LoopRobot find_robot(const sim::worldfile::LoadedWorld& loaded) {
  for (const auto& position : loaded.devices) {
    if (position.interface_code != protocol::kPositionCode) continue;
    for (const auto& laser : loaded.devices) {
      if (laser.interface_code != protocol::kLaserCode) continue;
      if (loaded.world.root_of(laser.model) != loaded.world.root_of(position.model)) continue;
      const auto* spec = std::get_if<sim::LaserSpec>(&loaded.world.spec(laser.model).params);
      if (spec == nullptr) continue;
      // The laser's pose on the robot: its model's place (nested models
      // compose) and the scan origin within the model.
      geometry::Pose2 mount = spec->pose;
      for (sim::ModelId id = laser.model; id != position.model && id != sim::kNoModel;
           id = loaded.world.spec(id).parent) {
        mount = loaded.world.spec(id).pose.compose(mount);
      }
      return {position.model, laser.model, mount};
    }
  }
  throw std::runtime_error("no robot in the world carries a laser (the loop needs a position and a laser on it)");
}

amcl::LaserScan amcl_scan(const sim::LaserScan& scan, const geometry::Pose2& mount, double range_max) {
  amcl::LaserScan out;
  out.ranges = scan.ranges;
  const std::size_t count = scan.ranges.size();
  const double step = count > 1 ? (scan.max_angle - scan.min_angle) / static_cast<double>(count - 1) : 0.0;
  out.bearings.reserve(count);
  for (std::size_t i = 0; i < count; ++i) out.bearings.push_back(scan.min_angle + step * static_cast<double>(i));
  out.max_range = std::min(range_max, scan.range_max);
  out.sensor_pose = mount;
  return out;
}

}  // namespace

struct NavigationLoop::State {
  NavigationSetup setup;
  grid::OccupancyGrid map;
  std::shared_ptr<const grid::OccupancyGrid> shared_map;
  std::unique_ptr<sim::World> world;
  LoopRobot robot;
  std::unique_ptr<amcl::AmclFilter> localizer;
  wavefront::WavefrontNavigator global;
  vfh::VfhNavigator local;
  wavefront::WavefrontPlanner reference;
  double last_scan_time = -1.0;
  std::vector<double> scan_ranges;  // the latest scan vfh steers by
  double scan_first_bearing = 0.0, scan_step = 0.0;
  bool stuck_flag = false;          // vfh's stall flag after "stuck", until its next command
  std::vector<double> clearances;
  std::vector<double> vfh_ms;
  std::function<void(const StepRecord&)> observer;

  State(const NavigationSetup& config, sim::worldfile::WorldDescription description, std::uint64_t seed)
      : setup(config),
        map(description.map),
        shared_map(std::make_shared<grid::OccupancyGrid>(description.map)),
        global(map, config.global_planner, config.waypoints),
        local(config.local_planner),
        reference(map, config.global_planner) {
    sim::worldfile::LoadedWorld loaded = sim::worldfile::make_world(std::move(description));
    robot = find_robot(loaded);
    world = std::make_unique<sim::World>(std::move(loaded.world));
    world->set_active(robot.position, true);
    world->set_active(robot.laser, true);
    localizer = std::make_unique<amcl::AmclFilter>(setup.localizer, shared_map, seed,
                                                   amcl::StartPose{world->true_pose(robot.position),
                                                                   setup.initial_covariance});
  }

  geometry::Pose2 odometry() const { return world->position(robot.position).pose; }

  geometry::Pose2 localized() const { return localizer->predict(odometry()).mean; }

  void relocalize_on_truth() {
    localizer->set_pose(world->true_pose(robot.position), setup.initial_covariance);
  }

  double body_clearance() const {
    const geometry::Pose2 truth = world->true_pose(robot.position);
    const double radius = setup.global_planner.robot_radius;
    return reference.clearance().point_clearance(truth.translation(), radius + 2.0) - radius;
  }
};

NavigationLoop::NavigationLoop(const std::filesystem::path& world_file, const NavigationSetup& setup,
                               std::uint64_t seed)
    : state_(std::make_unique<State>(setup, sim::worldfile::describe_world(world_file, {.seed = seed}), seed)) {}

NavigationLoop::~NavigationLoop() = default;

geometry::Pose2 NavigationLoop::true_pose() const { return state_->world->true_pose(state_->robot.position); }
const grid::OccupancyGrid& NavigationLoop::map() const { return state_->map; }
wavefront::WavefrontPlanner& NavigationLoop::reference_planner() { return state_->reference; }
std::vector<double>& NavigationLoop::clearances() { return state_->clearances; }
void NavigationLoop::set_step_observer(std::function<void(const StepRecord&)> observer) {
  state_->observer = std::move(observer);
}
std::vector<double>& NavigationLoop::vfh_milliseconds() { return state_->vfh_ms; }

GoalOutcome NavigationLoop::drive_to(const geometry::Pose2& goal) {
  State& s = *state_;
  GoalOutcome outcome;
  outcome.start = true_pose();
  outcome.goal = goal;
  const wavefront::PlanResult reference = s.reference.plan(outcome.start.translation(), goal.translation());
  outcome.plan_m = reference.found() ? reference.length_m : 0.0;
  outcome.time_limit_s = 3.0 * outcome.plan_m / kLimitSpeed + kLimitSlack;
  outcome.min_clearance_m = s.body_clearance();

  (void)s.global.set_goal(goal);
  const std::uint64_t reached_before = s.global.goals_reached();
  const std::uint64_t stuck_before = s.local.stuck_events();
  const std::uint64_t replans_before = s.global.replans();
  const double dt = s.world->settings().step;
  const double started = s.world->time();
  geometry::Pose2 previous_truth = outcome.start;
  bool touching = s.world->position(s.robot.position).stalled;
  double last_turn = 0.0;

  while (outcome.ending.empty()) {
    s.world->step();
    const sim::PositionReading& base = s.world->position(s.robot.position);
    const sim::LaserScan& scan = s.world->laser(s.robot.laser);
    if (scan.time > s.last_scan_time && !scan.ranges.empty()) {
      s.last_scan_time = scan.time;
      const amcl::LaserScan seen = amcl_scan(scan, s.robot.laser_mount, s.setup.laser_range_max);
      s.localizer->update(base.pose, &seen);
      s.scan_ranges = scan.ranges;
      s.scan_first_bearing = scan.min_angle;
      s.scan_step = scan.ranges.size() > 1 ? (scan.max_angle - scan.min_angle) / static_cast<double>(scan.ranges.size() - 1) : 0.0;
    }

    // wavefront on the odometry vfh passes up (stall: the base's or vfh's "stuck").
    const Clock::time_point plan_start = Clock::now();
    const std::uint64_t plans_before = s.global.plans();
    const wavefront::BaseOrder order = s.global.cycle(base.pose, s.localized(), base.stalled || s.stuck_flag);
    if (s.global.plans() != plans_before) outcome.replan_ms_max = std::max(outcome.replan_ms_max, milliseconds_since(plan_start));
    if (order.kind == wavefront::BaseOrder::Kind::drive_to) {
      s.local.go_to(order.target);
      s.stuck_flag = false;
    } else if (order.kind == wavefront::BaseOrder::Kind::stop) {
      s.local.stop();
      s.stuck_flag = false;
    }
    for (const wavefront::NavigationEvent& event : s.global.take_events()) {
      if (event.kind == wavefront::NavigationEvent::Kind::refused) outcome.ending = "refused";
      if (event.kind == wavefront::NavigationEvent::Kind::given_up) outcome.ending = "given up";
    }

    // vfh on the same odometry and the latest scan.
    vfh::Motion motion;
    if (!s.scan_ranges.empty()) {
      const Clock::time_point vfh_start = Clock::now();
      motion = s.local.step(base.pose, {s.scan_first_bearing, s.scan_step, s.scan_ranges}, dt, base.stalled);
      s.vfh_ms.push_back(milliseconds_since(vfh_start));
    }
    if (motion.stuck) s.stuck_flag = true;
    s.world->command_velocity(s.robot.position, {motion.speed, 0.0, motion.turn_rate});

    // What the step did.
    const geometry::Pose2 truth = true_pose();
    outcome.path_m += std::hypot(truth.x - previous_truth.x, truth.y - previous_truth.y);
    previous_truth = truth;
    if (base.stalled && !touching) ++outcome.collisions;
    touching = base.stalled;
    const double clearance = s.body_clearance();
    s.clearances.push_back(clearance);
    outcome.min_clearance_m = std::min(outcome.min_clearance_m, clearance);
    if (std::abs(motion.turn_rate) > kFlipTurnRate) {
      if (last_turn != 0.0 && (motion.turn_rate > 0) != (last_turn > 0)) ++outcome.heading_flips;
      last_turn = motion.turn_rate;
    }

    if (s.observer) {
      const std::optional<geometry::Pose2> local_goal = s.local.goal();
      s.observer({s.world->time(), truth, s.localized(), base.pose, motion.speed, motion.turn_rate,
                  local_goal.value_or(geometry::Pose2{}), s.local.goal_active(), base.stalled,
                  vfh::phase_name(s.local.phase())});
    }
    outcome.time_s = s.world->time() - started;
    if (s.global.goals_reached() != reached_before) {
      const bool close = std::hypot(truth.x - goal.x, truth.y - goal.y) <= kSuccessDistance &&
                         std::abs(geometry::angle_difference(truth.yaw, goal.yaw)) <= kSuccessAngle;
      outcome.ending = close ? "reached" : "reached off the goal";
      outcome.success = close;
    } else if (outcome.ending.empty() && outcome.time_s > outcome.time_limit_s) {
      outcome.ending = "timed out";
    }
  }
  // Whatever the ending, the robot stands still before the next goal.
  s.local.stop();
  s.world->command_velocity(s.robot.position, {0.0, 0.0, 0.0});

  const geometry::Pose2 estimate = s.localized();
  const geometry::Pose2 truth = true_pose();
  outcome.localization_error_m = std::hypot(estimate.x - truth.x, estimate.y - truth.y);
  outcome.goal_distance_m = std::hypot(truth.x - goal.x, truth.y - goal.y);
  outcome.goal_angle_deg = geometry::angle_difference(truth.yaw, goal.yaw) * 180.0 / std::numbers::pi;
  if (outcome.localization_error_m > kLostDistance) {
    s.relocalize_on_truth();
    outcome.relocalized = true;
  }
  outcome.stuck_events = static_cast<int>(s.local.stuck_events() - stuck_before);
  outcome.replans = static_cast<int>(s.global.replans() - replans_before);
  return outcome;
}

}  // namespace playerkit::nav_bench
