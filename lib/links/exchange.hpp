#pragma once
// One request and its reply over a FramedReader, the loop every device
// driver needs and none should write again:
//
//   links::Exchanger exchanger(reader, [&] { return stop.stop_requested(); }, "the robot");
//   const auto reply = exchanger.exchange({.name = "SYNC0",
//                                          .bytes = command_frame(Command::plain(command::sync0)),
//                                          .matcher = is_sync0_echo,  // mine, refusal or not_mine
//                                          .timeout = 250ms,
//                                          .attempts = 2});
//
// It sends the request (after dropping stale input), waits for the
// telegram the matcher calls the reply, skipping what the matcher says is
// not (a scan of a streaming device, a late reply to an earlier request),
// and sends again while attempts remain. Noise and bad checksums are the
// reader's business (counted as resyncs and checksum errors).
//
// Waiting looks at the stop predicate every 50 ms or sooner, on poll(2)
// slices rather than a sleep loop, and calls the idle callback after each
// quiet slice (a driver answering its clients while the device is silent).
//
// Counting, in the link's counters: one `timeouts` per attempt left without
// a reply, one `retries` per request sent again, and a telegram that stalled
// half way counts a timeout in the reader; a line that is merely idle while
// next() waits counts nothing.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "links/byte_link.hpp"
#include "links/deadline.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::links {

// What a matcher says of one whole telegram received while waiting.
enum class ReplyMatch {
  mine,      // the reply to this request
  refusal,   // the device answered this request, and the answer is no
  not_mine,  // anything else: keep waiting
};

using ReplyMatcher = std::function<ReplyMatch(std::span<const std::uint8_t> telegram)>;

struct ExchangeRequest {
  // Names the request in failure messages: "SYNC0", "T1 installation mode".
  std::string name;
  // The whole request as it goes on the line.
  std::vector<std::uint8_t> bytes;
  // Judges each telegram; without one, the first telegram is the reply.
  // What it throws passes through the exchange.
  ReplyMatcher matcher;
  // How long each attempt waits for its reply.
  LinkClock::duration timeout{};
  // Sends in all, at least 1. Only silence leads to another: a refusal is
  // an answer.
  int attempts = 1;
  // Before each send, drop what is buffered and pending: nothing received
  // earlier answers this request. Off for a request that follows an
  // answered one closely (its reply may already be on its way).
  bool flush_first = true;
};

// What is left until `deadline`, never negative: a timeout for an exchange
// that must end by a deadline the caller already has.
inline LinkClock::duration time_until(Deadline deadline) {
  return std::max(deadline - LinkClock::now(), LinkClock::duration::zero());
}

enum class ExchangeFailure {
  no_reply,  // every attempt's wait ended without the reply
  refused,   // the matcher called a telegram a refusal
  stopped,   // the stop predicate said so
};

class ExchangeError : public std::runtime_error {
 public:
  using Kind = ExchangeFailure;
  ExchangeError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  [[nodiscard]] Kind kind() const { return kind_; }

 private:
  Kind kind_;
};

// An exchange's end as a value, for callers to whom silence is an ordinary
// answer (a probe, a handshake trying speeds).
struct ExchangeOutcome {
  std::optional<ExchangeFailure> failure;  // none: the reply came
  std::vector<std::uint8_t> telegram;      // the reply or the refusal; empty otherwise
  std::string message;                     // on failure: what happened, naming the request

  [[nodiscard]] bool replied() const { return !failure.has_value(); }
  // The reply; a failure is thrown as an ExchangeError carrying `message`.
  [[nodiscard]] std::vector<std::uint8_t> reply() &&;
};

class Exchanger {
 public:
  // `reader` must outlive the exchanger, which shares it with any other
  // user of the reader on the same thread. `stopping` may be empty.
  // `device` names the other end in messages ("the laser", "the robot").
  explicit Exchanger(FramedReader& reader, std::function<bool()> stopping = {}, std::string device = "the device");

  // Sends the request and returns how it ended. LinkErrors pass through
  // (disconnected, a write that timed out).
  ExchangeOutcome try_exchange(const ExchangeRequest& request);
  // The reply, or throws ExchangeError.
  std::vector<std::uint8_t> exchange(const ExchangeRequest& request);

  // The next whole telegram, or nullopt when none has begun arriving by
  // `deadline` (an idle line is not a timeout). One that has begun is
  // waited for until it is whole, at most as long as the longest telegram
  // takes on the line. Throws ExchangeError(stopped); LinkErrors pass through.
  std::optional<std::vector<std::uint8_t>> next(Deadline deadline);

  // When the last whole telegram was taken from the link.
  [[nodiscard]] LinkClock::time_point last_arrival() const { return last_arrival_; }

  // Called after each quiet slice of a wait (about every 50 ms); empty removes it.
  void set_idle_callback(std::function<void()> idle) { idle_ = std::move(idle); }

  FramedReader& reader() { return reader_; }
  ByteLink& link() { return reader_.link(); }

 private:
  enum class Wait { telegram, silence, stopped };
  // Waits for a whole telegram as next() does, reporting a stop as a value.
  Wait wait_for_telegram(Deadline deadline, std::vector<std::uint8_t>& telegram);
  // Waits for the first byte, slice by slice: `telegram` once input is there.
  Wait wait_for_input(Deadline until);
  [[nodiscard]] bool stop_requested() const { return stopping_ && stopping_(); }
  [[nodiscard]] LinkClock::duration completion_time();

  FramedReader& reader_;
  std::function<bool()> stopping_;
  std::string device_;
  std::function<void()> idle_;
  LinkClock::time_point last_arrival_{};
};

}  // namespace playerkit::links
