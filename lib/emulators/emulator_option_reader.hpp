#pragma once
// Reads an emulator's KEY=VALUE options with the checks every option needs;
// each error names the emulator, the option and what was expected:
//
//   sicklms200: noise=-1: expected a number from 0 to 1 (metres)

#include <string>
#include <string_view>

#include "algorithms/geometry/pose2.hpp"
#include "emulators/emulator_kind.hpp"

namespace playerkit::emulators {

class EmulatorOptionReader {
 public:
  // Throws std::invalid_argument for a name the kind does not have (listing
  // those it has) and for a name given twice.
  EmulatorOptionReader(const EmulatorKind& kind, const EmulatorOptionValues& values);

  [[nodiscard]] bool has(std::string_view name) const;
  [[nodiscard]] std::string text(std::string_view name, std::string_view fallback) const;
  [[nodiscard]] double number(std::string_view name, double fallback, double minimum, double maximum) const;
  [[nodiscard]] int integer(std::string_view name, int fallback, int minimum, int maximum) const;
  // 0/1, also no/yes, off/on, false/true.
  [[nodiscard]] bool flag(std::string_view name, bool fallback) const;
  // "x,y,yaw": metres, metres, degrees; returned with yaw in radians.
  [[nodiscard]] geometry::Pose2 pose(std::string_view name, geometry::Pose2 fallback) const;

  // "<kind>: <name>=<value>: <why>"
  [[noreturn]] void fail(std::string_view name, const std::string& why) const;

 private:
  [[nodiscard]] const std::string* value(std::string_view name) const;

  const EmulatorKind& kind_;
  const EmulatorOptionValues& values_;
};

}  // namespace playerkit::emulators
