#pragma once
// Applies a FaultPlan's per-telegram faults to what an emulator sends. Pure
// and seeded: the same plan and telegrams give the same bytes.

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "emulators/runner/fault_plan.hpp"

namespace playerkit::emulators {

struct InjectedFaults {
  std::uint64_t bad_checksums = 0;
  std::uint64_t garbage_runs = 0;
  std::uint64_t truncated = 0;
  std::uint64_t dropped_bytes = 0;       // single bytes lost to drop=P
  std::uint64_t dropped_while_dead = 0;  // telegrams lost to silent-start, slow-start or vanish
};

// "3 bad checksums, 12 bytes dropped" (empty when nothing was injected): the
// counts as `player-drivers emulate --stats` prints them.
std::string describe(const InjectedFaults& faults);

class FaultInjector {
 public:
  explicit FaultInjector(FaultPlan plan);

  // The bytes to write for `telegram`, each chunk with one write(); empty
  // when nothing goes out.
  std::vector<std::vector<std::uint8_t>> apply(const Telegram& telegram);
  // A telegram sent while the line is dead: counted, never written.
  void drop() { ++counts_.dropped_while_dead; }

  [[nodiscard]] const FaultPlan& plan() const { return plan_; }
  [[nodiscard]] const InjectedFaults& counts() const { return counts_; }

 private:
  bool happens(double probability);

  FaultPlan plan_;
  std::mt19937_64 random_;
  InjectedFaults counts_;
};

}  // namespace playerkit::emulators
