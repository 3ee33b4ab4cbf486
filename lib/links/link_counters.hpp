#pragma once
// What a link has seen, for `--stats`, logs and tests. Updated by the link
// and its FramedReader from whichever thread does the I/O, read from any
// other thread; each counter is its own relaxed atomic, so a snapshot is a
// set of recent values, not one instant.

#include <atomic>
#include <cstdint>
#include <string>

namespace playerkit::links {

class Counter {
 public:
  void add(std::uint64_t amount = 1) noexcept { value_.fetch_add(amount, std::memory_order_relaxed); }
  [[nodiscard]] std::uint64_t value() const noexcept { return value_.load(std::memory_order_relaxed); }

 private:
  std::atomic<std::uint64_t> value_{0};
};

struct LinkCounterSnapshot {
  std::uint64_t bytes_in = 0;         // received from the device
  std::uint64_t bytes_out = 0;        // written to the device
  std::uint64_t telegrams = 0;        // whole valid telegrams a FramedReader returned
  std::uint64_t checksum_errors = 0;  // framed telegrams that failed their check
  std::uint64_t resyncs = 0;          // runs of noise skipped to find the next telegram
  std::uint64_t bytes_dropped = 0;    // bytes given up on: noise, bad telegrams, flushes
  std::uint64_t timeouts = 0;         // waits for a telegram (or a write) that ran out of time
  std::uint64_t reconnects = 0;       // successful reopen()s after the first open
  std::uint64_t retries = 0;          // requests sent again because no reply came

  friend bool operator==(const LinkCounterSnapshot&, const LinkCounterSnapshot&) = default;
  // The change between two snapshots (for rates): later - earlier.
  friend LinkCounterSnapshot operator-(const LinkCounterSnapshot& later, const LinkCounterSnapshot& earlier);
};

// "in 1204 B, out 36 B, 12 telegrams, 1 checksum error, 2 resyncs (17 B dropped), 0 timeouts, 0 reconnects, 0 retries"
std::string to_string(const LinkCounterSnapshot& counters);

struct LinkCounters {
  Counter bytes_in;
  Counter bytes_out;
  Counter telegrams;
  Counter checksum_errors;
  Counter resyncs;
  Counter bytes_dropped;
  Counter timeouts;
  Counter reconnects;
  Counter retries;

  [[nodiscard]] LinkCounterSnapshot snapshot() const;
};

}  // namespace playerkit::links
