#pragma once
// Talking to the robot's cerebellum over a link (trogdor.md §1.1): each
// message answered by its ACK or NACK, GET_ODOM by the ACK and its block,
// through the kit's exchange (a deadline and a retry where 1.5 waited
// forever once running).

#include <chrono>
#include <functional>
#include <optional>

#include "families/trogdor/protocol/trogdor_messages.hpp"
#include "families/trogdor/protocol/trogdor_reply_format.hpp"
#include "links/byte_link.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::trogdor {

namespace hw = hardware::trogdor;

class Cerebellum {
 public:
  // `link` must outlive it; `stopping` is asked while waiting.
  Cerebellum(links::ByteLink& link, std::function<bool()> stopping);

  // True for ACK, false for NACK. Throws links::ExchangeError (no_reply,
  // stopped); LinkErrors pass through.
  bool tell(const char* name, const hw::Bytes& message);
  // GET_ODOM. A NACK throws links::ExchangeError(refused).
  hw::OdometryReading odometry();

  // INIT (after a NACK: DEINIT and INIT again, as 1.5), then the first
  // odometry reading and the start-up accelerations. Throws on failure.
  hw::OdometryReading start();

  // The robot answers at once; a loaded host may not read it for a while.
  static constexpr std::chrono::milliseconds kReplyTimeout{200};
  // Sends of one message before the robot counts as gone.
  static constexpr int kAttempts = 4;
  // INIT's: a second in all.
  static constexpr int kFirstAttempts = 5;

 private:
  // The reply (ACK first); nothing when the robot NACKed and never ACKed.
  std::optional<hw::Bytes> exchange(const char* name, const hw::Bytes& message, hw::ReplyShape shape,
                                    std::chrono::milliseconds timeout, int attempts);

  hw::TrogdorReplyFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
};

}  // namespace playerkit::drivers::trogdor
