#pragma once
// The server's clock: every header time the server writes and every sample a
// device publishes without a time of its own is read from it. It reads the
// wall clock (or the fallback it was made with) until a driver family claims
// it, while the devices are created, with a clock of its own: readlog's -r
// replay with the log's time, the simulator with simulation time.
//
//   void factory(const core::DriverContext& context) {
//     context.clock.claim(simulation->clock_handle(), core::to_string(context.key) + " (position)");
//   }
//
// One claimant at a time: the same clock may be claimed again (every device
// of one simulation, every readlog device of the -r log), a different one is
// refused with a ClockClaimError naming both devices, which the configuration
// reports at the second device's declaration.

#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "core/clock.hpp"

namespace playerkit::core {

class ClockClaimError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ServerClock final : public Clock {
 public:
  // The wall clock until claimed.
  ServerClock();
  // `fallback` until claimed; it must outlive this clock.
  explicit ServerClock(const Clock& fallback);
  ServerClock(const ServerClock&) = delete;
  ServerClock& operator=(const ServerClock&) = delete;

  // Safe from any thread, also while a claim is made.
  [[nodiscard]] Timestamp now() const override;

  // From now on `clock` is the server's (kept alive as long as this is).
  // `claimant` names the device for messages: "position:0@6665 (readlog)".
  // Throws ClockClaimError when another clock holds the claim, or for a null
  // clock.
  void claim(std::shared_ptr<const Clock> clock, const std::string& claimant);
  [[nodiscard]] bool claimed() const;
  // The first device that claimed it; empty while the fallback runs.
  [[nodiscard]] std::string claimant() const;

 private:
  WallClock wall_clock_;
  mutable std::mutex mutex_;  // the claim, not the readings
  std::shared_ptr<const Clock> claimed_;
  std::string claimant_;
  std::atomic<const Clock*> current_;
};

}  // namespace playerkit::core
