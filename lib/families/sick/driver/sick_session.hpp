#pragma once
// Telegrams to and from a SICK laser over a ByteLink: a request and the
// reply it is waiting for, or the next telegram of the stream. Every wait
// ends at a deadline and looks at a stop flag every few tens of
// milliseconds, so a driver thread never hangs on a silent device (the 1.5
// drivers waited forever for T3-T8).
//
// An idle line costs nothing in the link's counters: the session waits for
// the first byte with poll(2) and only then asks the FramedReader for the
// whole telegram, so `timeouts` counts telegrams that stalled half way and
// requests that got no reply, not quiet moments.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/requests.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "links/byte_link.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::sick_laser {

class SickExchangeError : public std::runtime_error {
 public:
  enum class Kind {
    no_reply,  // nothing (valid) came back in time
    refused,   // 92, or a reply saying no
    stopped,   // the driver is stopping
  };
  SickExchangeError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  [[nodiscard]] Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

class SickSession {
 public:
  using Clock = std::chrono::steady_clock;

  // `link` must outlive the session. `stopping` is asked between waits.
  explicit SickSession(links::ByteLink& link, std::function<bool()> stopping = {});

  // Flushes stale input, sends `request` and returns the first reply with
  // code `expected`; scans and late replies to earlier requests arriving
  // meanwhile are skipped. Throws SickExchangeError: refused for a 92
  // reply, no_reply when nothing fitting comes within `timeout`, stopped.
  // LinkErrors pass through.
  hardware::sick::Reply exchange(const hardware::sick::Request& request, std::uint8_t expected,
                                 Clock::duration timeout);

  // The next valid telegram unframed, or nullopt when none has begun
  // arriving by `deadline`. One that has begun is waited for until it is
  // whole (bounded by the time the longest telegram takes on the line).
  std::optional<hardware::sick::Reply> next_reply(Clock::time_point deadline);
  // The time the last whole telegram was taken from the link.
  [[nodiscard]] Clock::time_point last_arrival() const { return last_arrival_; }

  // Called about every 50 ms while a wait goes on (a driver answering
  // requests from its state while it looks for a lost device).
  void set_idle_callback(std::function<void()> idle) { idle_ = std::move(idle); }

  [[nodiscard]] links::ByteLink& link() { return link_; }

 private:
  // Waits for input up to `until` (in slices); false when none came.
  bool wait_for_input(Clock::time_point until);
  void check_stop() const;

  links::ByteLink& link_;
  hardware::sick::SickFrameFormat format_;
  links::FramedReader reader_;
  std::function<bool()> stopping_;
  std::function<void()> idle_;
  Clock::time_point last_arrival_{};
};

}  // namespace playerkit::drivers::sick_laser
