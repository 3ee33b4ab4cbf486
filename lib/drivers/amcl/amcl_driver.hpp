#pragma once
// `amcl` (manual 7.3): adaptive Monte-Carlo localization served as a
// localize device, fed by a position device (odometry) and a laser device of
// the same server, e.g.
//
//   localize:0 ( driver "amcl" position_index 0 laser_index 0
//                map_file "cave.pnm" map_scale 0.03 map_negate 1 )
//
// While subscribed it holds subscriptions on both sources and listens to
// their data. Each scan is paired with the odometry at its timestamp and
// queued with the odometry-only samples (at most 100 entries, 1.5's queue
// length; when full the oldest odometry-only entry goes, never blocking the
// publisher). The driver's own thread feeds the queue to the filter in
// order and publishes the hypotheses after every scan it processed; while
// scans are still queued, every new odometry sample also gets a prediction
// for "now" (the manual's temporal behaviour). See README.md.

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <stop_token>
#include <vector>

#include "algorithms/amcl/amcl_filter.hpp"
#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "core/source_subscription.hpp"
#include "drivers/amcl/amcl_options.hpp"

namespace playerkit::drivers {

class AmclDriver final : public core::ThreadedDriver, private core::DeviceListener {
 public:
  // Player 1.5's amcl queue length.
  static constexpr std::size_t kQueueCapacity = 100;

  AmclDriver(AmclOptions options, core::DeviceTable& devices);
  ~AmclDriver() override;

  core::RequestResult handle_request(const core::Request& request) override;
  // Its position and laser devices exist (looked up again at set-up).
  void check() override;
  // Its position and laser devices.
  [[nodiscard]] std::vector<core::DeviceKey> source_devices() const override;

 protected:
  void open() override;
  void close() override;
  void run(std::stop_token stop) override;

 private:
  struct OdometrySample {
    geometry::Pose2 pose;
    core::Timestamp time;
  };
  // One step for the filter: odometry, and the scan taken there if any.
  struct Observation {
    geometry::Pose2 odometry;
    core::Timestamp time;
    std::optional<amcl::LaserScan> scan;
  };

  void data_published(const core::Device& source) override;
  void replies_ready(const core::Device&) override {}

  // Under queue_mutex_.
  void add_odometry(const OdometrySample& sample);
  void add_scan(amcl::LaserScan scan, core::Timestamp time);
  void push(Observation observation);
  [[nodiscard]] std::optional<geometry::Pose2> odometry_at(core::Timestamp time) const;
  [[nodiscard]] std::uint16_t queued_scans() const;

  // On the driver's thread.
  void start_filter();
  void process(const Observation& observation, std::uint16_t scans_left);
  void publish_prediction(const OdometrySample& odometry, std::uint16_t scans_left);
  void publish(std::span<const amcl::Hypothesis> hypotheses, std::uint16_t scans_left,
               core::Timestamp timestamp);
  core::RequestResult set_pose(const core::Request& request);
  core::RequestResult set_config(const core::Request& request);
  core::RequestResult map_info() const;
  core::RequestResult map_tile(const core::Request& request) const;

  const AmclOptions options_;
  core::DeviceTable& devices_;
  // The sources, to tell their notifications apart; set before subscribing,
  // since a source may publish from its setup() on.
  core::Device* position_ = nullptr;
  core::Device* laser_ = nullptr;

  // The driver's thread only (requests are answered there too).
  std::unique_ptr<amcl::AmclFilter> filter_;
  amcl::AmclParameters parameters_;  // survives set-ups: SET_CONFIG is sticky
  bool filter_moved_ = false;        // an update ran since the last (re)start
  core::Timestamp last_processed_;

  std::mutex queue_mutex_;  // everything below
  std::condition_variable_any queue_ready_;
  std::deque<Observation> queue_;
  std::deque<OdometrySample> odometry_history_;  // recent samples, for pairing scans
  std::optional<OdometrySample> unpredicted_odometry_;
  std::size_t dropped_scans_ = 0;
  // Callbacks may still arrive after remove_listener(); close() clears this first.
  bool accepting_ = false;

  // Held between open() and close(). Last, so they go first on destruction:
  // no notification can reach members already destroyed.
  core::SourceSubscription position_subscription_;
  core::SourceSubscription laser_subscription_;
};

core::DriverSpec amcl_driver_spec();

}  // namespace playerkit::drivers
