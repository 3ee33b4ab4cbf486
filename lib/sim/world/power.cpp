// Batteries: drained every step by the robot they ride on.

#include <algorithm>
#include <cmath>

#include "sim/world/world_state.hpp"

namespace playerkit::sim {

void World::State::drain_power() {
  const double dt = settings.step;
  for (const ModelId id : powers) {
    ModelRecord& model = models[static_cast<std::size_t>(id)];
    const auto& spec = std::get<PowerSpec>(model.spec.params);
    // The robot it rides on is its nearest position ancestor; a stalled
    // robot is not moving, whatever it was told.
    double speed = 0.0;
    for (ModelId up = model.spec.parent; up != kNoModel; up = models[static_cast<std::size_t>(up)].spec.parent) {
      if (const auto* position = std::get_if<PositionState>(&models[static_cast<std::size_t>(up)].device)) {
        if (!position->stalled) speed = std::hypot(position->velocity.x(), position->velocity.y());
        break;
      }
    }
    auto& power = std::get<PowerState>(model.device);
    const double watts = spec.idle_watts + spec.watts_per_mps * speed;
    power.joules = std::max(power.joules - watts * dt, 0.0);
  }
}

const PowerReading& World::power(ModelId id) const { return state_->device<PowerState>(id, "power").reading; }

}  // namespace playerkit::sim
