#include "drivers/wavefront/wavefront_driver.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/wavefront/wavefront_planner.hpp"
#include "algorithms/wavefront/waypoint_follower.hpp"
#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver.hpp"
#include "core/source_subscription.hpp"
#include "core/wakeup.hpp"
#include "drivers/wavefront/wavefront_options.hpp"
#include "localization/localize_wire.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/localize.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {

namespace {

using wavefront_driver::WavefrontOptions;

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
constexpr core::ClientId kWavefrontAsClient = core::kFirstDriverClient - 2;
// A new goal differs from the last by more than these (1.5's test).
constexpr double kSameGoalDistance = 0.001;  // m
constexpr double kSameGoalAngle = 0.001;     // rad
// Plans made for one goal before it is given up (the robot keeps straying,
// the local planner keeps getting stuck).
constexpr int kMostPlansPerGoal = 10;

class WavefrontDriver final : public core::ThreadedDriver, private core::DeviceListener {
 public:
  WavefrontDriver(WavefrontOptions options, core::DeviceTable& devices)
      : options_(std::move(options)),
        devices_(devices),
        planner_(*options_.map, options_.planner),
        follower_(options_.follower) {}

  ~WavefrontDriver() override {
    localize_subscription_.reset();
    position_subscription_.reset();
  }

  void check() override {
    (void)local_planner();
    (void)localizer();
  }

  [[nodiscard]] std::vector<core::DeviceKey> source_devices() const override {
    return {key_of(protocol::kPositionCode, options_.position_index),
            key_of(protocol::kLocalizeCode, options_.localize_index)};
  }

  [[nodiscard]] std::vector<core::DriverCounter> counters() const override {
    return {{"goals_reached", reached_.load()}, {"goals_refused", refused_.load()}, {"plans", plans_.load()},
            {"replans", replans_.load()}};
  }

 protected:
  void open() override {
    core::Device& base = local_planner();
    core::Device& localize = localizer();
    {
      std::lock_guard lock(mutex_);
      odometry_.reset();
      localized_.reset();
    }
    base_ = &base;
    goal_.reset();
    pending_goal_.reset();
    last_map_pose_.reset();
    follower_.clear();
    driving_ = false;
    device().set_wakeup(wakeup_);
    // Stopped until a goal comes (1.5 published this at set-up).
    protocol::PositionData stopped;
    stopped.stall = 1;
    device().publish(protocol::encode(stopped), device().clock().now());
    core::SourceSubscription odometry(base, this, device().name());
    core::SourceSubscription poses(localize, this, device().name());
    position_subscription_ = std::move(odometry);
    localize_subscription_ = std::move(poses);
  }

  void close() override {
    position_subscription_.stop_listening();
    localize_subscription_.stop_listening();
    if (driving_) stop_base();
    localize_subscription_.reset();
    position_subscription_.reset();
    device().set_wakeup(nullptr);
  }

  void run(std::stop_token stop) override {
    const std::stop_callback wake_on_stop(stop, [this] { wakeup_->notify(); });
    while (!stop.stop_requested()) {
      wakeup_->wait(core::Wakeup::Clock::now() + std::chrono::seconds(1));
      device().service_requests();  // none are known: each gets its NACK (1.5 never answered)
      take_client_command();
      std::shared_ptr<const core::DataSample> odometry;
      std::shared_ptr<const core::DataSample> localized;
      {
        std::lock_guard lock(mutex_);
        odometry = std::exchange(odometry_, nullptr);
        localized = localized_;
      }
      if (odometry && localized) cycle(*odometry, *localized);
    }
  }

 private:
  core::Device& local_planner() const {
    return core::source_device(devices_, device(), protocol::kPositionCode, options_.position_index, "position_index",
                               "drive");
  }

  core::Device& localizer() const {
    return core::source_device(devices_, device(), protocol::kLocalizeCode, options_.localize_index, "localize_index",
                               "localize with");
  }

  core::DeviceKey key_of(std::uint16_t interface, int index) const {
    return {device().key().port, {interface, static_cast<std::uint16_t>(index)}};
  }

  void data_published(const core::Device& from) override {
    std::shared_ptr<const core::DataSample> sample = from.latest_data();
    if (!sample || sample->payload.empty()) return;
    const bool is_odometry = &from == base_;
    {
      std::lock_guard lock(mutex_);
      (is_odometry ? odometry_ : localized_) = std::move(sample);
    }
    if (is_odometry) wakeup_->notify();
  }
  void replies_ready(const core::Device&) override {}

  void take_client_command() {
    const std::optional<core::Command> command = device().take_command();
    if (!command) return;
    const auto wanted = protocol::decode<protocol::PositionCommand>(command->payload);
    const geometry::Pose2 goal{wanted.xpos / 1000.0, wanted.ypos / 1000.0,
                               geometry::normalize_angle(wanted.yaw / kDegreesPerRadian)};
    // The command buffer is persistent: the same goal again is not a new one.
    if (goal_ && std::hypot(goal.x - goal_->x, goal.y - goal_->y) <= kSameGoalDistance &&
        std::abs(geometry::angle_difference(goal.yaw, goal_->yaw)) <= kSameGoalAngle) {
      return;
    }
    goal_ = goal;
    pending_goal_ = goal;  // planned at the next cycle, from the pose then
    plans_for_goal_ = 0;
  }

  void cycle(const core::DataSample& odometry_sample, const core::DataSample& localize_sample) {
    const auto odometry_data = protocol::decode<protocol::PositionData>(odometry_sample.payload);
    const auto localized = protocol::decode<protocol::LocalizeData>(localize_sample.payload);
    if (localized.hypoth_count == 0) return;
    const geometry::Pose2 odometry = localization::odometry_pose(odometry_data);
    const geometry::Pose2 map_pose = localization::pose_from_wire(localized.hypoths[0].mean);
    // Odometry = transform(map): how to hand a map-frame waypoint down.
    to_odometry_ = odometry.compose(map_pose.inverse());

    if (pending_goal_) {
      plan(map_pose, *std::exchange(pending_goal_, std::nullopt));
    } else if (follower_.active()) {
      const bool jumped = last_map_pose_ && std::hypot(map_pose.x - last_map_pose_->x,
                                                       map_pose.y - last_map_pose_->y) > options_.jump_distance;
      const bool local_planner_stuck = odometry_data.stall != 0 && driving_;
      if (jumped || local_planner_stuck) replan(map_pose, jumped ? "the localization jumped" : "the local planner is stuck");
    }
    last_map_pose_ = map_pose;
    if (follower_.active()) follow(map_pose);

    protocol::PositionData out;
    out.xpos = localized.hypoths[0].mean[0];
    out.ypos = localized.hypoths[0].mean[1];
    out.yaw = static_cast<std::int32_t>(std::lround(std::fmod(map_pose.yaw * kDegreesPerRadian + 360.0, 360.0))) % 360;
    out.xspeed = odometry_data.xspeed;
    out.yspeed = odometry_data.yspeed;
    out.yawspeed = odometry_data.yawspeed;
    out.stall = driving_ ? 0 : 1;
    device().publish(protocol::encode(out), odometry_sample.timestamp);
  }

  void plan(const geometry::Pose2& from, const geometry::Pose2& goal) {
    ++plans_;
    ++plans_for_goal_;
    const wavefront::PlanResult result = planner_.plan({from.x, from.y}, {goal.x, goal.y});
    if (!result.found()) {
      ++refused_;
      char where[64];
      std::snprintf(where, sizeof where, "(%.2f, %.2f)", goal.x, goal.y);
      device().logger().warning(device().name() + ": goal " + where + " refused: " +
                                wavefront::describe_failure(result, planner_.parameters()));
      give_up();
      return;
    }
    follower_.follow(result.waypoints, goal.yaw);
  }

  void replan(const geometry::Pose2& from, const std::string& why) {
    if (plans_for_goal_ >= kMostPlansPerGoal) {
      device().logger().warning(device().name() + ": " + why + " again after " + std::to_string(plans_for_goal_) +
                                " plans; goal given up");
      give_up();
      return;
    }
    ++replans_;
    device().logger().info(device().name() + ": " + why + "; planning again");
    plan(from, *goal_);
  }

  void follow(const geometry::Pose2& map_pose) {
    const wavefront::WaypointFollower::Step step = follower_.step(map_pose);
    switch (step.action) {
      case wavefront::WaypointFollower::Action::idle:
        return;
      case wavefront::WaypointFollower::Action::reached:
        ++reached_;
        give_up();
        return;
      case wavefront::WaypointFollower::Action::replan:
        replan(map_pose, "the robot strayed from the path");
        if (follower_.active()) follow(map_pose);
        return;
      case wavefront::WaypointFollower::Action::drive:
        if (step.new_target || !driving_) send_waypoint(step.target);
        return;
    }
  }

  void send_waypoint(const geometry::Pose2& map_target) {
    const geometry::Pose2 target = to_odometry_.compose(map_target);
    protocol::PositionCommand command;
    command.xpos = static_cast<std::int32_t>(std::lround(target.x * 1000.0));
    command.ypos = static_cast<std::int32_t>(std::lround(target.y * 1000.0));
    command.yaw = static_cast<std::int32_t>(std::lround(target.yaw * kDegreesPerRadian));
    command.state = 1;
    command.type = 1;
    (void)base_->put_command(kWavefrontAsClient, protocol::encode(command));
    driving_ = true;
  }

  // Not driving any more: the robot is told to stop where it is.
  void give_up() {
    follower_.clear();
    if (driving_) stop_base();
    driving_ = false;
  }

  void stop_base() {
    protocol::PositionCommand stop;  // state 0: stop (vfh), motors off (a base)
    (void)base_->put_command(kWavefrontAsClient, protocol::encode(stop));
  }

  const WavefrontOptions options_;
  core::DeviceTable& devices_;
  wavefront::WavefrontPlanner planner_;
  wavefront::WaypointFollower follower_;
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();
  core::Device* base_ = nullptr;
  core::SourceSubscription position_subscription_;
  core::SourceSubscription localize_subscription_;
  std::mutex mutex_;
  std::shared_ptr<const core::DataSample> odometry_;   // newest not used yet
  std::shared_ptr<const core::DataSample> localized_;  // newest
  std::optional<geometry::Pose2> goal_;          // the last goal given
  std::optional<geometry::Pose2> pending_goal_;  // given, not planned yet
  std::optional<geometry::Pose2> last_map_pose_;
  geometry::Pose2 to_odometry_;
  int plans_for_goal_ = 0;
  bool driving_ = false;
  std::atomic<std::uint64_t> reached_ = 0;
  std::atomic<std::uint64_t> refused_ = 0;
  std::atomic<std::uint64_t> plans_ = 0;
  std::atomic<std::uint64_t> replans_ = 0;
};

}  // namespace

core::DriverSpec wavefront_driver_spec() {
  core::DriverSpec spec;
  spec.name = "wavefront";
  spec.interfaces = {protocol::kPositionCode};
  spec.access = protocol::Access::kAll;
  spec.factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    return std::make_unique<WavefrontDriver>(wavefront_driver::read_wavefront_options(context.section),
                                             context.devices);
  };
  spec.summary = "global path planner: goals on a map, handed to a local planner (vfh) as waypoints";
  spec.doc.manual_section = "7.47";
  spec.doc.example =
      "position:2 ( driver \"wavefront\" position_index 1 localize_index 0 map_filename \"cave.png\" map_scale 0.03 )";
  spec.doc.schema = wavefront_driver::wavefront_option_schema();
  return spec;
}

}  // namespace playerkit::drivers
