#include "core/clock.hpp"

#include <chrono>

namespace playerkit::core {

std::uint64_t to_microseconds(Timestamp time) {
  return std::uint64_t{time.sec} * 1'000'000u + time.usec;
}

Timestamp from_microseconds(std::uint64_t microseconds) {
  // The wire has 32-bit seconds; times past 2106 wrap, as they would in 1.5.
  return {static_cast<std::uint32_t>(microseconds / 1'000'000u),
          static_cast<std::uint32_t>(microseconds % 1'000'000u)};
}

Timestamp WallClock::now() const {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  const auto us = std::chrono::duration_cast<std::chrono::microseconds>(since_epoch).count();
  return from_microseconds(static_cast<std::uint64_t>(us));
}

Timestamp ManualClock::now() const { return from_microseconds(microseconds_.load()); }

void ManualClock::set(Timestamp time) { microseconds_.store(to_microseconds(time)); }

void ManualClock::advance_microseconds(std::uint64_t microseconds) {
  microseconds_.fetch_add(microseconds);
}

}  // namespace playerkit::core
