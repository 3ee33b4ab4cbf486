#pragma once
// How far each reader (a client connection) has taken a queued device's
// samples. The server reports progress as it builds data rounds; a publisher
// that must never overrun a reader's share of the queue (a burst replay:
// `player-log replay --burst`) waits on it instead of dropping samples.
// Thread-safe.

#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <stop_token>

#include "core/exchange.hpp"

namespace playerkit::core {

class ReaderProgress {
 public:
  // Registers `reader` or moves it on. A reader is tracked from before its
  // subscription starts the driver, so it cannot miss the first samples.
  void taken(ClientId reader, std::uint64_t sequence);
  void forget(ClientId reader);
  [[nodiscard]] std::size_t count() const;
  // True once every tracked reader has taken sample `sequence` (at once when
  // there are none); false as soon as `stop` is requested.
  bool wait_until_taken(std::uint64_t sequence, const std::stop_token& stop);
  // True once some reader is tracked; false as soon as `stop` is requested.
  bool wait_for_reader(const std::stop_token& stop);

 private:
  [[nodiscard]] bool all_taken(std::uint64_t sequence) const;

  mutable std::mutex mutex_;
  std::condition_variable_any changed_;
  std::map<ClientId, std::uint64_t> taken_;
};

}  // namespace playerkit::core
