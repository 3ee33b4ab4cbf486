#include "drivers/wavefront/wavefront_driver.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/wavefront/wavefront_navigator.hpp"
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

wavefront::NavigatorSettings navigator_settings(const WavefrontOptions& options) {
  wavefront::NavigatorSettings settings;
  settings.follower = options.follower;
  settings.jump_distance = options.jump_distance;
  return settings;
}

class WavefrontDriver final : public core::ThreadedDriver, private core::DeviceListener {
 public:
  WavefrontDriver(WavefrontOptions options, core::DeviceTable& devices)
      : options_(std::move(options)),
        devices_(devices),
        navigator_(*options_.map, options_.planner, navigator_settings(options_)) {}

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
    std::lock_guard lock(counters_mutex_);
    return counters_;
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
    navigator_.reset();
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
    if (navigator_.driving()) stop_base();
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
    (void)navigator_.set_goal({wanted.xpos / 1000.0, wanted.ypos / 1000.0,
                               geometry::normalize_angle(wanted.yaw / kDegreesPerRadian)});
  }

  void cycle(const core::DataSample& odometry_sample, const core::DataSample& localize_sample) {
    const auto odometry_data = protocol::decode<protocol::PositionData>(odometry_sample.payload);
    const auto localized = protocol::decode<protocol::LocalizeData>(localize_sample.payload);
    if (localized.hypoth_count == 0) return;
    const geometry::Pose2 odometry = localization::odometry_pose(odometry_data);
    const geometry::Pose2 map_pose = localization::pose_from_wire(localized.hypoths[0].mean);
    const wavefront::BaseOrder order = navigator_.cycle(odometry, map_pose, odometry_data.stall != 0);
    if (order.kind == wavefront::BaseOrder::Kind::drive_to) send_waypoint(order.target);
    if (order.kind == wavefront::BaseOrder::Kind::stop) stop_base();
    log_events();

    protocol::PositionData out;
    out.xpos = localized.hypoths[0].mean[0];
    out.ypos = localized.hypoths[0].mean[1];
    out.yaw = static_cast<std::int32_t>(std::lround(std::fmod(map_pose.yaw * kDegreesPerRadian + 360.0, 360.0))) % 360;
    out.xspeed = odometry_data.xspeed;
    out.yspeed = odometry_data.yspeed;
    out.yawspeed = odometry_data.yawspeed;
    out.stall = navigator_.driving() ? 0 : 1;
    device().publish(protocol::encode(out), odometry_sample.timestamp);
  }

  void log_events() {
    for (const wavefront::NavigationEvent& event : navigator_.take_events()) {
      const std::string line = device().name() + ": " + event.message;
      if (event.kind == wavefront::NavigationEvent::Kind::refused ||
          event.kind == wavefront::NavigationEvent::Kind::given_up) {
        device().logger().warning(line);
      } else {
        device().logger().info(line);
      }
    }
    std::lock_guard lock(counters_mutex_);
    counters_ = {{"goals_reached", navigator_.goals_reached()},
                 {"goals_refused", navigator_.goals_refused()},
                 {"plans", navigator_.plans()},
                 {"replans", navigator_.replans()}};
  }

  // `target` in the odometric frame: the local planner's goal.
  void send_waypoint(const geometry::Pose2& target) {
    protocol::PositionCommand command;
    command.xpos = static_cast<std::int32_t>(std::lround(target.x * 1000.0));
    command.ypos = static_cast<std::int32_t>(std::lround(target.y * 1000.0));
    command.yaw = static_cast<std::int32_t>(std::lround(target.yaw * kDegreesPerRadian));
    command.state = 1;
    command.type = 1;
    (void)base_->put_command(kWavefrontAsClient, protocol::encode(command));
  }

  void stop_base() {
    protocol::PositionCommand stop;  // state 0: stop (vfh), motors off (a base)
    (void)base_->put_command(kWavefrontAsClient, protocol::encode(stop));
  }

  const WavefrontOptions options_;
  core::DeviceTable& devices_;
  wavefront::WavefrontNavigator navigator_;  // its thread only
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();
  core::Device* base_ = nullptr;
  core::SourceSubscription position_subscription_;
  core::SourceSubscription localize_subscription_;
  std::mutex mutex_;
  std::shared_ptr<const core::DataSample> odometry_;   // newest not used yet
  std::shared_ptr<const core::DataSample> localized_;  // newest
  mutable std::mutex counters_mutex_;
  std::vector<core::DriverCounter> counters_{
      {"goals_reached", 0}, {"goals_refused", 0}, {"plans", 0}, {"replans", 0}};
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
