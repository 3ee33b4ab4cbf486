#include "families/khepera/protocol/khepera_commands.hpp"

#include <cctype>
#include <charconv>

namespace playerkit::hardware::khepera {

namespace {

std::vector<std::uint8_t> encode(char first, const std::vector<std::int64_t>& values, framing::LineEnd end) {
  std::string text(1, first);
  for (const std::int64_t value : values) text += "," + std::to_string(value);
  return framing::line_bytes(text, end);
}

}  // namespace

Message set_speed(std::int64_t left, std::int64_t right) { return {letter::set_speed, {left, right}}; }
Message read_speed() { return {letter::read_speed, {}}; }
Message set_position(std::int64_t left, std::int64_t right) { return {letter::set_position, {left, right}}; }
Message read_position() { return {letter::read_position, {}}; }
Message read_proximity() { return {letter::read_proximity, {}}; }

std::vector<std::uint8_t> encode_command(const Message& command) {
  return encode(static_cast<char>(std::toupper(static_cast<unsigned char>(command.letter))), command.values,
                framing::LineEnd::lf);
}

std::vector<std::uint8_t> encode_reply(const Message& reply) {
  // cr_or_lf writes CR LF, the robot's line end.
  return encode(static_cast<char>(std::tolower(static_cast<unsigned char>(reply.letter))), reply.values,
                framing::LineEnd::cr_or_lf);
}

std::optional<Message> parse_line(std::string_view text) {
  while (!text.empty() && (text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
  if (text.empty() || std::isalpha(static_cast<unsigned char>(text.front())) == 0) return std::nullopt;
  Message message{text.front(), {}};
  text.remove_prefix(1);
  while (!text.empty()) {
    if (text.front() != ',') return std::nullopt;
    text.remove_prefix(1);
    std::int64_t value = 0;
    const char* begin = text.data();
    const char* end = text.data() + text.size();
    if (begin != end && *begin == '+') ++begin;  // a BIOS may sign positive values
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (error != std::errc{} || stop == begin) return std::nullopt;
    message.values.push_back(value);
    text.remove_prefix(static_cast<std::size_t>(stop - text.data()));
  }
  return message;
}

std::optional<Message> parse_reply_to(char command, std::string_view text, std::optional<std::size_t> count) {
  auto reply = parse_line(text);
  const char expected = static_cast<char>(std::tolower(static_cast<unsigned char>(command)));
  if (!reply || reply->letter != expected) return std::nullopt;
  if (count && reply->values.size() != *count) return std::nullopt;
  return reply;
}

std::optional<Message> find_reply_to(char command, std::string_view text, std::optional<std::size_t> count) {
  const char expected = static_cast<char>(std::tolower(static_cast<unsigned char>(command)));
  for (std::size_t at = text.find(expected); at != std::string_view::npos; at = text.find(expected, at + 1)) {
    if (auto reply = parse_reply_to(command, text.substr(at), count)) return reply;
  }
  return std::nullopt;
}

framing::LineOptions reply_line_options() {
  return {.end = framing::LineEnd::cr_or_lf,
          .max_length = kLongestLine,
          .prompt = std::nullopt,
          .skip_empty_lines = true,
          .name = "khepera"};
}

framing::LineOptions command_line_options() {
  framing::LineOptions options = reply_line_options();
  options.name = "khepera commands";
  return options;
}

}  // namespace playerkit::hardware::khepera
