#include "emulators/catalog/emulator_rig.hpp"

#include <stdexcept>


namespace playerkit::emulators {

EmulatorRig::EmulatorRig(const EmulatorCatalog& catalog, const std::vector<EmulatorRequest>& requests,
                         RigSettings settings)
    : settings_(std::move(settings)) {
  members_.resize(requests.size());
  kinds_.reserve(requests.size());
  // Every name first, so that a typo in the last one starts nothing.
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const EmulatorKind* kind = catalog.find(requests[i].name);
    if (!kind) {
      throw std::invalid_argument("no emulator '" + requests[i].name + "'; there are " + catalog.names());
    }
    kinds_.push_back(*kind);
  }
  for (std::size_t i = 0; i < requests.size(); ++i) members_[i].kind = &kinds_[i];
  const grid::OccupancyGrid* map = settings_.map.get();
  EmulatorRunner* robot = nullptr;
  try {
    // Robots (everything that does not ride) first: the riders' pose source needs one.
    for (const bool riders : {false, true}) {
      for (std::size_t i = 0; i < requests.size(); ++i) {
        Member& member = members_[i];
        if ((member.kind->mount == EmulatorMount::rider) != riders) continue;
        EmulatorWorld world{.map = map, .carrier_pose = {}};
        if (riders && robot) {
          member.carried = true;
          world.carrier_pose = [robot] {
            return robot->with_emulator<DeviceEmulator>(
                [](DeviceEmulator& carrier) { return carrier.world_pose().value_or(geometry::Pose2{}); });
          };
        }
        member.runner = std::make_unique<EmulatorRunner>(catalog.make(requests[i].name, requests[i].options, world),
                                                         requests[i].endpoint, settings_.faults);
        if (!robot && member.kind->mount == EmulatorMount::robot) robot = member.runner.get();
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
