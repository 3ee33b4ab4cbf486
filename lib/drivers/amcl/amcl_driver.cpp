#include "drivers/amcl/amcl_driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <utility>

#include "localization/localize_wire.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using localization::covariance_from_wire;
using localization::laser_scan;
using localization::localize_data;
using localization::odometry_pose;
using localization::pose_from_wire;

// How long the idle thread waits for data before answering requests again.
constexpr std::chrono::milliseconds kIdleWait{10};
// Odometry kept for pairing scans that arrive later than newer odometry.
constexpr std::size_t kOdometryHistory = 32;
constexpr std::size_t kMaxTileCells = 4079;  // player_localize_map_data_t's data array
constexpr std::size_t kTileHeaderSize = 17;

double seconds_between(core::Timestamp from, core::Timestamp to) { return to.seconds() - from.seconds(); }

geometry::Pose2 interpolate(const geometry::Pose2& a, const geometry::Pose2& b, double fraction) {
  return {a.x + fraction * (b.x - a.x), a.y + fraction * (b.y - a.y),
          geometry::normalize_angle(a.yaw + fraction * geometry::angle_difference(b.yaw, a.yaw))};
}

}  // namespace

AmclDriver::AmclDriver(AmclOptions options, core::DeviceTable& devices)
    : options_(std::move(options)), devices_(devices), parameters_(options_.parameters) {}

AmclDriver::~AmclDriver() {
  // Normally close() has run; never leave a listener pointing at a dead driver.
  laser_subscription_.reset();
  position_subscription_.reset();
}

void AmclDriver::check() {
  const std::uint16_t port = device().key().port;
  for (const auto& [interface, index] : {std::pair{protocol::kPositionCode, options_.position_index},
                                         std::pair{protocol::kLaserCode, options_.laser_index}}) {
    if (devices_.find(port, {interface, static_cast<std::uint16_t>(index)}) == nullptr) {
      throw core::DriverError("amcl: no " + protocol::interface_name(interface) + ":" + std::to_string(index) +
                              " device on port " + std::to_string(port) + " to localize with");
    }
  }
}

std::vector<core::DeviceKey> AmclDriver::source_devices() const {
  const std::uint16_t port = device().key().port;
  return {{port, {protocol::kPositionCode, static_cast<std::uint16_t>(options_.position_index)}},
          {port, {protocol::kLaserCode, static_cast<std::uint16_t>(options_.laser_index)}}};
}

void AmclDriver::open() {
  const std::uint16_t port = device().key().port;
  core::Device* position =
      devices_.find(port, {protocol::kPositionCode, static_cast<std::uint16_t>(options_.position_index)});
  core::Device* laser =
      devices_.find(port, {protocol::kLaserCode, static_cast<std::uint16_t>(options_.laser_index)});
  for (const auto& [found, what] : {std::pair{position, "position:" + std::to_string(options_.position_index)},
                                    std::pair{laser, "laser:" + std::to_string(options_.laser_index)}}) {
    if (found == nullptr) {
      const std::string message = device().name() + ": no " + what + " device on port " +
                                  std::to_string(port) + " to localize with";
      device().logger().error(message);
      throw core::DriverError(message);
    }
  }
  start_filter();
  {
    std::lock_guard lock(queue_mutex_);
    queue_.clear();
    odometry_history_.clear();
    unpredicted_odometry_.reset();
    dropped_scans_ = 0;
    accepting_ = true;
  }
  position_ = position;
  laser_ = laser;
  // If the laser refuses, the odometry subscription is undone on the way out.
  core::SourceSubscription odometry(*position, this, device().name());
  core::SourceSubscription scans(*laser, this, device().name());
  position_subscription_ = std::move(odometry);
  laser_subscription_ = std::move(scans);
}

void AmclDriver::close() {
  position_subscription_.stop_listening();
  laser_subscription_.stop_listening();
  {
    std::lock_guard lock(queue_mutex_);
    accepting_ = false;
    if (dropped_scans_ > 0) {
      device().logger().warning(device().name() + ": " + std::to_string(dropped_scans_) +
                                " scans dropped: the filter could not keep up");
    }
  }
  laser_subscription_.reset();
  position_subscription_.reset();
}

void AmclDriver::start_filter() {
  filter_ = std::make_unique<amcl::AmclFilter>(parameters_, options_.map, options_.seed, options_.initial_pose);
  filter_moved_ = false;
  last_processed_ = {};
}

// --- the sources' threads

void AmclDriver::data_published(const core::Device& source) {
  const std::shared_ptr<const core::DataSample> sample = source.latest_data();
  if (sample->payload.empty()) return;  // readlog's empty packet before its first line
  std::lock_guard lock(queue_mutex_);
  if (!accepting_) return;
  try {
    if (&source == position_) {
      add_odometry({odometry_pose(protocol::decode<protocol::PositionData>(sample->payload)), sample->timestamp});
    } else if (&source == laser_) {
      add_scan(laser_scan(protocol::decode<protocol::LaserData>(sample->payload), options_.laser_pose,
                          options_.laser_range_max),
               sample->timestamp);
    } else {
      return;
    }
  } catch (const std::exception& e) {
    device().logger().warning(device().name() + ": ignored a sample of " + source.name() + ": " + e.what());
    return;
  }
  queue_ready_.notify_one();
}

void AmclDriver::add_odometry(const OdometrySample& sample) {
  odometry_history_.push_back(sample);
  if (odometry_history_.size() > kOdometryHistory) odometry_history_.pop_front();
  push({sample.pose, sample.time, std::nullopt});
  unpredicted_odometry_ = sample;
}

void AmclDriver::add_scan(amcl::LaserScan scan, core::Timestamp time) {
  const std::optional<geometry::Pose2> odometry = odometry_at(time);
  if (!odometry) return;  // nothing to say where the robot was: no use to the filter
  // The newest odometry, taken at or before the scan and still queued alone:
  // the scan belongs to it, one filter step instead of two.
  if (!queue_.empty() && !queue_.back().scan && queue_.back().time == odometry_history_.back().time &&
      queue_.back().time <= time) {
    queue_.back().scan = std::move(scan);
    queue_.back().time = time;
    return;
  }
  push({*odometry, time, std::move(scan)});
}

std::optional<geometry::Pose2> AmclDriver::odometry_at(core::Timestamp time) const {
  if (odometry_history_.empty()) return std::nullopt;
  // The last sample at or before `time`, interpolated towards the next one.
  auto after = std::upper_bound(odometry_history_.begin(), odometry_history_.end(), time,
                                [](core::Timestamp t, const OdometrySample& s) { return t < s.time; });
  if (after == odometry_history_.begin()) return odometry_history_.front().pose;  // older than we keep
  const OdometrySample& before = *std::prev(after);
  if (after == odometry_history_.end()) return before.pose;
  const double span = seconds_between(before.time, after->time);
  const double fraction = span > 0.0 ? seconds_between(before.time, time) / span : 0.0;
  return interpolate(before.pose, after->pose, std::clamp(fraction, 0.0, 1.0));
}

void AmclDriver::push(Observation observation) {
  if (queue_.size() >= kQueueCapacity) {
    // Odometry alone only refines the path between scans: lose that first.
    auto victim = std::find_if(queue_.begin(), queue_.end(), [](const Observation& o) { return !o.scan; });
    if (victim == queue_.end()) {
      victim = queue_.begin();
      ++dropped_scans_;
    }
    queue_.erase(victim);
  }
  queue_.push_back(std::move(observation));
}

std::uint16_t AmclDriver::queued_scans() const {
  return static_cast<std::uint16_t>(
      std::count_if(queue_.begin(), queue_.end(), [](const Observation& o) { return o.scan.has_value(); }));
}

// --- the driver's thread

void AmclDriver::run(std::stop_token stop) {
  while (!stop.stop_requested()) {
    device().service_requests();
    std::optional<Observation> next;
    std::optional<OdometrySample> predict_from;
    std::uint16_t scans_left = 0;
    {
      std::unique_lock lock(queue_mutex_);
      queue_ready_.wait_for(lock, stop, kIdleWait, [this] { return !queue_.empty(); });
      if (!queue_.empty()) {
        next = std::move(queue_.front());
        queue_.pop_front();
      }
      scans_left = queued_scans();
      // Only worth a prediction while the filter lags behind the scans.
      if (scans_left > 0) predict_from = std::exchange(unpredicted_odometry_, std::nullopt);
      else unpredicted_odometry_.reset();
    }
    if (next) process(*next, scans_left);
    if (predict_from && filter_moved_) publish_prediction(*predict_from, scans_left);
  }
}

void AmclDriver::process(const Observation& observation, std::uint16_t scans_left) {
  filter_->update(observation.odometry, observation.scan ? &*observation.scan : nullptr);
  filter_moved_ = true;
  if (!observation.scan) return;
  last_processed_ = observation.time;
  // Below the update thresholds the particles stay where the last laser
  // update left them; report them where this odometry says the robot is.
  std::vector<amcl::Hypothesis> hypotheses = filter_->hypotheses();
  if (!hypotheses.empty()) {
    const geometry::Pose2 unapplied = hypotheses.front().mean.between(filter_->predict(observation.odometry).mean);
    for (amcl::Hypothesis& hypothesis : hypotheses) hypothesis.mean = hypothesis.mean.compose(unapplied);
  }
  publish(hypotheses, scans_left, observation.time);
}

void AmclDriver::publish_prediction(const OdometrySample& odometry, std::uint16_t scans_left) {
  const amcl::Hypothesis predicted = filter_->predict(odometry.pose);
  publish(std::span(&predicted, 1), scans_left, odometry.time);
}

void AmclDriver::publish(std::span<const amcl::Hypothesis> hypotheses, std::uint16_t scans_left,
                         core::Timestamp timestamp) {
  device().publish(protocol::encode(localize_data(hypotheses, scans_left, last_processed_)), timestamp);
}

// --- requests (answered on the driver's thread)

core::RequestResult AmclDriver::handle_request(const core::Request& request) {
  try {
    switch (request.subtype()) {
      case protocol::kLocalizeSetPoseReq:
        return set_pose(request);
      case protocol::kLocalizeGetConfigReq: {
        protocol::LocalizeConfig config;
        config.subtype = protocol::kLocalizeGetConfigReq;
        config.num_particles = static_cast<std::uint32_t>(parameters_.max_particles);
        return core::RequestResult::ack(protocol::encode(config));
      }
      case protocol::kLocalizeSetConfigReq:
        return set_config(request);
      case protocol::kLocalizeGetMapInfoReq:
        return map_info();
      case protocol::kLocalizeGetMapDataReq:
        return map_tile(request);
      default:
        return core::RequestResult::nack();
    }
  } catch (const std::exception&) {
    return core::RequestResult::nack();  // too short or too long for its struct
  }
}

core::RequestResult AmclDriver::set_pose(const core::Request& request) {
  const auto wire = protocol::decode<protocol::LocalizeSetPose>(request.payload);
  const Eigen::Matrix3d covariance = covariance_from_wire(wire.cov);
  if ((covariance.diagonal().array() < 0.0).any()) return core::RequestResult::nack();
  filter_->set_pose(pose_from_wire(wire.mean), covariance);
  filter_moved_ = false;
  // Tell subscribers at once rather than at the next scan.
  const std::vector<amcl::Hypothesis> hypotheses = filter_->hypotheses();
  std::uint16_t scans_left = 0;
  {
    std::lock_guard lock(queue_mutex_);
    scans_left = queued_scans();
  }
  publish(hypotheses, scans_left, device().clock().now());
  return core::RequestResult::ack();
}

core::RequestResult AmclDriver::set_config(const core::Request& request) {
  const auto wire = protocol::decode<protocol::LocalizeConfig>(request.payload);
  amcl::AmclParameters changed = parameters_;
  changed.max_particles = wire.num_particles;
  changed.min_particles = std::min(changed.min_particles, changed.max_particles);
  try {
    amcl::validate(changed);
  } catch (const std::invalid_argument&) {
    return core::RequestResult::nack();
  }
  parameters_ = changed;
  filter_->set_parameters(parameters_);
  return core::RequestResult::ack();
}

core::RequestResult AmclDriver::map_info() const {
  const grid::OccupancyGrid& map = *options_.map;
  protocol::LocalizeMapInfo info;
  info.subtype = protocol::kLocalizeGetMapInfoReq;
  info.scale = static_cast<std::uint32_t>(std::lround(1000.0 / map.resolution()));  // pixels per km
  info.width = static_cast<std::uint32_t>(map.width());
  info.height = static_cast<std::uint32_t>(map.height());
  return core::RequestResult::ack(protocol::encode(info));
}

core::RequestResult AmclDriver::map_tile(const core::Request& request) const {
  if (request.payload.size() < kTileHeaderSize) return core::RequestResult::nack();
  auto tile = protocol::decode<protocol::LocalizeMapData>(
      std::span(request.payload.data(), kTileHeaderSize));  // a client may send the whole struct
  const grid::OccupancyGrid& map = *options_.map;
  const auto width = static_cast<std::uint64_t>(map.width());
  const auto height = static_cast<std::uint64_t>(map.height());
  const std::uint64_t cells = std::uint64_t{tile.width} * tile.height;
  if (cells == 0 || cells > kMaxTileCells || tile.col >= width || tile.row >= height ||
      tile.col + std::uint64_t{tile.width} > width || tile.row + std::uint64_t{tile.height} > height) {
    return core::RequestResult::nack();
  }
  tile.data.clear();
  tile.data.reserve(cells);
  for (std::uint32_t j = 0; j < tile.height; ++j) {
    for (std::uint32_t i = 0; i < tile.width; ++i) {
      const grid::CellState state = map.at(static_cast<int>(tile.col + i), static_cast<int>(tile.row + j));
      tile.data.push_back(static_cast<std::int8_t>(state));
    }
  }
  return core::RequestResult::ack(protocol::encode(tile));
}

core::DriverSpec amcl_driver_spec() {
  core::DriverSpec spec;
  spec.name = "amcl";
  spec.interfaces = {protocol::kLocalizeCode};
  spec.access = protocol::Access::kRead;
  spec.limits.request_queue = AmclDriver::kQueueCapacity;
  spec.factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    return std::make_unique<AmclDriver>(read_amcl_options(context.section), context.devices);
  };
  spec.summary = "adaptive Monte-Carlo localization from odometry and a laser in a known map";
  spec.doc.manual_section = "7.3";
  spec.doc.options = {
      {"map_file/laser_map", "filename", "(required)", "", "the map image (or a ROS .yaml)"},
      {"map_scale", "length", "0.05", "m", "metres per pixel of the image"},
      {"map_negate", "int", "0", "", "1: white is occupied"},
      {"map_origin", "tuple", "(centred)", "m m", "where the image's bottom-left corner lies; [0 0] for a Stage 1.3 world"},
      {"position_index/odom_index", "int", "0", "", "the position device giving odometry"},
      {"laser_index", "int", "0", "", "the laser device"},
      {"laser_pose", "tuple", "[0 0 0]", "m m deg", "the laser on the robot"},
      {"laser_model", "string", "\"likelihood_field\"", "", "likelihood_field or beam"},
      {"laser_max_samples/laser_max_beams", "int", "30", "", "beams used per scan"},
      {"laser_range_max", "length", "8", "m", "readings at or beyond it are no return"},
      {"pf_min_samples", "int", "100", "", "fewest particles"},
      {"pf_max_samples", "int", "5000", "", "most particles"},
      {"update_thresh", "tuple", "[0.2 30]", "m deg", "motion before the next laser update"},
      {"init_pose", "tuple", "[0 0 0]", "m m deg", "the initial pose estimate"},
      {"init_pose_var", "tuple", "[0.5 0.5 30]", "m m deg", "its standard deviations"},
      {"seed", "int", "0", "", "random seed"}};
  spec.doc.requests = {"SET_POSE: restart the filter at a pose", "GET_CONFIG, SET_CONFIG: the filter's settings",
                       "GET_MAP_INFO, GET_MAP_DATA: the map"};
  spec.doc.example =
      "localize:0 ( driver \"amcl\" position_index 0 laser_index 0 map_file \"map.png\" map_scale 0.05 )";
  return spec;
}

}  // namespace playerkit::drivers
