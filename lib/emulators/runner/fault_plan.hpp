#pragma once
// What can go wrong on a device's line, for rehearsing a driver's error
// paths: `player-drivers emulate p2os --fault bad-checksum=0.1 --fault vanish=5:3`.
// fault_kinds() lists them with their arguments; `--help` prints that list.
//
//   bad-checksum=P     each telegram's last byte (its checksum) flipped with probability P
//   garbage=P          1..16 random bytes before a telegram with probability P
//   truncate=P         a telegram cut short (and the rest never sent) with probability P
//   drop=P             each byte the device sends lost with probability P (a noisy line)
//   silent-start=S     the device hears and says nothing for its first S seconds (powered
//                      on with the emulator, slow to boot)
//   slow-start=S       the same for S seconds after every time the host opens the line: a
//                      device powered with the port or its adapter, the case the SICK
//                      drivers' `delay` option waits for (sicklms200.md §1.1 step 2)
//   vanish=AT:FOR      at AT seconds the line goes dead both ways for FOR seconds, then
//                      comes back (a pulled cable); the device itself keeps running
//   seed=N             the random choices' seed (default 1): the same plan, the same faults
//
// No sheet describes a device that answers garbage while it boots, so none
// is offered: a booting device here is deaf and mute, and keeps its state.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "emulators/device_emulator.hpp"

namespace playerkit::emulators {

struct FaultPlan {
  double bad_checksum = 0.0;
  double garbage = 0.0;
  double truncate = 0.0;
  double drop = 0.0;
  Duration silent_start{0};
  Duration slow_start{0};
  Duration vanish_at{0};
  Duration vanish_for{0};  // 0: never vanishes
  std::uint64_t seed = 1;

  [[nodiscard]] bool any() const;
  // "bad-checksum=0.1, vanish=5:3" (empty when there is no fault).
  [[nodiscard]] std::string describe() const;
  // Whether the line is dead at `now` (a silent or slow start, a vanish
  // window); `host_opened_at` is when the host last opened the line, if it has.
  [[nodiscard]] bool line_dead(Duration now, std::optional<Duration> host_opened_at = std::nullopt) const;
};

struct FaultKind {
  std::string_view argument;  // "drop=P": the kind and its value's form
  std::string_view summary;   // one line
};

// Every kind add_fault() takes, in the order of the table above.
std::span<const FaultKind> fault_kinds();

// Adds one `--fault` argument to `plan`. Throws std::invalid_argument with a
// message naming the argument and listing the kinds.
void add_fault(FaultPlan& plan, std::string_view argument);

}  // namespace playerkit::emulators
