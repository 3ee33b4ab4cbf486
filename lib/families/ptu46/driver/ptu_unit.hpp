#pragma once
// Talking to a PTU-46 over a link: one command, one reply line (ptu46.md
// §2), with the kit's exchange (a deadline, a retry, counted timeouts), and
// the start-up that reads the unit's resolution and limits. Unlike the
// reference driver, no read waits forever, and a reply ended by CR alone is
// taken as one.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "families/ptu46/protocol/ptu_commands.hpp"
#include "families/ptu46/protocol/ptu_replies.hpp"
#include "framing/terminated_line_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::ptu46 {

namespace ptu = hardware::ptu46;

struct AxisLimits {
  double degrees_per_position = 0;
  std::int64_t min_position = 0;
  std::int64_t max_position = 0;
  std::int64_t lower_speed = 0;  // positions/s
  std::int64_t upper_speed = 0;
};

struct UnitLimits {
  AxisLimits pan;
  AxisLimits tilt;
  [[nodiscard]] const AxisLimits& of(ptu::Axis axis) const { return axis == ptu::Axis::pan ? pan : tilt; }
  // What the reference driver checks before trusting them: a resolution
  // above 0 and no position limit of exactly 0 (ptu46.md §2.2 step 5).
  [[nodiscard]] bool plausible() const;
};

class PtuUnit {
 public:
  // `link` must outlive the unit; `stopping` is asked while waiting.
  PtuUnit(links::ByteLink& link, std::function<bool()> stopping);

  // The reply to `command`. Throws links::ExchangeError (no_reply after
  // kAttempts, stopped); LinkErrors pass through. A refusal ("! ...") is a reply.
  ptu::Reply ask(const ptu::Command& command, std::chrono::milliseconds timeout = kReplyTimeout);

  // Terse feedback, echo off, independent control, then the limits; a unit
  // reporting implausible ones is reset once and asked again. Throws
  // std::runtime_error when they stay implausible.
  UnitLimits start();

  // Lines the unit sent unasked (limit hits "!P", "!T"), dropped: how many.
  std::uint64_t drop_unsolicited();

  static constexpr std::chrono::milliseconds kReplyTimeout{500};
  // Sends of one command before the unit counts as gone: a reply lost to
  // line noise is asked for again.
  static constexpr int kAttempts = 3;
  // A reset drives both axes to their end stops and back.
  static constexpr std::chrono::milliseconds kResetTimeout{30000};

 private:
  UnitLimits read_limits();
  std::int64_t integer(const ptu::Command& command);

  framing::TerminatedLineFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
};

}  // namespace playerkit::drivers::ptu46
