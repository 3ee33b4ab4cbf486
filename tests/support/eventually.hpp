#pragma once
// Bounded waiting for something another thread or process will do: poll until
// the condition holds or the limit passes. Tests use it instead of sleeping
// and hoping.

#include <chrono>
#include <thread>

namespace playerkit::testing {

// True if `condition` held before `limit` passed.
template <class Condition>
bool eventually(Condition condition, std::chrono::milliseconds limit = std::chrono::seconds(5)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

}  // namespace playerkit::testing
