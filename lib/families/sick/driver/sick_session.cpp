#include "families/sick/driver/sick_session.hpp"

#include <poll.h>

#include <algorithm>
#include <cerrno>

#include "families/sick/protocol/codes.hpp"

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;
using namespace std::chrono_literals;

namespace {

constexpr auto kSlice = 50ms;
// The longest telegram: STX, address, LEN, 1024 body bytes, CRC.
constexpr std::size_t kMaxTelegram = sick::kHeaderSize + sick::kMaxBodyLength + sick::kCrcSize;

// How long a telegram that has begun may take to arrive whole: the longest
// one at the line's speed (9600 when it has none, a TCP bridge), plus slack
// for a loaded machine.
SickSession::Clock::duration completion_time(const links::ByteLink& link) {
  const int baud = link.baud() > 0 ? link.baud() : 9600;
  const auto line = std::chrono::microseconds(kMaxTelegram * 11 * 1'000'000 / static_cast<std::size_t>(baud));
  return line + 200ms;
}

}  // namespace

SickSession::SickSession(links::ByteLink& link, std::function<bool()> stopping)
    : link_(link),
      format_(sick::SickFrameFormat::replies()),
      reader_(link_, format_, kMaxTelegram),
      stopping_(std::move(stopping)) {}

void SickSession::check_stop() const {
  if (stopping_ && stopping_()) {
    throw SickExchangeError(SickExchangeError::Kind::stopped, "the driver is stopping");
  }
}

bool SickSession::wait_for_input(Clock::time_point until) {
  for (;;) {
    check_stop();
    if (reader_.buffered() > 0) return true;
    const auto now = Clock::now();
    if (now >= until) return false;
    const auto slice = std::min<Clock::duration>(until - now, kSlice);
    pollfd watched{link_.native_handle(), POLLIN, 0};
    const int timeout_ms =
        static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(slice).count());
    const int ready = watched.fd < 0 ? 1 : ::poll(&watched, 1, timeout_ms);
    // Readable, hung up or in error: the read inside the reader tells which.
    if (ready > 0) return true;
    if (ready < 0 && errno != EINTR) return true;
    if (idle_) idle_();
  }
}

std::optional<sick::Reply> SickSession::next_reply(Clock::time_point deadline) {
  while (wait_for_input(deadline)) {
    auto telegram = reader_.next(Clock::now() + completion_time(link_));
    if (!telegram) {
      if (Clock::now() >= deadline) return std::nullopt;
      continue;
    }
    last_arrival_ = Clock::now();
    try {
      return sick::unframe_reply(*telegram);
    } catch (const sick::TelegramError&) {
      // The format already checked STX, address, LEN and CRC; a reply too
      // short for code and status is noise like any other.
      continue;
    }
  }
  return std::nullopt;
}

sick::Reply SickSession::exchange(const sick::Request& request, std::uint8_t expected,
                                  Clock::duration timeout) {
  check_stop();
  const auto deadline = Clock::now() + timeout;
  // What is still buffered answers nothing we are about to ask.
  reader_.flush();
  link_.write_all(sick::encode_request(request), deadline);
  while (auto reply = next_reply(deadline)) {
    if (reply->code == expected) return *reply;
    if (reply->code == sick::kNotAcknowledged) {
      throw SickExchangeError(SickExchangeError::Kind::refused,
                              "the laser refused " + sick::describe(request) + " (reply 92)");
    }
    // A scan sent before the request stopped the stream, or a late reply
    // to an earlier request: not the answer.
  }
  link_.counters().timeouts.add();
  throw SickExchangeError(SickExchangeError::Kind::no_reply,
                          "no reply to " + sick::describe(request) + " within " +
                              std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(timeout).count()) +
                              " ms");
}

}  // namespace playerkit::drivers::sick_laser
