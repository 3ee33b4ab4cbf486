#pragma once
// For the simulated drivers' tests: small worlds made in the test, devices
// made from configuration text through the simulated drivers (as player-serve
// -s makes them), and a world stepped by hand (the host starts paused, so
// nothing moves unless the test says so).

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "core/device.hpp"
#include "drivers/sim/sim_drivers.hpp"
#include "drivers/sim/simulation_host.hpp"
#include "drivers/sim/simulation_source.hpp"
#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/world.hpp"

namespace playerkit::drivers::sim::testing {

using namespace playerkit::sim;
using drivers::testing::kTestPort;
using drivers::testing::make_request;

inline constexpr double kCell = 0.05;  // m: the test maps' resolution

// A free 20 x 20 m floor centred on the origin.
inline grid::OccupancyGrid open_floor() {
  return grid::OccupancyGrid::centred(400, 400, kCell, grid::CellState::free);
}

// Occupied: every cell whose centre lies in [x0, x1] x [y0, y1].
inline void add_wall(grid::OccupancyGrid& map, double x0, double y0, double x1, double y1) {
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      const double x = map.origin().x() + (col + 0.5) * map.resolution();
      const double y = map.origin().y() + (row + 0.5) * map.resolution();
      if (x >= x0 && x <= x1 && y >= y0 && y <= y1) map.set(col, row, grid::CellState::occupied);
    }
  }
}

// A robot at the origin facing +x, reporting its true pose (gps with the
// world's frame), 0.53 x 0.38 m like gazebo.md's Pioneer.
inline ModelSpec test_robot(const std::string& name, const geometry::Pose2& pose = {}) {
  ModelSpec spec;
  spec.name = name;
  spec.type = "position";
  spec.pose = pose;
  spec.body.size = {0.53, 0.38};
  PositionSpec position;
  position.localization = Localization::gps;
  position.localization_origin = geometry::Pose2{};
  position.max_velocity = {2.0, 2.0, std::numbers::pi};
  position.min_velocity = -position.max_velocity;
  spec.params = position;
  return spec;
}

inline ModelSpec on(ModelId parent, std::string name, ModelParams params, const geometry::Pose2& pose = {}) {
  ModelSpec spec;
  spec.name = std::move(name);
  spec.parent = parent;
  spec.pose = pose;
  spec.body.present = false;
  spec.params = std::move(params);
  return spec;
}

// A laser of `samples` over 180° (the first and last on the edges), 8 m.
inline LaserSpec test_laser(int samples = 181) {
  LaserSpec laser;
  laser.samples = samples;
  laser.fov = std::numbers::pi;
  laser.range_max = 8.0;
  laser.interval = 0.1;
  return laser;
}

// Paused from the start: the test steps the world.
inline SimulationSettings stepped_by_hand() {
  SimulationSettings settings;
  settings.start_paused = true;
  return settings;
}

// Simulated devices made from configuration text on `world`, stepped by hand.
struct SimDevices {
  explicit SimDevices(World world, SimulationSettings settings = stepped_by_hand())
      : source(std::make_shared<SimulationSource>(std::move(world), "test.world", settings)) {
    for (core::DriverSpec& spec : simulation_driver_specs(source)) builtin.registry.add(std::move(spec));
  }

  void load(const std::string& config) { builtin.load(config); }
  core::Device& device(std::uint16_t interface, std::uint16_t index = 0) { return builtin.device(interface, index); }
  SimulationHost& host() {
    auto made = source->existing_host();
    if (!made) throw std::runtime_error("no simulated device made yet");
    return *made;
  }
  void step(int steps = 1) {
    for (int i = 0; i < steps; ++i) host().step();
  }
  // One server cycle of the device: its update(), then its requests.
  void cycle(core::Device& device) { device.update(); }

  // The reply to one request, answered as the server would in a cycle.
  core::Reply ask(core::Device& device, std::vector<std::uint8_t> payload) {
    if (device.enqueue_request(make_request(device.address().interface, std::move(payload))) !=
        core::Device::RequestStatus::kQueued) {
      throw std::runtime_error("request queue full");
    }
    device.update();
    auto replies = device.take_replies();
    if (replies.size() != 1) throw std::runtime_error("expected one reply");
    return replies.front();
  }

  template <class T>
  T latest(const core::Device& device) const {
    return protocol::decode<T>(device.latest_data()->payload);
  }

  std::shared_ptr<SimulationSource> source;
  drivers::testing::BuiltinDevices builtin;  // last: its devices go before the source
};

}  // namespace playerkit::drivers::sim::testing
