#include "emulators/catalog/emulator_rig.hpp"

#include <stdexcept>

#include "emulators/p2os/p2os_robot_emulator.hpp"

namespace playerkit::emulators {

EmulatorRig::EmulatorRig(const std::vector<EmulatorRequest>& requests, RigSettings settings)
    : settings_(std::move(settings)) {
  members_.resize(requests.size());
  // Every name first, so that a typo in the last one starts nothing.
  for (std::size_t i = 0; i < requests.size(); ++i) {
    members_[i].kind = find_emulator_kind(requests[i].name);
    if (!members_[i].kind) {
      throw std::invalid_argument("no emulator '" + requests[i].name + "'; there are " + emulator_names());
    }
  }
  const grid::OccupancyGrid* map = settings_.map.get();
  EmulatorRunner* robot = nullptr;
  try {
    // Robots (everything that does not ride) first: the riders' pose source needs one.
    for (const bool riders : {false, true}) {
      for (std::size_t i = 0; i < requests.size(); ++i) {
        Member& member = members_[i];
        if (member.kind->rides_on_robot != riders) continue;
        EmulatorWorld world{.map = map, .carrier_pose = {}};
        if (riders && robot) {
          member.carried = true;
          world.carrier_pose = [robot] {
            return robot->with_emulator<P2osRobotEmulator>([](P2osRobotEmulator& r) { return r.true_pose(); });
          };
        }
        member.runner = std::make_unique<EmulatorRunner>(make_emulator(requests[i].name, requests[i].options, world),
                                                         requests[i].endpoint, settings_.faults);
        if (!robot && member.kind->name == "p2os") robot = member.runner.get();
      }
    }
  } catch (...) {
    for (Member& member : members_) {
      if (member.carried) member.runner.reset();
    }
    members_.clear();
    throw;
  }
}

EmulatorRig::~EmulatorRig() {
  for (Member& member : members_) {
    if (member.carried) member.runner.reset();
  }
}

std::string EmulatorRig::config_line(std::size_t index) const {
  const Member& member = members_.at(index);
  return config_example(*member.kind, member.runner->device_path());
}

std::string EmulatorRig::describe(std::size_t index) {
  return runner(index).with_emulator<DeviceEmulator>([](DeviceEmulator& emulator) { return emulator.describe(); });
}

}  // namespace playerkit::emulators
