#include "log/log_clock_reader.hpp"

#include <iostream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <utility>
#include <variant>

#include "log/carmen_log_reader.hpp"
#include "log/log_format_detection.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"

namespace playerkit::log {
namespace {

struct WarningState {
  std::mutex mutex;
  LogClockWarningHandler handler = [](const std::string& warning) { std::cerr << warning << '\n'; };
  std::set<std::string> reported;  // "path\nwarning"
};

WarningState& warning_state() {
  static WarningState state;
  return state;
}

}  // namespace

std::vector<double> read_log_times(const std::filesystem::path& path) {
  const LogFormat format = detect_log_format(path);
  auto in = open_log_input(path);
  std::vector<double> times;
  if (format == LogFormat::kPlayer) {
    TextLogReader reader(*in, path.string());
    while (auto line = reader.next()) {
      times.push_back(std::visit([](const auto& l) { return l.server_time.seconds(); }, *line));
    }
  } else {
    CarmenLogReader reader(*in, path.string());
    while (auto record = reader.next()) {
      if (std::holds_alternative<CarmenParam>(*record)) continue;
      times.push_back(std::visit([](const auto& r) { return r.stamp.logger_timestamp; }, *record));
    }
  }
  if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
  return times;
}

std::shared_ptr<const LogClock> audit_log_times(const std::filesystem::path& path) {
  auto clock = std::make_shared<const LogClock>(LogClock::audit(read_log_times(path)));
  if (clock->repair() != LogTimeRepair::kNone) {
    const std::string warning = path.string() + ": " + clock->describe();
    auto& state = warning_state();
    std::lock_guard lock(state.mutex);
    if (state.reported.insert(warning).second && state.handler) state.handler(warning);
  }
  return clock;
}

LogClockWarningHandler set_log_clock_warning_handler(LogClockWarningHandler handler) {
  auto& state = warning_state();
  std::lock_guard lock(state.mutex);
  return std::exchange(state.handler, std::move(handler));
}

}  // namespace playerkit::log
