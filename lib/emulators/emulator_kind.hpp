#pragma once
// One kind of emulated device as `player-drivers emulate` offers it: its name,
// what points at it, its documented KEY=VALUE options and the factory that
// builds it from them. Each hardware family's spec (lib/families/<name>)
// lists its kinds; the catalog (catalog/emulator_catalog.hpp) collects them.

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/device_emulator.hpp"

namespace playerkit::emulators {

struct EmulatorOptionDoc {
  std::string name;           // "noise"
  std::string default_value;  // as it would be typed: "0", "0,0,0"
  std::string summary;        // one line, with the unit
};

// KEY=VALUE pairs as given, in order.
using EmulatorOptionValues = std::vector<std::pair<std::string, std::string>>;

// What the emulator lives in, besides its options.
struct EmulatorWorld {
  // Walls for sonars, lasers and stalls. Not owned: it must outlive the emulator.
  const grid::OccupancyGrid* map = nullptr;
  // For kinds that ride on a robot: the robot's true pose, asked at every
  // scan; the sensor sits at its `mount` option in the robot's frame. Empty:
  // the sensor stands at its `pose` option.
  std::function<geometry::Pose2()> carrier_pose;
};

class EmulatorOptionReader;

// How an emulated device takes part in a rig of several.
enum class EmulatorMount {
  standalone,  // neither carries nor rides
  robot,       // a mobile base: DeviceEmulator::world_pose() is where it is
  rider,       // a sensor that rides on the rig's first robot when there is one
};

struct EmulatorKind {
  std::string name;     // "p2os", "sicklms200", "sickpls"
  std::string summary;  // one line
  // What a configuration points at it: `<interface>:0 ( driver "<driver>" port ... )`.
  std::string interface_name;
  std::string driver;
  EmulatorMount mount = EmulatorMount::standalone;
  std::vector<EmulatorOptionDoc> options;
  // Builds one from options already checked against `options` by name.
  // Throws std::invalid_argument for a bad value (EmulatorOptionReader::fail
  // names the kind and the option) or values the device cannot have.
  std::function<std::unique_ptr<DeviceEmulator>(const EmulatorOptionReader&, const EmulatorWorld&)> make;
};

// `position:0 ( driver "p2os_position" port "/tmp/robot" )`
std::string config_example(const EmulatorKind& kind, std::string_view port);

}  // namespace playerkit::emulators
