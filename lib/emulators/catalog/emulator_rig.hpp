#pragma once
// Several emulators at once, each on its own line, sharing one map; sensors
// that ride (EmulatorMount::rider) ride on the first emulated robot of any
// family (their pose follows its true pose, at their `mount` option). What
// `player-drivers emulate p2os sicklms200` runs:
//
//   emulators::EmulatorRig rig(catalog,
//                              {{"p2os", {}, emulators::PtyEndpoint{"/tmp/robot"}},
//                               {"sicklms200", {{"mount", "0.16,0,0"}}, emulators::PtyEndpoint{"/tmp/laser"}}},
//                              {.map = map});
//   rig.config_line(1)   // laser:0 ( driver "sicklms200" port "/tmp/laser" )

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "emulators/runner/fault_plan.hpp"

namespace playerkit::emulators {

struct EmulatorRequest {
  std::string name;  // "p2os", "sicklms200", "sickpls"
  EmulatorOptionValues options;
  Endpoint endpoint = PtyEndpoint{};
};

struct RigSettings {
  std::shared_ptr<const grid::OccupancyGrid> map;  // null: open space
  FaultPlan faults;                                // applied to every emulator's line
};

class EmulatorRig {
 public:
  // Builds and starts every emulator, robots first. Throws
  // std::invalid_argument for a bad name or option (nothing is left
  // running) and links::LinkError when a line cannot be had.
  // The catalog is only read while constructing.
  EmulatorRig(const EmulatorCatalog& catalog, const std::vector<EmulatorRequest>& requests, RigSettings settings);
  EmulatorRig(const EmulatorRig&) = delete;
  EmulatorRig& operator=(const EmulatorRig&) = delete;
  // Stops the riders before the robot they read.
  ~EmulatorRig();

  [[nodiscard]] std::size_t size() const { return members_.size(); }
  // In the order requested.
  [[nodiscard]] const EmulatorKind& kind(std::size_t index) const { return *members_.at(index).kind; }
  [[nodiscard]] EmulatorRunner& runner(std::size_t index) { return *members_.at(index).runner; }
  // Whether the emulator rides on the robot.
  [[nodiscard]] bool carried(std::size_t index) const { return members_.at(index).carried; }
  // A configuration section for a driver to use it.
  [[nodiscard]] std::string config_line(std::size_t index) const;
  // The emulator's own one-line state (DeviceEmulator::describe).
  [[nodiscard]] std::string describe(std::size_t index);

 private:
  struct Member {
    const EmulatorKind* kind = nullptr;  // a copy's, kept in kinds_
    bool carried = false;
    std::unique_ptr<EmulatorRunner> runner;
  };

  RigSettings settings_;
  std::vector<EmulatorKind> kinds_;
  std::vector<Member> members_;
};

}  // namespace playerkit::emulators
