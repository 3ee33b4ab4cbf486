#include <algorithm>
#include <optional>
#include <vector>

#include "drivers/sim/simulated_drivers.hpp"
#include "interfaces/ranger_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::sim {

double SimSonarDriver::reading_time(const World& world) const { return world.sonar(model()).time; }

std::optional<std::vector<std::uint8_t>> SimSonarDriver::encode_reading(const World& world) {
  const playerkit::sim::SonarScan& scan = world.sonar(model());
  protocol::SonarData data;
  // Player 1.5 carries 64 transducers; sim_drivers warns about more when the device is made.
  const std::size_t count = std::min(scan.ranges.size(), protocol::kSonarMaxSamples);
  data.range_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) {
    data.ranges[i] = wire_value<std::uint16_t>(scan.ranges[i] * kMillimetresPerMetre);
  }
  return protocol::encode(data);
}

core::RequestResult SimSonarDriver::answer(World& world, const core::Request& request) {
  class SimulatedRing final : public interfaces::RangerArray {
   public:
    SimulatedRing(const World& world, ModelId model) : world_(world), model_(model) {}

    // The transducers on the robot: the ring's mount composed with each one's pose on the ring.
    std::optional<std::vector<geometry::Pose2>> sensor_poses() override {
      const auto& spec = std::get<playerkit::sim::SonarSpec>(world_.spec(model_).params);
      const geometry::Pose2 mount = pose_on_robot(world_, model_);
      std::vector<geometry::Pose2> poses;
      poses.reserve(spec.transducers.size());
      for (const geometry::Pose2& transducer : spec.transducers) poses.push_back(mount.compose(transducer));
      return poses;
    }
    bool set_power(bool /*on*/) override { return true; }  // simulated transducers are always on

   private:
    const World& world_;
    ModelId model_;
  };
  SimulatedRing ring(world, model());
  return interfaces::answer_sonar_request(ring, request);
}

}  // namespace playerkit::drivers::sim
