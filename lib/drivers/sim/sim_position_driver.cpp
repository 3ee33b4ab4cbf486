#include <optional>
#include <utility>

#include "drivers/sim/simulated_drivers.hpp"
#include "interfaces/position_data.hpp"
#include "interfaces/position_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers::sim {

geometry::Pose2 pose_on_robot(const World& world, ModelId model) {
  return world.true_pose(world.root_of(model)).between(world.true_pose(model));
}

SimPositionDriver::SimPositionDriver(std::shared_ptr<SimulationHost> host, ModelId model, HeadingRange heading)
    : SimulatedDevice(std::move(host), model), heading_(heading) {}

void SimPositionDriver::apply_command(World& world, const core::Command& command) {
  const auto wanted = decode_padded<protocol::PositionCommand>(command.payload);
  if (wanted.type == 1) {
    world.command_pose(model(), {wanted.xpos / kMillimetresPerMetre, wanted.ypos / kMillimetresPerMetre,
                                 radians(wanted.yaw)});
    return;
  }
  world.command_velocity(model(), {wanted.xspeed / kMillimetresPerMetre, wanted.yspeed / kMillimetresPerMetre,
                                   radians(wanted.yawspeed)});
}

double SimPositionDriver::reading_time(const World& world) const { return world.position(model()).time; }

std::optional<std::vector<std::uint8_t>> SimPositionDriver::encode_reading(const World& world) {
  const playerkit::sim::PositionReading& reading = world.position(model());
  return protocol::encode(interfaces::position_data(reading.pose, reading.velocity, reading.stalled, heading_));
}

core::RequestResult SimPositionDriver::answer(World& world, const core::Request& request) {
  // The simulated robot's side of the position requests (as Stage 1.3:
  // GET_GEOM, RESET_ODOM and SET_ODOM, with MOTOR_POWER and VELOCITY_MODE
  // acknowledged and ignored); the adapter checks sizes and makes the replies.
  class SimulatedBase final : public interfaces::PositionBase {
   public:
    SimulatedBase(World& world, ModelId model) : world_(world), model_(model) {}

    std::optional<interfaces::BaseGeometry> geometry() override {
      const playerkit::sim::Body& body = world_.spec(model_).body;
      const double width = body.shape == playerkit::sim::Shape::circle ? body.size.x() : body.size.y();
      return interfaces::BaseGeometry{body.offset, body.size.x(), width};
    }
    // Motors are always on in a simulation; control modes are the command's type.
    bool set_motor_power(bool /*on*/) override { return true; }
    bool set_velocity_mode(std::uint8_t /*mode*/) override { return true; }
    bool set_position_mode(bool /*position_control*/) override { return true; }
    bool reset_odometry() override {
      world_.set_odometry(model_, {});
      return true;
    }
    bool set_odometry(const geometry::Pose2& pose) override {
      world_.set_odometry(model_, pose);
      return true;
    }

   private:
    World& world_;
    ModelId model_;
  };
  SimulatedBase base(world, model());
  return interfaces::answer_position_request(base, request);
}

}  // namespace playerkit::drivers::sim
