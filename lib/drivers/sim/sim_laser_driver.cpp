#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <utility>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::sim {

namespace {

constexpr int kMaxSamples = static_cast<int>(protocol::kLaserMaxSamples);
constexpr double kCentidegreesPerRadian = 18000.0 / std::numbers::pi;

// Stage 1.3's SET_CONFIG (stage-worlds.md §3.5): each resolution (0.01°)
// with the widest scan it allows (|angle| in 0.01°).
struct ResolutionLimit {
  int resolution;
  int max_angle;
};
constexpr ResolutionLimit kResolutions[] = {{25, 5000}, {50, 9000}, {100, 18000}};

const playerkit::sim::LaserSpec& laser_spec(const World& world, ModelId model) {
  return std::get<playerkit::sim::LaserSpec>(world.spec(model).params);
}

}  // namespace

std::uint16_t range_resolution_for(double range_max) {
  if (range_max * kMillimetresPerMetre <= 65535.0) return 1;
  if (range_max * kMillimetresPerMetre <= 655350.0) return 10;
  return 100;
}

LaserView default_laser_view(int samples, double range_max) {
  LaserView view;
  view.stride = samples > kMaxSamples ? (samples - 1 + kMaxSamples - 2) / (kMaxSamples - 1) : 1;
  view.count = samples > 0 ? (samples - 1) / view.stride + 1 : 0;
  view.range_res = range_resolution_for(range_max);
  return view;
}

SimLaserDriver::SimLaserDriver(std::shared_ptr<SimulationHost> host, ModelId model)
    : SimulatedDevice(std::move(host), model) {
  const playerkit::sim::LaserSpec spec =
      this->host().with_world([&](World& world) { return laser_spec(world, this->model()); });
  view_ = default_laser_view(spec.samples, spec.range_max);
}

void SimLaserDriver::unsubscribed() {
  // The world resets the scan when the last client leaves (Stage 1.3): so does the view.
  const playerkit::sim::LaserSpec spec = host().with_world([&](World& world) { return laser_spec(world, model()); });
  view_ = default_laser_view(spec.samples, spec.range_max);
}

double SimLaserDriver::reading_time(const World& world) const { return world.laser(model()).time; }

std::optional<std::vector<std::uint8_t>> SimLaserDriver::encode_reading(const World& world) {
  const playerkit::sim::LaserScan& scan = world.laser(model());
  const int samples = static_cast<int>(scan.ranges.size());
  const int last = view_.first + (view_.count - 1) * view_.stride;
  if (view_.count < 1 || last >= samples) return std::nullopt;  // a scan of another layout
  const double spacing = samples > 1 ? (scan.max_angle - scan.min_angle) / (samples - 1) : 0.0;
  protocol::LaserData data;
  data.min_angle = wire_value<std::int16_t>((scan.min_angle + view_.first * spacing) * kCentidegreesPerRadian);
  data.max_angle = wire_value<std::int16_t>((scan.min_angle + last * spacing) * kCentidegreesPerRadian);
  data.resolution = wire_value<std::uint16_t>(view_.stride * spacing * kCentidegreesPerRadian);
  data.range_res = view_.range_res;
  data.range_count = static_cast<std::uint16_t>(view_.count);
  const double units_per_metre = kMillimetresPerMetre / view_.range_res;
  for (int i = 0; i < view_.count; ++i) {
    const auto sample = static_cast<std::size_t>(view_.first + i * view_.stride);
    data.ranges[static_cast<std::size_t>(i)] = wire_value<std::uint16_t>(scan.ranges[sample] * units_per_metre);
    if (view_.intensity && sample < scan.intensities.size()) {
      data.intensity[static_cast<std::size_t>(i)] = scan.intensities[sample];
    }
  }
  return protocol::encode(data);
}

protocol::LaserConfig SimLaserDriver::current_config(const World& world) const {
  if (view_.configured) return *view_.configured;
  const playerkit::sim::LaserSpec& spec = laser_spec(world, model());
  const double spacing = spec.samples > 1 ? spec.fov / (spec.samples - 1) : 0.0;
  protocol::LaserConfig config;
  config.min_angle = wire_value<std::int16_t>(-spec.fov / 2.0 * kCentidegreesPerRadian);
  config.max_angle = wire_value<std::int16_t>((-spec.fov / 2.0 + (view_.count - 1) * view_.stride * spacing) *
                                              kCentidegreesPerRadian);
  config.resolution = wire_value<std::uint16_t>(view_.stride * spacing * kCentidegreesPerRadian);
  config.range_res = view_.range_res;
  config.intensity = view_.intensity ? 1 : 0;
  return config;
}

core::RequestResult SimLaserDriver::set_config(World& world, const core::Request& request) {
  if (request.payload.size() < protocol::LaserConfig::kWireSize) return core::RequestResult::nack();
  protocol::LaserConfig wanted = decode_padded<protocol::LaserConfig>(request.payload);
  const auto* limit = std::find_if(std::begin(kResolutions), std::end(kResolutions),
                                   [&](const ResolutionLimit& r) { return r.resolution == wanted.resolution; });
  if (limit == std::end(kResolutions)) return core::RequestResult::nack();
  const int resolution = limit->resolution;
  if (std::abs(wanted.min_angle) > limit->max_angle || std::abs(wanted.max_angle) > limit->max_angle ||
      wanted.min_angle > wanted.max_angle) {
    return core::RequestResult::nack();
  }
  if (wanted.range_res != 1 && wanted.range_res != 10 && wanted.range_res != 100) return core::RequestResult::nack();
  // Samples lie on multiples of the resolution from straight ahead: the
  // asked angles are rounded inwards to them.
  const auto floor_to = [](int angle, int step) { return static_cast<int>(std::floor(double(angle) / step)) * step; };
  const int min_angle = -floor_to(-wanted.min_angle, resolution);
  const int max_angle = floor_to(wanted.max_angle, resolution);
  if (min_angle > max_angle) return core::RequestResult::nack();
  // The world scans symmetrically about the laser's heading: as wide as the
  // farther of the two angles, of which the asked part is served.
  const int half_width = std::max({std::abs(min_angle), std::abs(max_angle), resolution});
  const int samples = 2 * half_width / resolution + 1;
  world.configure_laser(model(), 2.0 * half_width / kCentidegreesPerRadian, samples);
  view_.first = (min_angle + half_width) / resolution;
  view_.count = (max_angle - min_angle) / resolution + 1;
  view_.stride = 1;
  view_.range_res = wanted.range_res;
  view_.intensity = wanted.intensity != 0;
  wanted.subtype = protocol::kLaserSetConfig;
  wanted.min_angle = static_cast<std::int16_t>(min_angle);
  wanted.max_angle = static_cast<std::int16_t>(max_angle);
  view_.configured = wanted;
  // Scans taken before now have the old layout.
  skip_readings_until(world.time());
  return core::RequestResult::ack(protocol::encode(wanted));
}

core::RequestResult SimLaserDriver::answer(World& world, const core::Request& request) {
  switch (request.subtype()) {
    case protocol::kLaserGetGeom: {
      const geometry::Pose2 origin = pose_on_robot(world, model()).compose(laser_spec(world, model()).pose);
      const playerkit::sim::Body& body = world.spec(model()).body;
      protocol::LaserGeom geom;
      geom.subtype = protocol::kLaserGetGeom;
      geom.pose = {wire_value<std::int16_t>(origin.x * kMillimetresPerMetre),
                   wire_value<std::int16_t>(origin.y * kMillimetresPerMetre),
                   wire_value<std::int16_t>(degrees(origin.yaw))};
      if (body.present) {
        geom.size = {wire_value<std::int16_t>(body.size.x() * kMillimetresPerMetre),
                     wire_value<std::int16_t>(body.size.y() * kMillimetresPerMetre)};
      }
      return core::RequestResult::ack(protocol::encode(geom));
    }
    case protocol::kLaserGetConfig: {
      protocol::LaserConfig config = current_config(world);
      config.subtype = protocol::kLaserGetConfig;
      return core::RequestResult::ack(protocol::encode(config));
    }
    case protocol::kLaserSetConfig:
      return set_config(world, request);
    case protocol::kLaserPowerConfig:
      return core::RequestResult::ack();  // a simulated laser is always on
    default:
      return core::RequestResult::nack();
  }
}

}  // namespace playerkit::drivers::sim
