#include "links/exchange.hpp"

#include <poll.h>

#include <algorithm>
#include <chrono>
#include <utility>

#include "links/fd_io.hpp"

namespace playerkit::links {

using namespace std::chrono_literals;

namespace {

// How often a wait looks at the stop predicate and calls the idle callback.
constexpr auto kSlice = 50ms;
// A short reply timeout must not starve the write of its request.
constexpr auto kShortestWrite = 100ms;
// Line time is not all: a loaded machine delivers a begun telegram late.
constexpr auto kCompletionSlack = 200ms;
// Bits per byte on the line: start, 8 data, parity, stop (8E1 is the worst).
constexpr std::size_t kBitsPerByte = 11;
// Assumed for a link without a speed of its own (a TCP bridge to a serial device).
constexpr int kSlowestCommonBaud = 9600;

std::string milliseconds(LinkClock::duration duration) {
  return std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(duration).count()) + " ms";
}

}  // namespace

std::vector<std::uint8_t> ExchangeOutcome::reply() && {
  if (failure) throw ExchangeError(*failure, message);
  return std::move(telegram);
}

Exchanger::Exchanger(FramedReader& reader, std::function<bool()> stopping, std::string device)
    : reader_(reader), stopping_(std::move(stopping)), device_(std::move(device)) {}

ExchangeOutcome Exchanger::try_exchange(const ExchangeRequest& request) {
  const int attempts = std::max(1, request.attempts);
  const ExchangeOutcome stopped{ExchangeFailure::stopped, {},
                                "stopped waiting for " + device_ + " to answer " + request.name};
  for (int attempt = 1;; ++attempt) {
    if (stop_requested()) return stopped;
    if (attempt > 1) link().counters().retries.add();
    const Deadline deadline = deadline_in(request.timeout);
    if (request.flush_first) reader_.flush();
    link().write_all(request.bytes, std::max(deadline, deadline_in(kShortestWrite)));
    std::vector<std::uint8_t> telegram;
    for (;;) {
      const Wait waited = wait_for_telegram(deadline, telegram);
      if (waited == Wait::stopped) return stopped;
      if (waited == Wait::silence) break;
      const ReplyMatch match = request.matcher ? request.matcher(telegram) : ReplyMatch::mine;
      if (match == ReplyMatch::mine) return {std::nullopt, std::move(telegram), {}};
      if (match == ReplyMatch::refusal) {
        return {ExchangeFailure::refused, std::move(telegram), device_ + " refused " + request.name};
      }
    }
    link().counters().timeouts.add();
    if (attempt >= attempts) {
      const std::string waited = attempts == 1 ? "within " + milliseconds(request.timeout)
                                               : "in " + std::to_string(attempts) + " tries of " +
                                                     milliseconds(request.timeout);
      return {ExchangeFailure::no_reply, {}, "no reply from " + device_ + " to " + request.name + " " + waited};
    }
  }
}

std::vector<std::uint8_t> Exchanger::exchange(const ExchangeRequest& request) {
  return try_exchange(request).reply();
}

std::optional<std::vector<std::uint8_t>> Exchanger::next(Deadline deadline) {
  std::vector<std::uint8_t> telegram;
  switch (wait_for_telegram(deadline, telegram)) {
    case Wait::telegram: return telegram;
    case Wait::silence: return std::nullopt;
    case Wait::stopped: break;
  }
  throw ExchangeError(ExchangeFailure::stopped, "stopped waiting for " + device_);
}

Exchanger::Wait Exchanger::wait_for_telegram(Deadline deadline, std::vector<std::uint8_t>& telegram) {
  for (;;) {
    const Wait input = wait_for_input(deadline);
    if (input != Wait::telegram) return input;
    // Bytes have come: asking the reader only now keeps an idle line out of
    // the timeouts, and the bound lets a telegram begun just before the
    // deadline finish.
    if (auto whole = reader_.next(deadline_in(completion_time()))) {
      last_arrival_ = LinkClock::now();
      telegram = std::move(*whole);
      return Wait::telegram;
    }
    // Noise, or a telegram that stalled half way (the reader counted it).
    if (LinkClock::now() >= deadline) return Wait::silence;
  }
}

Exchanger::Wait Exchanger::wait_for_input(Deadline until) {
  for (;;) {
    if (stop_requested()) return Wait::stopped;
    if (reader_.buffered() > 0) return Wait::telegram;
    const Deadline now = LinkClock::now();
    if (now >= until) return Wait::silence;
    const int fd = link().native_handle();
    // Readable, hung up or in error alike: the reader's read says which.
    // A closed link (-1) is left to the reader's read to report.
    if (fd < 0 || wait_for_fd(fd, POLLIN, std::min(until, now + kSlice)) != 0) return Wait::telegram;
    if (idle_) idle_();
  }
}

LinkClock::duration Exchanger::completion_time() {
  const int baud = link().baud() > 0 ? link().baud() : kSlowestCommonBaud;
  const auto line = std::chrono::microseconds(reader_.max_telegram() * kBitsPerByte * 1'000'000 /
                                              static_cast<std::size_t>(baud));
  return line + kCompletionSlack;
}

}  // namespace playerkit::links
