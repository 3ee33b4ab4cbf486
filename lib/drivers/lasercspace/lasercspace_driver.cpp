#include "drivers/lasercspace/lasercspace_driver.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <utility>
#include <string>
#include <vector>

#include "algorithms/cspace/free_ranges.hpp"
#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver.hpp"
#include "core/source_request.hpp"
#include "core/source_subscription.hpp"
#include "core/wakeup.hpp"
#include "drivers/lasercspace/lasercspace_options.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers {

namespace {

using lasercspace::LaserCspaceOptions;

constexpr double kRadiansPerHundredthDegree = 3.14159265358979323846 / 18000.0;
// How long a GET_GEOM waits for the source laser's answer.
constexpr std::chrono::milliseconds kSourceReplyTimeout{2000};

// The input's ranges in metres: range_res scales them (1.5 ignored it, and
// read a laser with range_res 10 ten times too near).
std::vector<double> metres(const protocol::LaserData& scan) {
  const double millimetres_per_unit = scan.range_res == 0 ? 1.0 : scan.range_res;
  const std::size_t count = std::min<std::size_t>(scan.range_count, scan.ranges.size());
  std::vector<double> ranges(count);
  for (std::size_t i = 0; i < count; ++i) ranges[i] = scan.ranges[i] * millimetres_per_unit / 1000.0;
  return ranges;
}

protocol::LaserData free_space_scan(const protocol::LaserData& scan, const LaserCspaceOptions& options) {
  const cspace::ScanGeometry geometry{scan.min_angle * kRadiansPerHundredthDegree,
                                      scan.resolution * kRadiansPerHundredthDegree};
  const std::vector<double> free = cspace::free_ranges(metres(scan), geometry, options.radius, options.obstacle_stride);
  protocol::LaserData out;
  out.min_angle = scan.min_angle;
  out.max_angle = scan.max_angle;
  out.resolution = scan.resolution;
  out.range_res = 1;  // millimetres; 1.5 sent 0, which libplayerc multiplies every range by
  out.range_count = static_cast<std::uint16_t>(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) {
    out.ranges[i] = static_cast<std::uint16_t>(std::min(std::floor(free[i] * 1000.0), 65535.0));  // truncated, as 1.5
  }
  return out;
}

class LaserCspaceDriver final : public core::ThreadedDriver, private core::DeviceListener {
 public:
  LaserCspaceDriver(LaserCspaceOptions options, core::DeviceTable& devices)
      : options_(options), devices_(devices) {}

  ~LaserCspaceDriver() override { source_.reset(); }

  void check() override { (void)source_device(); }

  [[nodiscard]] std::vector<core::DeviceKey> source_devices() const override {
    return {{device().key().port, {protocol::kLaserCode, static_cast<std::uint16_t>(options_.laser_index)}}};
  }

  [[nodiscard]] std::vector<core::DriverCounter> counters() const override {
    return {{"scans_converted", converted_.load()}, {"scans_repeated", repeated_.load()}};
  }

  core::RequestResult handle_request(const core::Request& request) override {
    if (request.subtype() != protocol::kLaserGetGeom) return core::RequestResult::nack();
    // The geometry is the source laser's: ask it.
    const std::optional<core::Reply> reply =
        core::ask_source(*source_.device(), request.payload, kSourceReplyTimeout);
    if (!reply || reply->type != protocol::MessageType::kAck ||
        reply->payload.size() != protocol::LaserGeom::kWireSize) {
      return core::RequestResult::nack();
    }
    return core::RequestResult::ack(reply->payload);
  }

 protected:
  void open() override {
    core::Device& laser = source_device();
    {
      std::lock_guard lock(mutex_);
      pending_.reset();
      last_used_.reset();
    }
    device().set_wakeup(wakeup_);
    source_ = core::SourceSubscription(laser, this, device().name());
  }

  void close() override {
    source_.reset();
    device().set_wakeup(nullptr);
  }

  void run(std::stop_token stop) override {
    const std::stop_callback wake_on_stop(stop, [this] { wakeup_->notify(); });
    while (!stop.stop_requested()) {
      wakeup_->wait(core::Wakeup::Clock::now() + std::chrono::seconds(1));
      device().service_requests();
      std::shared_ptr<const core::DataSample> sample;
      {
        std::lock_guard lock(mutex_);
        sample = std::exchange(pending_, nullptr);
      }
      if (sample) convert(*sample);
    }
  }

 private:
  core::Device& source_device() const {
    return core::source_device(devices_, device(), protocol::kLaserCode, options_.laser_index, "laser", "read");
  }

  // On the source's thread: hand the scan over and wake ours.
  void data_published(const core::Device& source) override {
    std::shared_ptr<const core::DataSample> sample = source.latest_data();
    if (!sample || sample->payload.empty()) return;
    {
      std::lock_guard lock(mutex_);
      pending_ = std::move(sample);
    }
    wakeup_->notify();
  }
  void replies_ready(const core::Device&) override {}

  void convert(const core::DataSample& sample) {
    // 1.5 recomputed only for a scan with a new timestamp; a source that
    // publishes the same scan again gets no second copy.
    if (last_used_ && *last_used_ == sample.timestamp) {
      ++repeated_;
      return;
    }
    try {
      const auto scan = protocol::decode<protocol::LaserData>(sample.payload);
      device().publish(protocol::encode(free_space_scan(scan, options_)), sample.timestamp);
      last_used_ = sample.timestamp;
      ++converted_;
    } catch (const std::exception& e) {
      if (!warned_) device().logger().warning(device().name() + ": a scan it could not read: " + e.what());
      warned_ = true;
    }
  }

  const LaserCspaceOptions options_;
  core::DeviceTable& devices_;
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();
  core::SourceSubscription source_;
  std::mutex mutex_;
  std::shared_ptr<const core::DataSample> pending_;  // the newest scan not converted yet
  std::optional<protocol::Timestamp> last_used_;
  bool warned_ = false;
  std::atomic<std::uint64_t> converted_ = 0;
  std::atomic<std::uint64_t> repeated_ = 0;
};

}  // namespace

core::DriverSpec lasercspace_driver_spec() {
  core::DriverSpec spec;
  spec.name = "lasercspace";
  spec.interfaces = {protocol::kLaserCode};
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    return std::make_unique<LaserCspaceDriver>(lasercspace::read_lasercspace_options(context.section),
                                               context.devices);
  };
  spec.summary = "another laser's scan as the free configuration space of a round robot";
  spec.doc.manual_section = "7.22";
  spec.doc.requests = {"GET_GEOM: the source laser's geometry"};
  spec.doc.example = "laser:1 ( driver \"lasercspace\" laser 0 radius 0.3 )";
  spec.doc.schema = lasercspace::lasercspace_option_schema();
  return spec;
}

}  // namespace playerkit::drivers
