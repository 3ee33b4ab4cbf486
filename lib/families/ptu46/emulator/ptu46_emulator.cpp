#include "families/ptu46/emulator/ptu46_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "families/ptu46/protocol/ptu_replies.hpp"

namespace playerkit::emulators {

namespace ptu = hardware::ptu46;
using namespace std::chrono_literals;

namespace {

// How often the axes' motion is worked out while they move.
constexpr Duration kMotionStep = 10ms;

bool is_delimiter(std::uint8_t byte) { return byte == ' ' || byte == '\r' || byte == '\n'; }

std::string with_line_end(std::string line) { return line + "\r\n"; }

void check(bool holds, const std::string& what) {
  if (!holds) throw std::invalid_argument("ptu46 emulator: " + what);
}

}  // namespace

Ptu46Emulator::Ptu46Emulator(Ptu46EmulatorOptions options) : options_(options), echo_(options.echo_at_power_up) {
  check(options_.resolution_arc_seconds > 0, "the resolution must be above 0 arc-seconds");
  // The reference driver resets a unit that reports a limit of exactly 0 (ptu46.md §6.5).
  check(options_.pan_min < 0 && options_.pan_max > 0, "the pan limits must be below and above 0");
  check(options_.tilt_min < 0 && options_.tilt_max > 0, "the tilt limits must be below and above 0");
  check(options_.lower_speed >= 0 && options_.lower_speed < options_.upper_speed,
        "the speed limits must satisfy 0 <= lower < upper");
  check(options_.start_speed >= options_.lower_speed && options_.start_speed <= options_.upper_speed,
        "the power-up speed must lie within the speed limits");
  state(Axis::pan) = {.speed = options_.start_speed, .min = options_.pan_min, .max = options_.pan_max};
  state(Axis::tilt) = {.speed = options_.start_speed, .min = options_.tilt_min, .max = options_.tilt_max};
}

void Ptu46Emulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);  // queries report where the axes are now
  std::string echoed;
  for (const std::uint8_t byte : bytes) {
    if (echo_) echoed.push_back(static_cast<char>(byte));
    if (!is_delimiter(byte)) {
      // A runaway line without delimiters is cut, as the unit's buffer is.
      if (typed_.size() < 64) typed_.push_back(static_cast<char>(byte));
      continue;
    }
    if (!echoed.empty()) {
      output_.push_back({std::vector<std::uint8_t>(echoed.begin(), echoed.end()), false});
      echoed.clear();
    }
    const std::string text = std::move(typed_);
    typed_.clear();
    if (!text.empty()) execute(text);
  }
  if (!echoed.empty()) output_.push_back({std::vector<std::uint8_t>(echoed.begin(), echoed.end()), false});
}

void Ptu46Emulator::execute(const std::string& text) {
  ++commands_;
  const auto command = ptu::parse_command(text);
  reply(command ? answer(*command) : ptu::refusal_line("Illegal Command"));
}

void Ptu46Emulator::reply(const std::string& line) {
  if (line.empty()) return;
  const std::string bytes = with_line_end(line);
  output_.push_back({std::vector<std::uint8_t>(bytes.begin(), bytes.end()), false});
}

std::string Ptu46Emulator::answer(const ptu::ParsedCommand& command) {
  const std::string& name = command.name;
  const bool bare = !command.argument.has_value();
  if (name.size() == 2 && (name[0] == 'p' || name[0] == 't')) {
    return axis_command(name[0] == 'p' ? Axis::pan : Axis::tilt, name[1], command);
  }
  if (!bare) return ptu::refusal_line("Illegal Command");
  if (name == "ft" || name == "fv") {
    terse_ = name == "ft";
    return ptu::done_line();
  }
  if (name == "ee" || name == "ed") {
    echo_ = name == "ee";
    return ptu::done_line();
  }
  if (name == "ci" || name == "cv") {
    const ControlMode wanted = name == "ci" ? ControlMode::independent : ControlMode::pure_velocity;
    if (wanted != mode_) {
      // Switching holds both axes where they are: a velocity left over from
      // CV must not become a target speed in CI, nor the reverse.
      for (AxisState& axis : axes_) {
        axis.target = std::llround(axis.position);
        axis.speed = wanted == ControlMode::pure_velocity ? 0 : options_.start_speed;
      }
      mode_ = wanted;
    }
    return ptu::done_line();
  }
  if (name == "r") {
    for (AxisState& axis : axes_) {
      axis.position = 0;
      axis.target = 0;
    }
    return ptu::reset_line();
  }
  return ptu::refusal_line("Illegal Command");
}

std::string Ptu46Emulator::axis_command(Axis axis, char quantity, const ptu::ParsedCommand& command) {
  AxisState& s = state(axis);
  const std::string axis_text(ptu::axis_name(axis));
  const std::optional<std::int64_t> argument = command.argument;
  switch (quantity) {
    case 'p':
      if (!argument) return value(axis, "position", static_cast<double>(std::llround(s.position)));
      if (mode_ == ControlMode::pure_velocity) return ptu::refusal_line("Position commands need independent control (CI)");
      if (*argument > s.max) return ptu::refusal_line("Maximum allowable " + axis_text + " position is " + std::to_string(s.max));
      if (*argument < s.min) return ptu::refusal_line("Minimum allowable " + axis_text + " position is " + std::to_string(s.min));
      s.target = *argument;
      return ptu::done_line();
    case 's': {
      if (!argument) return value(axis, "speed", static_cast<double>(s.speed));
      const std::int64_t magnitude = *argument < 0 ? -*argument : *argument;
      if (*argument < 0 && mode_ == ControlMode::independent) {
        return ptu::refusal_line("Negative speeds need pure velocity control (CV)");
      }
      if (magnitude > options_.upper_speed) {
        return ptu::refusal_line("Maximum allowable " + axis_text + " speed is " + std::to_string(options_.upper_speed));
      }
      // In CV, 0 stops the axis whatever the lower limit.
      if (magnitude < options_.lower_speed && !(mode_ == ControlMode::pure_velocity && magnitude == 0)) {
        return ptu::refusal_line("Minimum allowable " + axis_text + " speed is " + std::to_string(options_.lower_speed));
      }
      s.speed = *argument;
      return ptu::done_line();
    }
    default:
      break;
  }
  if (argument) return ptu::refusal_line("Illegal Command");
  switch (quantity) {
    case 'r': return value(axis, "resolution in seconds arc per position", options_.resolution_arc_seconds);
    case 'n': return value(axis, "minimum position", static_cast<double>(s.min));
    case 'x': return value(axis, "maximum position", static_cast<double>(s.max));
    case 'l': return value(axis, "lower speed limit", static_cast<double>(options_.lower_speed));
    case 'u': return value(axis, "upper speed limit", static_cast<double>(options_.upper_speed));
    default: return ptu::refusal_line("Illegal Command");
  }
}

std::string Ptu46Emulator::value(Axis axis, std::string_view what, double number) const {
  if (terse_) return ptu::value_line(number);
  // Verbose feedback: the sheet fixes only the terse form, which every driver
  // selects; the verbose text is ours and also ends in the number.
  return "* Current " + std::string(ptu::axis_name(axis)) + " " + std::string(what) + " is " +
         ptu::value_line(number).substr(2);
}

void Ptu46Emulator::advance(Duration now) {
  if (now <= now_) return;
  const double seconds = std::chrono::duration<double>(now - now_).count();
  now_ = now;
  for (AxisState& axis : axes_) {
    if (mode_ == ControlMode::pure_velocity) {
      axis.position = std::clamp(axis.position + static_cast<double>(axis.speed) * seconds,
                                 static_cast<double>(axis.min), static_cast<double>(axis.max));
      continue;
    }
    const double to_go = static_cast<double>(axis.target) - axis.position;
    const double step = static_cast<double>(axis.speed < 0 ? -axis.speed : axis.speed) * seconds;
    axis.position = std::fabs(to_go) <= step ? static_cast<double>(axis.target)
                                             : axis.position + std::copysign(step, to_go);
  }
}

bool Ptu46Emulator::moving() const {
  return std::any_of(axes_.begin(), axes_.end(), [this](const AxisState& axis) {
    if (mode_ == ControlMode::pure_velocity) {
      return (axis.speed > 0 && axis.position < static_cast<double>(axis.max)) ||
             (axis.speed < 0 && axis.position > static_cast<double>(axis.min));
    }
    return axis.speed != 0 && axis.position != static_cast<double>(axis.target);
  });
}

Duration Ptu46Emulator::next_deadline() const { return moving() ? now_ + kMotionStep : Duration::max(); }

std::vector<Telegram> Ptu46Emulator::take_output() { return std::exchange(output_, {}); }

std::string Ptu46Emulator::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "PTU-46, pan %lld tilt %lld positions, %s, %s feedback%s",
                static_cast<long long>(std::llround(position(Axis::pan))),
                static_cast<long long>(std::llround(position(Axis::tilt))),
                mode_ == ControlMode::independent ? "independent control" : "pure velocity control",
                terse_ ? "terse" : "verbose", moving() ? ", moving" : "");
  return text;
}

}  // namespace playerkit::emulators
