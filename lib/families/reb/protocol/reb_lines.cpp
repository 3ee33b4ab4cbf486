#include "families/reb/protocol/reb_lines.hpp"

#include <cctype>
#include <charconv>

namespace playerkit::hardware::reb {

namespace {

// "L,1,-2" or "l,1,-2": a letter, then integers each behind a comma.
std::optional<std::pair<char, std::vector<std::int32_t>>> split_line(std::string_view line) {
  if (line.empty() || std::isalpha(static_cast<unsigned char>(line.front())) == 0) return std::nullopt;
  const char letter = line.front();
  std::vector<std::int32_t> numbers;
  std::string_view rest = line.substr(1);
  while (!rest.empty()) {
    if (rest.front() != ',') return std::nullopt;
    rest.remove_prefix(1);
    std::int32_t value = 0;
    const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), value);
    if (error != std::errc{}) return std::nullopt;
    numbers.push_back(value);
    rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
  }
  return std::pair{letter, std::move(numbers)};
}

Command make(char letter, std::vector<std::int32_t> arguments) { return {letter, std::move(arguments)}; }
std::int32_t number(Motor motor) { return static_cast<std::int32_t>(motor); }

}  // namespace

std::vector<std::uint8_t> encode(const Command& command) {
  std::string text(1, command.letter);
  for (const std::int32_t argument : command.arguments) text += "," + std::to_string(argument);
  text += '\r';
  return {text.begin(), text.end()};
}

std::optional<Command> parse_command(std::string_view line) {
  auto split = split_line(line);
  if (!split || std::isupper(static_cast<unsigned char>(split->first)) == 0) return std::nullopt;
  return Command{split->first, std::move(split->second)};
}

std::string reply_text(const Reply& reply) {
  std::string text(1, reply.letter);
  for (const std::int32_t value : reply.values) text += "," + std::to_string(value);
  return text;
}

std::optional<Reply> parse_reply(std::string_view line) {
  auto split = split_line(line);
  if (!split || std::islower(static_cast<unsigned char>(split->first)) == 0) return std::nullopt;
  return Reply{split->first, std::move(split->second)};
}

std::optional<Reply> find_reply(std::string_view line, char letter) {
  for (std::size_t at = line.find(letter); at != std::string_view::npos; at = line.find(letter, at + 1)) {
    if (auto reply = parse_reply(line.substr(at))) return reply;
  }
  return std::nullopt;
}

bool is_prompt(std::string_view line) { return !line.empty() && line.back() == ':'; }

char reply_letter(char command_letter) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(command_letter)));
}

Command set_speed(Motor motor, std::int32_t pulses_per_10ms) { return make('D', {number(motor), pulses_per_10ms}); }
Command read_speed(Motor motor) { return make('E', {number(motor)}); }
Command move_to(Motor motor, std::int32_t position) { return make('C', {number(motor), position}); }
Command set_position(Motor motor, std::int32_t position) { return make('G', {number(motor), position}); }
Command read_position(Motor motor) { return make('H', {number(motor)}); }
Command read_motion_status(Motor motor) { return make('K', {number(motor)}); }
Command speed_pid(Motor motor, std::int32_t kp, std::int32_t ki, std::int32_t kd) {
  return make('A', {number(motor), kp, ki, kd});
}
Command position_pid(Motor motor, std::int32_t kp, std::int32_t ki, std::int32_t kd) {
  return make('F', {number(motor), kp, ki, kd});
}
Command speed_profile(Motor motor, std::int32_t speed, std::int32_t acceleration) {
  return make('J', {number(motor), speed, acceleration});
}
Command read_analog(int channel) { return make('I', {channel}); }
Command read_ir() { return make('W', {}); }
Command ir_power(bool on) { return make('Y', {on ? 1 : 0}); }

framing::LineOptions reply_line_options() {
  return {.end = framing::LineEnd::cr_or_lf,
          .max_length = kLongestLine,
          .prompt = std::nullopt,
          .skip_empty_lines = true,
          .name = "reb"};
}

framing::LineOptions command_line_options() {
  return {.end = framing::LineEnd::cr,
          .max_length = kLongestLine,
          .prompt = std::nullopt,
          .skip_empty_lines = true,
          .name = "reb"};
}

}  // namespace playerkit::hardware::reb
