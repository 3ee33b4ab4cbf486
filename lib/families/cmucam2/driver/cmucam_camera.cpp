#include "families/cmucam2/driver/cmucam_camera.hpp"

#include <optional>

namespace playerkit::drivers::cmucam2 {

namespace {

// What comes after an ACK: `lines` data lines, then (unless `prompt` is
// false) the prompt. Before the ACK, anything (a late packet, a stray
// prompt) is someone else's.
struct ReplyShape {
  int lines = 0;
  bool prompt = true;
  // A data line it does not accept (cut short, or noise) is not the reply:
  // the exchange asks again.
  std::function<bool(std::string_view)> accept = [](std::string_view) { return true; };
};

links::ReplyMatcher matcher_for(ReplyShape shape, std::string& data) {
  return [shape, &data, acked = false, lines = 0](std::span<const std::uint8_t> telegram) mutable {
    const std::string_view text = framing::line_text(telegram);
    const cam::ReplyLine kind = cam::classify(text);
    if (!acked) {
      if (kind == cam::ReplyLine::nck) return links::ReplyMatch::refusal;
      // An ACK cut short by line noise: the data line it announced still
      // proves the command was taken (the input was flushed before sending).
      if (kind == cam::ReplyLine::other && shape.lines == 1 && shape.accept(text)) {
        acked = true;
        data = std::string(text);
        lines = 1;
        return shape.prompt ? links::ReplyMatch::not_mine : links::ReplyMatch::mine;
      }
      acked = kind == cam::ReplyLine::ack;
      return acked && shape.lines == 0 && !shape.prompt ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
    }
    if (lines < shape.lines) {
      if (kind != cam::ReplyLine::other || !shape.accept(text)) return links::ReplyMatch::not_mine;
      data = std::string(text);
      ++lines;
      return lines == shape.lines && !shape.prompt ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
    }
    return kind == cam::ReplyLine::prompt ? links::ReplyMatch::mine : links::ReplyMatch::not_mine;
  };
}

}  // namespace

CmucamCamera::CmucamCamera(links::ByteLink& link, std::function<bool()> stopping)
    : format_(cam::reply_line_options()),
      reader_(link, format_, cam::kLongestLine),
      exchanger_(reader_, std::move(stopping), "the camera") {}

void CmucamCamera::command(const std::string& text) {
  std::string ignored;
  exchanger_.exchange({.name = text.empty() ? "CR (idle)" : "'" + text + "'",
                       .bytes = cam::encode(text),
                       .matcher = matcher_for({.lines = 0, .prompt = true}, ignored),
                       .timeout = kReplyTimeout,
                       .attempts = kAttempts});
}

std::string CmucamCamera::query(const std::string& text, std::function<bool(std::string_view)> accept) {
  std::string line;
  exchanger_.exchange({.name = "'" + text + "'",
                       .bytes = cam::encode(text),
                       .matcher = matcher_for({.lines = 1, .prompt = true, .accept = std::move(accept)}, line),
                       .timeout = kReplyTimeout,
                       .attempts = kAttempts});
  return line;
}

cam::TPacket CmucamCamera::track(const cam::ColorBounds& bounds) {
  std::string line;
  const std::string text = cam::track_color(bounds);
  exchanger_.exchange({.name = "'" + text + "'",
                       .bytes = cam::encode(text),
                       .matcher = matcher_for({.lines = 1,
                                               .prompt = false,
                                               .accept = [](std::string_view data) {
                                                 return cam::parse_t_packet(data).has_value();
                                               }},
                                              line),
                       .timeout = kReplyTimeout,
                       .attempts = kAttempts});
  const std::optional<cam::TPacket> packet = cam::parse_t_packet(line);
  // Whatever follows (a prompt, or nothing) is ended by the CR's own reply.
  idle();
  if (!packet) throw links::ExchangeError(links::ExchangeFailure::no_reply, "the camera answered '" + text + "' with '" + line + "', not a T packet");
  return *packet;
}

}  // namespace playerkit::drivers::cmucam2
