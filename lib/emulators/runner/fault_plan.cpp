#include "emulators/runner/fault_plan.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace playerkit::emulators {

namespace {

constexpr FaultKind kKinds[] = {
    {"bad-checksum=P", "each telegram's checksum byte flipped with probability P"},
    {"garbage=P", "1 to 16 random bytes before a telegram with probability P"},
    {"truncate=P", "a telegram cut short with probability P"},
    {"drop=P", "each byte sent lost with probability P"},
    {"silent-start=S", "deaf and mute for the first S seconds"},
    {"slow-start=S", "deaf and mute for S seconds after each time the host opens the line"},
    {"vanish=AT:FOR", "the line dead both ways from AT for FOR seconds, then back"},
    {"seed=N", "the seed of the random choices (default 1)"},
};

std::string kind_list() {
  std::string list;
  for (const FaultKind& kind : kKinds) list += (list.empty() ? "" : ", ") + std::string(kind.argument);
  return list;
}

[[noreturn]] void refuse(std::string_view argument, std::string_view why) {
  throw std::invalid_argument("--fault " + std::string(argument) + ": " + std::string(why) +
                              " (kinds: " + kind_list() + ")");
}

double parse_number(std::string_view argument, std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
    refuse(argument, "'" + std::string(text) + "' is not a number");
  }
  return value;
}

double parse_probability(std::string_view argument, std::string_view text) {
  const double value = parse_number(argument, text);
  if (value < 0.0 || value > 1.0) refuse(argument, "a probability lies between 0 and 1");
  return value;
}

Duration parse_seconds(std::string_view argument, std::string_view text) {
  const double value = parse_number(argument, text);
  if (value < 0.0 || value > 1e6) refuse(argument, "seconds lie between 0 and 1e6");
  return std::chrono::duration_cast<Duration>(std::chrono::duration<double>(value));
}

double seconds(Duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

std::span<const FaultKind> fault_kinds() { return kKinds; }

bool FaultPlan::any() const {
  return bad_checksum > 0 || garbage > 0 || truncate > 0 || drop > 0 || silent_start > Duration::zero() ||
         slow_start > Duration::zero() || vanish_for > Duration::zero();
}

std::string FaultPlan::describe() const {
  std::ostringstream out;
  const char* separator = "";
  const auto item = [&](std::string_view name) -> std::ostream& {
    out << separator << name << '=';
    separator = ", ";
    return out;
  };
  if (bad_checksum > 0) item("bad-checksum") << bad_checksum;
  if (garbage > 0) item("garbage") << garbage;
  if (truncate > 0) item("truncate") << truncate;
  if (drop > 0) item("drop") << drop;
  if (silent_start > Duration::zero()) item("silent-start") << seconds(silent_start);
  if (slow_start > Duration::zero()) item("slow-start") << seconds(slow_start);
  if (vanish_for > Duration::zero()) item("vanish") << seconds(vanish_at) << ':' << seconds(vanish_for);
  return out.str();
}

bool FaultPlan::line_dead(Duration now, std::optional<Duration> host_opened_at) const {
  if (now < silent_start) return true;
  if (host_opened_at && now < *host_opened_at + slow_start) return true;
  return vanish_for > Duration::zero() && now >= vanish_at && now < vanish_at + vanish_for;
}

void add_fault(FaultPlan& plan, std::string_view argument) {
  const std::size_t equals = argument.find('=');
  if (equals == std::string_view::npos) refuse(argument, "expected KIND=VALUE");
  const std::string_view kind = argument.substr(0, equals);
  const std::string_view value = argument.substr(equals + 1);
  if (kind == "bad-checksum") {
    plan.bad_checksum = parse_probability(argument, value);
  } else if (kind == "garbage") {
    plan.garbage = parse_probability(argument, value);
  } else if (kind == "truncate") {
    plan.truncate = parse_probability(argument, value);
  } else if (kind == "drop") {
    plan.drop = parse_probability(argument, value);
  } else if (kind == "silent-start") {
    plan.silent_start = parse_seconds(argument, value);
  } else if (kind == "slow-start") {
    plan.slow_start = parse_seconds(argument, value);
  } else if (kind == "vanish") {
    const std::size_t colon = value.find(':');
    if (colon == std::string_view::npos) refuse(argument, "expected vanish=AT:FOR (seconds)");
    plan.vanish_at = parse_seconds(argument, value.substr(0, colon));
    plan.vanish_for = parse_seconds(argument, value.substr(colon + 1));
    if (plan.vanish_for == Duration::zero()) refuse(argument, "FOR must be above 0");
  } else if (kind == "seed") {
    const double seed = parse_number(argument, value);
    if (seed < 0 || seed != std::floor(seed)) refuse(argument, "a seed is a whole number, 0 or more");
    plan.seed = static_cast<std::uint64_t>(seed);
  } else {
    refuse(argument, "unknown fault '" + std::string(kind) + "'");
  }
}

}  // namespace playerkit::emulators
