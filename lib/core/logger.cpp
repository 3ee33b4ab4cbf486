#include "core/logger.hpp"

#include <cstdio>

namespace playerkit::core {

std::string_view to_string(LogLevel level) {
  switch (level) {
    case LogLevel::kError: return "error";
    case LogLevel::kWarning: return "warning";
    case LogLevel::kInfo: return "info";
    case LogLevel::kDebug: return "debug";
  }
  return "log";
}

Logger::Logger(std::string program) : program_(std::move(program)) {}

void Logger::set_level(LogLevel level) {
  std::lock_guard lock(mutex_);
  level_ = level;
}

bool Logger::enabled(LogLevel level) const {
  std::lock_guard lock(mutex_);
  return level <= level_;
}

void Logger::set_sink(Sink sink) {
  std::lock_guard lock(mutex_);
  sink_ = std::move(sink);
}

void Logger::log(LogLevel level, std::string_view message) {
  std::lock_guard lock(mutex_);
  if (level > level_) return;
  if (sink_) {
    sink_(level, message);
    return;
  }
  // One fprintf per line so lines from different threads do not interleave.
  std::fprintf(stderr, "%s: %.*s: %.*s\n", program_.c_str(),
               static_cast<int>(to_string(level).size()), to_string(level).data(),
               static_cast<int>(message.size()), message.data());
}

}  // namespace playerkit::core
