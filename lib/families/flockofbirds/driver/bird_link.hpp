#pragma once
// Talking to a Flock of Birds over a link (flockofbirds.md §2): the start-up
// that stops whatever the bird was doing, asks its position scaling and
// starts its stream, and the records of the stream as they come. Unlike the
// reference driver, every wait has a deadline and the scaling is known
// before the first record is read.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>

#include "families/flockofbirds/protocol/bird_commands.hpp"
#include "families/flockofbirds/protocol/bird_record.hpp"
#include "framing/fixed_length_format.hpp"
#include "framing/phasing_bit_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::flockofbirds {

namespace fob = hardware::flockofbirds;

class BirdLink {
 public:
  // `link` must outlive this; `stopping` is asked while waiting.
  BirdLink(links::ByteLink& link, std::function<bool()> stopping);

  // POINT (which also ends a stream left running) answered by a record,
  // the line left to go quiet, POSITION/ANGLES, EXAMINE VALUE 3, STREAM.
  // Throws links::ExchangeError (no_reply, stopped) or std::runtime_error
  // (a bird that will not stop streaming, a scaling it cannot have);
  // LinkErrors pass through.
  fob::PositionScaling start();

  // The records that have arrived, without waiting for more (a record
  // begun stays buffered for the next call): how many, and the newest.
  // Each call counts one timeout on the link.
  struct Arrivals {
    std::uint64_t count = 0;
    std::optional<fob::RecordWords> newest;
  };
  Arrivals arrivals();

  // POINT: the stream ends (the one record it answers is left on the line).
  void stop();

  static constexpr std::chrono::milliseconds kReplyTimeout{500};
  static constexpr int kAttempts = 3;
  // How long a bird that was streaming may take to fall quiet after POINT:
  // records already under way, at 2400 baud 50 ms each.
  static constexpr std::chrono::milliseconds kSettleLimit{400};
  static constexpr std::chrono::milliseconds kQuietGap{60};

 private:
  void send(const std::vector<std::uint8_t>& bytes);
  void wait_until_quiet();

  framing::PhasingBitFormat record_format_;
  framing::FixedLengthFormat value_format_;
  links::FramedReader record_reader_;
  links::FramedReader value_reader_;
  links::Exchanger records_exchanger_;
  links::Exchanger value_exchanger_;
};

}  // namespace playerkit::drivers::flockofbirds
