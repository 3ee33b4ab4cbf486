#include "core/server_clock.hpp"

#include <utility>

namespace playerkit::core {

ServerClock::ServerClock() : current_(&wall_clock_) {}

ServerClock::ServerClock(const Clock& fallback) : current_(&fallback) {}

Timestamp ServerClock::now() const { return current_.load(std::memory_order_acquire)->now(); }

void ServerClock::claim(std::shared_ptr<const Clock> clock, const std::string& claimant) {
  if (!clock) throw ClockClaimError(claimant + ": claims the server clock without a clock");
  std::lock_guard lock(mutex_);
  if (claimed_ == clock) return;
  if (claimed_) {
    throw ClockClaimError("the server clock is " + claimant_ + "'s already; " + claimant +
                          " keeps a clock of its own (one replay or simulation sets the server's time)");
  }
  claimed_ = std::move(clock);
  claimant_ = claimant;
  current_.store(claimed_.get(), std::memory_order_release);
}

bool ServerClock::claimed() const {
  std::lock_guard lock(mutex_);
  return claimed_ != nullptr;
}

std::string ServerClock::claimant() const {
  std::lock_guard lock(mutex_);
  return claimant_;
}

}  // namespace playerkit::core
