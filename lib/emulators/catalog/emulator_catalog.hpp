#pragma once
// Emulators by name, with their options as KEY=VALUE text, for
// `player-drivers emulate`, tests and the demo:
//
//   auto laser = emulators::make_emulator("sicklms200", {{"noise", "0.01"}, {"pose", "1,2,90"}},
//                                         {.map = &map});
//   emulators::EmulatorRunner runner(std::move(laser), emulators::PtyEndpoint{"/tmp/laser"});
//
// Every name and option is checked here, so a typo is an error that lists
// what exists rather than an emulator quietly built with defaults.

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

struct EmulatorKind {
  std::string name;     // "p2os", "sicklms200", "sickpls"
  std::string summary;  // one line
  // What a configuration points at it: `<interface>:0 ( driver "<driver>" port ... )`.
  std::string interface_name;
  std::string driver;
  // Lasers: when a robot is emulated too, they ride on it (the `mount` option).
  bool rides_on_robot = false;
  std::vector<EmulatorOptionDoc> options;
};

// Every emulator, in a fixed order.
const std::vector<EmulatorKind>& emulator_kinds();
// nullptr when there is none of that name.
const EmulatorKind* find_emulator_kind(std::string_view name);
// "p2os, sicklms200, sickpls"
std::string emulator_names();

// `position:0 ( driver "p2os_position" port "/tmp/robot" )`
std::string config_example(const EmulatorKind& kind, std::string_view port);

// KEY=VALUE pairs as given, in order.
using EmulatorOptionValues = std::vector<std::pair<std::string, std::string>>;

// What the emulator lives in, besides its options.
struct EmulatorWorld {
  // Walls for sonars, lasers and stalls. Not owned: it must outlive the emulator.
  const grid::OccupancyGrid* map = nullptr;
  // For kinds that ride on a robot: the robot's true pose, asked at every
  // scan; the laser sits at its `mount` option in the robot's frame. Empty:
  // the laser stands at its `pose` option.
  std::function<geometry::Pose2()> carrier_pose;
};

// Throws std::invalid_argument naming the emulator and the option: an unknown
// name (listing the names), an unknown option (listing the options), a bad
// value, or values the device cannot have.
std::unique_ptr<DeviceEmulator> make_emulator(std::string_view name, const EmulatorOptionValues& options,
                                              const EmulatorWorld& world = {});

}  // namespace playerkit::emulators
