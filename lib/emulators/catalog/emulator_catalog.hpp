#pragma once
// Emulators by name, with their options as KEY=VALUE text, for
// `player-drivers emulate`, tests and the demo. The kinds come from the
// registered hardware families (families::FamilyRegistry::emulator_catalog()):
//
//   const auto catalog = families::builtin_families().emulator_catalog();
//   auto laser = catalog.make("sicklms200", {{"noise", "0.01"}, {"pose", "1,2,90"}}, {.map = &map});
//   emulators::EmulatorRunner runner(std::move(laser), emulators::PtyEndpoint{"/tmp/laser"});
//
// Every name and option is checked here, so a typo is an error that lists
// what exists rather than an emulator quietly built with defaults.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "emulators/emulator_kind.hpp"

namespace playerkit::emulators {

class EmulatorCatalog {
 public:
  EmulatorCatalog() = default;
  // Throws std::invalid_argument for two kinds of one name or a kind without a factory.
  explicit EmulatorCatalog(std::vector<EmulatorKind> kinds);

  // In the order given.
  [[nodiscard]] const std::vector<EmulatorKind>& kinds() const { return kinds_; }
  // nullptr when there is none of that name.
  [[nodiscard]] const EmulatorKind* find(std::string_view name) const;
  // "p2os, sicklms200, sickpls"; "none" when empty.
  [[nodiscard]] std::string names() const;

  // Throws std::invalid_argument naming the emulator and the option: an
  // unknown name (listing the names), an unknown option (listing the
  // options), a bad value, or values the device cannot have.
  [[nodiscard]] std::unique_ptr<DeviceEmulator> make(std::string_view name, const EmulatorOptionValues& options,
                                                     const EmulatorWorld& world = {}) const;

 private:
  std::vector<EmulatorKind> kinds_;
};

}  // namespace playerkit::emulators
