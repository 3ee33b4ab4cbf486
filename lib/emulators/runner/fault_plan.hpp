#pragma once
// What can go wrong on a device's line, for rehearsing a driver's error
// paths: `player-drivers emulate p2os --fault bad-checksum=0.1 --fault vanish=5:3`.
//
//   bad-checksum=P     each telegram's last byte (its checksum) flipped with probability P
//   garbage=P          1..16 random bytes before a telegram with probability P
//   truncate=P         a telegram cut short (and the rest never sent) with probability P
//   silent-start=S     the device ignores everything for its first S seconds (slow to boot)
//   vanish=AT:FOR      at AT seconds the line goes dead both ways for FOR seconds, then
//                      comes back (a pulled cable); the device itself keeps running
//   seed=N             the random choices' seed (default 1): the same plan, the same faults

#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>

#include "emulators/device_emulator.hpp"

namespace playerkit::emulators {

struct FaultPlan {
  double bad_checksum = 0.0;
  double garbage = 0.0;
  double truncate = 0.0;
  Duration silent_start{0};
  Duration vanish_at{0};
  Duration vanish_for{0};  // 0: never vanishes
  std::uint64_t seed = 1;

  [[nodiscard]] bool any() const;
  // "bad-checksum=0.1, vanish=5:3" (empty when there is no fault).
  [[nodiscard]] std::string describe() const;
  // Whether the line is dead at `now` (silent start or a vanish window).
  [[nodiscard]] bool line_dead(Duration now) const;
};

// Adds one `--fault` argument to `plan`. Throws std::invalid_argument with a
// message naming the argument and listing the kinds.
void add_fault(FaultPlan& plan, std::string_view argument);

}  // namespace playerkit::emulators
