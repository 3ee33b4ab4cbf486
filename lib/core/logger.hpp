#pragma once
// Diagnostics for humans, on stderr by default: one line per event, with the
// level in front. Thread-safe; drivers log from their own threads.
//
//   logger.warning("client 3: command to laser:0 ignored: no write access");

#include <functional>
#include <mutex>
#include <string>
#include <string_view>

namespace playerkit::core {

enum class LogLevel { kError = 0, kWarning = 1, kInfo = 2, kDebug = 3 };

std::string_view to_string(LogLevel level);

class Logger {
 public:
  using Sink = std::function<void(LogLevel, std::string_view line)>;

  // Writes "player-serve: warning: ..." style lines to stderr, up to kInfo.
  explicit Logger(std::string program = "playerkit");

  void set_level(LogLevel level);
  [[nodiscard]] bool enabled(LogLevel level) const;
  // Replaces the stderr writer (tests capture lines with this).
  void set_sink(Sink sink);

  void log(LogLevel level, std::string_view message);
  void error(std::string_view message) { log(LogLevel::kError, message); }
  void warning(std::string_view message) { log(LogLevel::kWarning, message); }
  void info(std::string_view message) { log(LogLevel::kInfo, message); }
  void debug(std::string_view message) { log(LogLevel::kDebug, message); }

 private:
  mutable std::mutex mutex_;
  std::string program_;
  LogLevel level_ = LogLevel::kInfo;
  Sink sink_;
};

}  // namespace playerkit::core
