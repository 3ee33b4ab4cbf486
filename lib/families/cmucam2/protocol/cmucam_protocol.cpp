#include "families/cmucam2/protocol/cmucam_protocol.hpp"

#include <cctype>
#include <charconv>

namespace playerkit::hardware::cmucam2 {

namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\r' || text.front() == '\n')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
  return text;
}

// Space-separated decimal integers; nullopt at anything else.
std::optional<std::vector<int>> integers(std::string_view text) {
  std::vector<int> values;
  std::size_t at = 0;
  while (at < text.size()) {
    if (text[at] == ' ') {
      ++at;
      continue;
    }
    int value = 0;
    const auto [end, error] = std::from_chars(text.data() + at, text.data() + text.size(), value);
    if (error != std::errc() || (end != text.data() + text.size() && *end != ' ')) return std::nullopt;
    values.push_back(value);
    at = static_cast<std::size_t>(end - text.data());
  }
  return values;
}

bool byte_range(int value) { return value >= 0 && value <= 255; }

}  // namespace

framing::LineOptions reply_line_options() {
  return {.end = framing::LineEnd::cr,
          .max_length = kLongestLine,
          .prompt = kPrompt,
          .skip_empty_lines = true,
          .name = "cmucam2"};
}

framing::LineOptions command_line_options() {
  return {.end = framing::LineEnd::cr,
          .max_length = kLongestLine,
          .prompt = std::nullopt,
          .skip_empty_lines = false,
          .name = "cmucam2 commands"};
}

bool ColorBounds::valid() const {
  const std::array<std::array<int, 2>, 3> ranges{{{red_min, red_max}, {green_min, green_max}, {blue_min, blue_max}}};
  for (const auto& [low, high] : ranges) {
    if (!byte_range(low) || !byte_range(high) || low > high) return false;
  }
  return true;
}

std::uint32_t ColorBounds::packed_middle() const {
  const auto middle = [](int low, int high) { return static_cast<std::uint32_t>((low + high) / 2) & 0xffu; };
  return middle(red_min, red_max) << 16 | middle(green_min, green_max) << 8 | middle(blue_min, blue_max);
}

std::string poll_mode(bool on) { return on ? "PM 1" : "PM 0"; }

std::string track_color(const ColorBounds& b) {
  std::string text = "TC";
  for (const int value : {b.red_min, b.red_max, b.green_min, b.green_max, b.blue_min, b.blue_max}) {
    text += ' ' + std::to_string(value);
  }
  return text;
}

std::string set_servo(int servo, int position) { return "SV " + std::to_string(servo) + ' ' + std::to_string(position); }
std::string get_servo(int servo) { return "GS " + std::to_string(servo); }
std::string get_version() { return "GV"; }

std::vector<std::uint8_t> encode(std::string_view command) {
  std::vector<std::uint8_t> bytes(command.begin(), command.end());
  bytes.push_back('\r');
  return bytes;
}

ReplyLine classify(std::string_view line) {
  // Line noise may come before a reply; nothing a camera says ends like one.
  const std::string_view text = trimmed(line);
  if (text.ends_with("ACK")) return ReplyLine::ack;
  if (text.ends_with("NCK")) return ReplyLine::nck;
  if (text.size() == 1 && text.front() == kPrompt) return ReplyLine::prompt;
  return ReplyLine::other;
}

std::optional<TPacket> parse_t_packet(std::string_view line) {
  std::string_view text = trimmed(line);
  // The packet starts at the last "T " (noise may come before it).
  const std::size_t start = text.rfind("T ");
  if (start == std::string_view::npos) return std::nullopt;
  text.remove_prefix(start);
  const auto values = integers(text.substr(2));
  if (!values || values->size() != 8) return std::nullopt;
  for (const int value : *values) {
    if (!byte_range(value)) return std::nullopt;
  }
  const auto& v = *values;
  return TPacket{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
}

std::string t_packet_line(const TPacket& p) {
  std::string text = "T";
  for (const int value : {p.mx, p.my, p.x1, p.y1, p.x2, p.y2, p.pixels, p.confidence}) text += ' ' + std::to_string(value);
  return text;
}

std::optional<int> parse_number(std::string_view line) {
  const auto values = integers(trimmed(line));
  if (!values || values->size() != 1) return std::nullopt;
  return values->front();
}

std::optional<ParsedCommand> parse_command(std::string_view text) {
  text = trimmed(text);
  std::size_t end = 0;
  while (end < text.size() && std::isalpha(static_cast<unsigned char>(text[end]))) ++end;
  if (end == 0) return std::nullopt;
  ParsedCommand command;
  for (std::size_t i = 0; i < end; ++i) command.name.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text[i]))));
  if (end < text.size() && text[end] != ' ') return std::nullopt;
  auto arguments = integers(text.substr(end));
  if (!arguments) return std::nullopt;
  command.arguments = std::move(*arguments);
  return command;
}

}  // namespace playerkit::hardware::cmucam2
