#include "families/ptu46/protocol/ptu_commands.hpp"

#include <cctype>
#include <charconv>

namespace playerkit::hardware::ptu46 {

namespace {

char quantity_letter(Quantity quantity) {
  switch (quantity) {
    case Quantity::position: return 'p';
    case Quantity::speed: return 's';
    case Quantity::resolution: return 'r';
    case Quantity::min_position: return 'n';
    case Quantity::max_position: return 'x';
    case Quantity::lower_speed: return 'l';
    case Quantity::upper_speed: return 'u';
  }
  return '?';
}

Command two_letters(Axis axis, Quantity quantity) {
  return {std::string{axis_letter(axis), quantity_letter(quantity)}};
}

}  // namespace

char axis_letter(Axis axis) { return axis == Axis::pan ? 'p' : 't'; }

std::string_view axis_name(Axis axis) { return axis == Axis::pan ? "Pan" : "Tilt"; }

Command query(Axis axis, Quantity quantity) { return two_letters(axis, quantity); }

Command set_position(Axis axis, std::int64_t positions) {
  Command command = two_letters(axis, Quantity::position);
  command.text += std::to_string(positions);
  return command;
}

Command set_speed(Axis axis, std::int64_t positions_per_second) {
  Command command = two_letters(axis, Quantity::speed);
  command.text += std::to_string(positions_per_second);
  return command;
}

Command set_control_mode(ControlMode mode) { return {mode == ControlMode::independent ? "ci" : "cv"}; }
Command terse_feedback() { return {"ft"}; }
Command echo_off() { return {"ed"}; }
Command reset() { return {"r"}; }
Command empty() { return {""}; }

std::vector<std::uint8_t> encode(const Command& command) {
  std::vector<std::uint8_t> bytes(command.text.begin(), command.text.end());
  bytes.push_back(' ');
  return bytes;
}

std::optional<ParsedCommand> parse_command(std::string_view text) {
  ParsedCommand parsed;
  std::size_t at = 0;
  while (at < text.size() && std::isalpha(static_cast<unsigned char>(text[at])) != 0) {
    parsed.name += static_cast<char>(std::tolower(static_cast<unsigned char>(text[at])));
    ++at;
  }
  if (parsed.name.empty()) return std::nullopt;
  if (at == text.size()) return parsed;
  std::int64_t value = 0;
  const char* first = text.data() + at;
  const char* last = text.data() + text.size();
  if (*first == '+') ++first;  // "+583": from_chars takes only a minus
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last) return std::nullopt;
  parsed.argument = value;
  return parsed;
}

}  // namespace playerkit::hardware::ptu46
