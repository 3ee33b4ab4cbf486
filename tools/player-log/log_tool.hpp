#pragma once
// What the player-log subcommands share: exit codes, usage errors, the two
// log formats, device lists, output files ("-" = stdout) and progress on a
// terminal.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "log/log_format_detection.hpp"
#include "protocol/device_address.hpp"

namespace playerkit::plog {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // unreadable file, malformed line with --strict, server problems
inline constexpr int kExitUsage = 2;

class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The two log formats, told apart by content (lib/log/log_format_detection).
using log::detect_log_format;
using log::LogFormat;

// "laser:0,position:0" (a bare interface is index 0). Throws UsageError.
std::vector<protocol::DeviceAddress> parse_device_list(const std::string& text);

// Where a subcommand writes: a file (truncated) or stdout for "-".
class Output {
 public:
  Output(const std::string& path, std::ostream& standard_out);
  std::ostream& stream() { return *out_; }
  // Throws std::runtime_error "cannot write PATH: reason" when a write failed.
  void check() const;
  void flush_and_check();

 private:
  std::string path_;
  std::unique_ptr<std::ofstream> file_;
  std::ostream* out_;
};

// "\rplayer-log: N messages" on stderr a few times a second, when enabled
// (main enables it when stderr is a terminal); cleared at the end.
class Progress {
 public:
  Progress(std::ostream& err, bool enabled) : err_(err), enabled_(enabled) {}
  ~Progress();
  void tick() {
    ++count_;
    if (enabled_ && (count_ & 1023u) == 0) show();
  }

 private:
  void show();
  std::ostream& err_;
  bool enabled_;
  std::uint64_t count_ = 0;
  std::chrono::steady_clock::time_point last_{};
  bool shown_ = false;
};

}  // namespace playerkit::plog
