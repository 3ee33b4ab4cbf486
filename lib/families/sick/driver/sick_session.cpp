#include "families/sick/driver/sick_session.hpp"

#include "families/sick/protocol/codes.hpp"

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;

namespace {

// The longest telegram: STX, address, LEN, 1024 body bytes, CRC.
constexpr std::size_t kMaxTelegram = sick::kHeaderSize + sick::kMaxBodyLength + sick::kCrcSize;

// The reply with `expected`; 92 says no. A scan sent before the request
// stopped the stream, or a late reply to an earlier request, is not it.
links::ReplyMatch judge(std::span<const std::uint8_t> telegram, std::uint8_t expected) {
  try {
    const std::uint8_t code = sick::unframe_reply(telegram).code;
    if (code == expected) return links::ReplyMatch::mine;
    if (code == sick::kNotAcknowledged) return links::ReplyMatch::refusal;
  } catch (const sick::TelegramError&) {
    // The format already checked STX, address, LEN and CRC; a reply too
    // short for code and status is noise like any other.
  }
  return links::ReplyMatch::not_mine;
}

}  // namespace

SickSession::SickSession(links::ByteLink& link, std::function<bool()> stopping)
    : format_(sick::SickFrameFormat::replies()),
      reader_(link, format_, kMaxTelegram),
      exchanger_(reader_, std::move(stopping), "the laser") {}

sick::Reply SickSession::exchange(const sick::Request& request, std::uint8_t expected, Clock::duration timeout,
                                  int attempts) {
  return sick::unframe_reply(exchanger_.exchange(
      {.name = sick::describe(request),
       .bytes = sick::encode_request(request),
       .matcher = [expected](std::span<const std::uint8_t> telegram) { return judge(telegram, expected); },
       .timeout = timeout,
       .attempts = attempts}));
}

std::optional<sick::Reply> SickSession::next_reply(Clock::time_point deadline) {
  while (auto telegram = exchanger_.next(deadline)) {
    try {
      return sick::unframe_reply(*telegram);
    } catch (const sick::TelegramError&) {
      // Framed right but too short for a reply: noise.
    }
  }
  return std::nullopt;
}

}  // namespace playerkit::drivers::sick_laser
