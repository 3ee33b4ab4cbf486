#pragma once
// Telegrams to and from a SICK laser: a links::Exchanger that speaks in
// requests and unframed replies. Every wait ends at a deadline and looks at
// the stop flag every few tens of milliseconds, so a driver thread never
// hangs on a silent device (the 1.5 drivers waited forever for T3-T8); an
// idle line costs nothing in the link's counters (links/exchange.hpp).

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>

#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::sick_laser {

// no_reply, refused (a 92 reply), stopped (the driver is stopping).
using SickExchangeError = links::ExchangeError;

class SickSession {
 public:
  using Clock = std::chrono::steady_clock;

  // `link` must outlive the session. `stopping` is asked between waits.
  explicit SickSession(links::ByteLink& link, std::function<bool()> stopping = {});

  // Flushes stale input, sends `request` and returns the first reply with
  // code `expected`; scans and late replies to earlier requests arriving
  // meanwhile are skipped. Sent up to `attempts` times while nothing
  // fitting comes within `timeout`. Throws SickExchangeError; LinkErrors
  // pass through.
  hardware::sick::Reply exchange(const hardware::sick::Request& request, std::uint8_t expected,
                                 Clock::duration timeout, int attempts = 1);

  // The next valid reply, or nullopt when no telegram has begun arriving
  // by `deadline` (links::Exchanger::next).
  std::optional<hardware::sick::Reply> next_reply(Clock::time_point deadline);
  // The time the last whole telegram was taken from the link.
  [[nodiscard]] Clock::time_point last_arrival() const { return exchanger_.last_arrival(); }

  // Called about every 50 ms while a wait goes on (a driver answering
  // requests from its state while it looks for a lost device).
  void set_idle_callback(std::function<void()> idle) { exchanger_.set_idle_callback(std::move(idle)); }

  [[nodiscard]] links::ByteLink& link() { return exchanger_.link(); }

 private:
  hardware::sick::SickFrameFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
};

}  // namespace playerkit::drivers::sick_laser
