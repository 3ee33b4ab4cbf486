#pragma once
// Where "now" comes from. Every header time the server writes is read from one
// Clock, the core::ServerClock (server_clock.hpp): the wall clock normally, the
// log's clock when replaying (readlog sets a ManualClock as it goes and claims
// the server clock with it), simulation time when simulating, a ManualClock in
// tests.

#include <atomic>
#include <cstdint>

#include "protocol/message.hpp"

namespace playerkit::core {

using protocol::Timestamp;

class Clock {
 public:
  virtual ~Clock() = default;
  // Safe to call from any thread.
  [[nodiscard]] virtual Timestamp now() const = 0;
};

// gettimeofday-style time since the Unix epoch, as 1.5 stamped its messages.
class WallClock final : public Clock {
 public:
  [[nodiscard]] Timestamp now() const override;
};

// Time that only moves when told to.
class ManualClock final : public Clock {
 public:
  explicit ManualClock(Timestamp start = {}) { set(start); }

  [[nodiscard]] Timestamp now() const override;
  void set(Timestamp time);
  void advance_microseconds(std::uint64_t microseconds);

 private:
  std::atomic<std::uint64_t> microseconds_{0};
};

// Whole microseconds since the epoch, for arithmetic on timestamps.
[[nodiscard]] std::uint64_t to_microseconds(Timestamp time);
[[nodiscard]] Timestamp from_microseconds(std::uint64_t microseconds);

}  // namespace playerkit::core
