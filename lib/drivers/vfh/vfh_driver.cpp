#include "drivers/vfh/vfh_driver.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/vfh/vfh_navigator.hpp"
#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver.hpp"
#include "core/source_request.hpp"
#include "core/source_subscription.hpp"
#include "core/wakeup.hpp"
#include "drivers/vfh/vfh_options.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {

namespace {

using vfh_driver::VfhOptions;

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
// Who vfh is to the position device it drives (any id: commands only count
// the newest, whoever wrote it).
constexpr core::ClientId kVfhAsClient = core::kFirstDriverClient - 1;
constexpr std::chrono::milliseconds kSourceReplyTimeout{2000};
// Odometry further apart than this is a gap, not a step (the ramp restarts slow).
constexpr double kLongestStep = 0.5;  // s

std::vector<double> scan_metres(const protocol::LaserData& scan) {
  const double millimetres_per_unit = scan.range_res == 0 ? 1.0 : scan.range_res;
  const std::size_t count = std::min<std::size_t>(scan.range_count, scan.ranges.size());
  std::vector<double> ranges(count);
  for (std::size_t i = 0; i < count; ++i) ranges[i] = scan.ranges[i] * millimetres_per_unit / 1000.0;
  return ranges;
}

class VfhDriver final : public core::ThreadedDriver, private core::DeviceListener {
 public:
  VfhDriver(VfhOptions options, core::DeviceTable& devices)
      : options_(std::move(options)), devices_(devices), navigator_(options_.navigator) {}

  ~VfhDriver() override {
    laser_subscription_.reset();
    position_subscription_.reset();
  }

  void check() override {
    (void)driven_base();
    (void)steering_laser();
  }

  [[nodiscard]] std::vector<core::DeviceKey> source_devices() const override {
    return {key_of(protocol::kPositionCode, options_.position_index), key_of(protocol::kLaserCode, options_.laser_index)};
  }

  [[nodiscard]] std::vector<core::DriverCounter> counters() const override {
    return {{"goals_reached", reached_.load()}, {"stuck", stuck_.load()}, {"stalls", stalls_.load()}};
  }

  core::RequestResult handle_request(const core::Request& request) override {
    // The base's geometry and motor power are the base's: ask it.
    if (request.subtype() != protocol::kPositionGetGeomReq && request.subtype() != protocol::kPositionMotorPowerReq) {
      return core::RequestResult::nack();
    }
    const std::optional<core::Reply> reply = core::ask_source(*base_, request.payload, kSourceReplyTimeout);
    if (!reply || reply->type != protocol::MessageType::kAck) return core::RequestResult::nack();
    return core::RequestResult::ack(reply->payload);
  }

 protected:
  void open() override {
    core::Device& base = driven_base();
    core::Device& laser = steering_laser();
    {
      std::lock_guard lock(mutex_);
      odometry_.reset();
      scan_.reset();
    }
    navigator_ = vfh::VfhNavigator(options_.navigator);
    last_odometry_.reset();
    driving_ = false;
    stuck_flag_ = false;
    base_ = &base;
    device().set_wakeup(wakeup_);
    core::SourceSubscription odometry(base, this, device().name());
    core::SourceSubscription scans(laser, this, device().name());
    position_subscription_ = std::move(odometry);
    laser_subscription_ = std::move(scans);
  }

  void close() override {
    position_subscription_.stop_listening();
    laser_subscription_.stop_listening();
    if (driving_) send(0, 0);  // leave the base standing
    laser_subscription_.reset();
    position_subscription_.reset();
    device().set_wakeup(nullptr);
  }

  void run(std::stop_token stop) override {
    const std::stop_callback wake_on_stop(stop, [this] { wakeup_->notify(); });
    while (!stop.stop_requested()) {
      wakeup_->wait(core::Wakeup::Clock::now() + std::chrono::seconds(1));
      device().service_requests();
      take_client_command();
      std::shared_ptr<const core::DataSample> odometry;
      {
        std::lock_guard lock(mutex_);
        odometry = std::exchange(odometry_, nullptr);
      }
      if (odometry) cycle(*odometry);
    }
  }

 private:
  core::Device& driven_base() const {
    return core::source_device(devices_, device(), protocol::kPositionCode, options_.position_index, "position_index",
                               "drive");
  }

  core::Device& steering_laser() const {
    return core::source_device(devices_, device(), protocol::kLaserCode, options_.laser_index, "laser_index",
                               "steer by");
  }

  core::DeviceKey key_of(std::uint16_t interface, int index) const {
    return {device().key().port, {interface, static_cast<std::uint16_t>(index)}};
  }

  // On the sources' threads: keep the newest and wake ours on odometry.
  void data_published(const core::Device& from) override {
    std::shared_ptr<const core::DataSample> sample = from.latest_data();
    if (!sample || sample->payload.empty()) return;
    const bool is_odometry = &from == base_;
    {
      std::lock_guard lock(mutex_);
      (is_odometry ? odometry_ : scan_) = std::move(sample);
    }
    if (is_odometry) wakeup_->notify();
  }
  void replies_ready(const core::Device&) override {}

  void take_client_command() {
    const std::optional<core::Command> command = device().take_command();
    if (!command) return;
    const auto wanted = protocol::decode<protocol::PositionCommand>(command->payload);
    stuck_flag_ = false;
    if (wanted.state == 0) {
      navigator_.stop();
    } else if (wanted.type == 0) {
      navigator_.drive(wanted.xspeed / 1000.0, wanted.yawspeed * kRadiansPerDegree);
    } else {
      navigator_.go_to({wanted.xpos / 1000.0, wanted.ypos / 1000.0, wanted.yaw * kRadiansPerDegree});
    }
  }

  void cycle(const core::DataSample& odometry) {
    const auto data = protocol::decode<protocol::PositionData>(odometry.payload);
    const geometry::Pose2 pose{data.xpos / 1000.0, data.ypos / 1000.0, data.yaw * kRadiansPerDegree};
    double dt = 0.1;
    if (last_odometry_) {
      const double gap = odometry.timestamp.seconds() - last_odometry_->seconds();
      if (gap <= 0) return;  // the same odometry again: nothing new to steer by
      dt = std::min(gap, kLongestStep);
    }
    last_odometry_ = odometry.timestamp;

    std::shared_ptr<const core::DataSample> scan_sample;
    {
      std::lock_guard lock(mutex_);
      scan_sample = scan_;
    }
    vfh::Motion motion;
    if (scan_sample) {
      const auto scan = protocol::decode<protocol::LaserData>(scan_sample->payload);
      const std::vector<double> ranges = scan_metres(scan);
      const vfh::Scan seen{scan.min_angle / 100.0 * kRadiansPerDegree, scan.resolution / 100.0 * kRadiansPerDegree,
                           ranges};
      motion = navigator_.step(pose, seen, dt, data.stall != 0);
    }
    // else: no scan yet, so nothing is known to be clear: stand still.
    if (motion.reached) ++reached_;
    if (motion.stuck) {
      ++stuck_;
      stuck_flag_ = true;
      device().logger().warning(device().name() + ": turned a turn and a half without getting nearer the goal; stopped");
    }
    stalls_ = navigator_.stalls();

    const bool active = navigator_.goal_active() || motion.speed != 0 || motion.turn_rate != 0;
    if (active || driving_) send(motion.speed, motion.turn_rate);
    driving_ = active;

    protocol::PositionData out = data;  // speeds and stall as the base says
    if (stuck_flag_) out.stall = 1;
    device().publish(protocol::encode(out), odometry.timestamp);
  }

  void send(double speed, double turn_rate) {
    protocol::PositionCommand command;
    command.xspeed = static_cast<std::int32_t>(std::lround(speed * 1000.0));
    command.yawspeed = static_cast<std::int32_t>(std::lround(turn_rate / kRadiansPerDegree));
    command.state = 1;  // 1.5 sent 0 and relied on P2OS ignoring it
    command.type = 0;
    (void)base_->put_command(kVfhAsClient, protocol::encode(command));
  }

  const VfhOptions options_;
  core::DeviceTable& devices_;
  vfh::VfhNavigator navigator_;
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();
  core::Device* base_ = nullptr;
  core::SourceSubscription position_subscription_;
  core::SourceSubscription laser_subscription_;
  std::mutex mutex_;
  std::shared_ptr<const core::DataSample> odometry_;  // newest not steered by yet
  std::shared_ptr<const core::DataSample> scan_;      // newest
  std::optional<protocol::Timestamp> last_odometry_;
  bool driving_ = false;     // the last command sent to the base moved it
  bool stuck_flag_ = false;  // until the next client command
  std::atomic<std::uint64_t> reached_ = 0;
  std::atomic<std::uint64_t> stuck_ = 0;
  std::atomic<std::uint64_t> stalls_ = 0;
};

}  // namespace

core::DriverSpec vfh_driver_spec() {
  core::DriverSpec spec;
  spec.name = "vfh";
  spec.interfaces = {protocol::kPositionCode};
  spec.access = protocol::Access::kAll;
  spec.limits.request_queue = 10;
  spec.factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    return std::make_unique<VfhDriver>(vfh_driver::read_vfh_options(context.section), context.devices);
  };
  spec.summary = "Vector Field Histogram local planner: drives a position device to goals around laser obstacles";
  spec.doc.manual_section = "7.45";
  spec.doc.requests = {"GET_GEOM: the driven device's geometry", "MOTOR_POWER: passed to the driven device"};
  spec.doc.example = "position:1 ( driver \"vfh\" position_index 0 laser_index 0 )";
  spec.doc.schema = vfh_driver::vfh_option_schema();
  return spec;
}

}  // namespace playerkit::drivers
